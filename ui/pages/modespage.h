#pragma once

#include "base/page.h"

#include "base/writechangesdialog.h"
#include "base/writeflow.h"

#include <QMessageBox>
#include <QPointer>

class QComboBox;
class QGroupBox;
class QLabel;

class QPushButton;
class QTableWidget;

namespace stepcom {

class AboutBox;

class ParameterForm;

// The special modes (40300) and the round-trip count (40301). A mode changes what the machine's
// inputs IN1-IN4 do, so choosing one asks first (the question says the write review's problems)
// and then writes it at once through the window's WriteFlow, logged and read back; it is never
// held as an edit that "Write changes" could send unseen.
class ModesPage : public Page
{
    Q_OBJECT
public:
    ModesPage(DeviceSession *session, WriteFlow *writes, QWidget *parent = nullptr);

    QString title() const override;
    QString iconName() const override { return QStringLiteral("modes"); }
    Stage stage() const override { return Stage::SetUp; }
    QStringList keys() const override;

    QComboBox *modeBox() const { return m_mode; }
    QMessageBox *confirmation() const { return m_confirmation; }
    QTableWidget *table() const { return m_table; }
    QLabel *warning() const { return m_warning; }
    QLabel *explanation() const { return m_explanation; }
    ParameterForm *form() const { return m_form; }
    QPushButton *writeButton() const { return m_write; }
    WriteChangesDialog *writeDialog() const { return m_writeFlow->dialog(); }
    // What a user does: pick a mode in the list (asks before anything is written).
    void chooseMode(int mode);

protected:
    void retranslate() override;
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    // The list shows what the controller holds (unless a change is being asked).
    void refresh();
    void fitTable();
    // The explanation, the warning and the table for the mode the list shows.
    void describe();
    void confirmMode(int mode);
    void openWriteDialog();
    std::optional<qint64> deviceMode() const;
    int shownMode() const;

    QGroupBox *m_modeBox;
    QGroupBox *m_tableBox;
    QGroupBox *m_tripsBox;
    QLabel *m_modeLabel;
    QComboBox *m_mode;
    QLabel *m_current;
    QLabel *m_explanation;
    QLabel *m_warning;
    AboutBox *m_about; // The whole warning, on demand
    QTableWidget *m_table;
    ParameterForm *m_form;
    QLabel *m_tripsNote;
    QPushButton *m_write;
    QPointer<QMessageBox> m_confirmation;
    WriteFlow *m_writeFlow;
};

} // namespace stepcom
