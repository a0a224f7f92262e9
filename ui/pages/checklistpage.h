#pragma once

#include "base/page.h"
#include "commissioning/checklist.h"

#include <QHash>

class QLabel;
class QListWidget;
class QPushButton;
class QStackedWidget;

namespace stepcom {

class ChecklistStepWidget;
class WriteFlow;

// "Commissioning checklist": every step of the machine's checklist (Checklist::forMap) in a
// list with its latest result, the selected step's own controls beside it. Each result is
// recorded with its time, measurements and note and saved at once in the checklist file
// beside the profile (ChecklistFile::pathFor) -- or, without a profile, in the data location
// -- so closing the window and opening it again resumes at the first step not run.
class ChecklistPage : public Page
{
    Q_OBJECT
public:
    ChecklistPage(DeviceSession *session, WriteFlow *writes, QWidget *parent = nullptr);

    QString title() const override;
    QString iconName() const override { return QStringLiteral("checklist"); }
    Stage stage() const override { return Stage::CheckAndReport; }
    Progress progress() const override;

    const Checklist &checklist() const { return m_checklist; }
    // The file the progress is kept in.
    QString checklistFile() const { return m_file; }
    QString profilePath() const { return m_profile; }
    // Uses the checklist kept beside this profile (empty: the data location's) and remembers it.
    void setProfilePath(const QString &path);
    // For the report: the checklist when any step was run, with its file.
    std::optional<std::pair<Checklist, QString>> reportChecklist() const;

    ChecklistStepWidget *stepWidget(const QString &id) const { return m_widgets.value(id); }
    QString currentStepId() const;
    void selectStep(const QString &id);
    QListWidget *stepList() const { return m_list; }
    QString summaryText() const;
    QString problemText() const;

    // Where the checklist is kept without a profile.
    static QString defaultFile();
    // Opens the write dialog for the speed the motor's margin search recommended.
    void writeRecommendation(int motor);
    // A run-in of the machine's cycle ended (the Sequence page): its result, recorded as the
    // run-in step's attempt.
    void recordRunIn(StepResult result, const QList<ChecklistMeasurement> &measurements,
                     const QString &summary);

protected:
    void retranslate() override;

Q_SIGNALS:
    // A step's result was recorded: "checklist motor1.direction: passed" (English, for the
    // session log's user lines).
    void resultRecorded(const QString &what);
    // The proof of an axis: lost steps at the motor's own settings (a margin's recommendation
    // when one is known), or kept again.
    void stepsLost(int motor, qint64 speedRpm, std::optional<qint64> recommended);
    void stepsKept(int motor);
    // The run-in step's "Open the Sequence page".
    void sequencePageWanted();

private:
    void load();
    void onRecorded(const QString &id, StepResult result,
                    const QList<ChecklistMeasurement> &measurements, const QString &note);
    void refreshList();
    void chooseProfile();

    WriteFlow *m_writes;
    Checklist m_checklist;
    QString m_profile;
    QString m_file;
    bool m_fileUsable = true; // false: the file could not be read; it is not overwritten
    QLabel *m_profileLabel;
    QPushButton *m_chooseProfile;
    QLabel *m_summary;
    QLabel *m_problem;
    QListWidget *m_list;
    QStackedWidget *m_stack;
    QHash<QString, ChecklistStepWidget *> m_widgets;
};

} // namespace stepcom
