#pragma once

#include "device/valuecheck.h"

#include <QWidget>

#include <optional>

class QComboBox;
class QLabel;
class QLineEdit;

namespace stepcom {

class ParameterStore;
struct Parameter;

// The editor of one parameter, bound to the store: shows what the device holds (or nothing
// while unknown), takes the user's edit (held, never written from here), and shows the
// state -- unknown, in sync, edited, write failed -- in colour and in words.
class ParameterField : public QWidget
{
    Q_OBJECT
public:
    ParameterField(ParameterStore *store, const Parameter &parameter, QWidget *parent = nullptr);

    const Parameter &parameter() const { return m_parameter; }
    QWidget *editor() const;
    // What a user would do: type text and press Enter, or pick an enum entry by value.
    void enterText(const QString &text);
    // What the editor shows now as a raw value: the text being typed when it parses (not yet
    // held in the store), else the store's shown value. For previews that follow the typing.
    std::optional<qint64> typedRaw() const;
    // The text being typed differs from what the store holds (Enter or leaving holds it).
    bool isTyping() const;
    // Why the value typed last was not taken, in the window's language; empty when it was.
    QString rejectionText() const;
    QLabel *reasonLabel() const { return m_reason; }
    void retranslate();

Q_SIGNALS:
    void rejected(const QString &why);
    // The user changed the text (each keystroke), before it is held as an edit.
    void typing();

protected:
    void changeEvent(QEvent *event) override;

private:
    void refresh();
    void commitText();
    void commitIndex(int index);
    void applyStateLook();
    void reject(ValueCheck::Problem problem, const QString &typed);
    // The value is valid again, reverted, or replaced by what the controller holds.
    void clearRejection();

    ParameterStore *m_store;
    const Parameter &m_parameter;
    QLineEdit *m_line = nullptr;
    QComboBox *m_combo = nullptr;
    QLabel *m_unit = nullptr;
    QLabel *m_state = nullptr;
    QLabel *m_reason = nullptr; // the rejection, under the field, not only in a tooltip
    ValueCheck::Problem m_problem = ValueCheck::Problem::None;
    QString m_rejected; // the text that was refused; it stays in the editor for correction
};

} // namespace stepcom
