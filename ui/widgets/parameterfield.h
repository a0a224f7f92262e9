#pragma once

#include <QWidget>

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
    void retranslate();

Q_SIGNALS:
    void rejected(const QString &why);

protected:
    void changeEvent(QEvent *event) override;

private:
    void refresh();
    void commitText();
    void commitIndex(int index);
    void applyStateLook();

    ParameterStore *m_store;
    const Parameter &m_parameter;
    QLineEdit *m_line = nullptr;
    QComboBox *m_combo = nullptr;
    QLabel *m_unit = nullptr;
    QLabel *m_state = nullptr;
    QString m_lastError;
};

} // namespace stepcom
