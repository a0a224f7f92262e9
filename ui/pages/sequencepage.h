#pragma once

#include "base/page.h"
#include "sequence/sequence.h"

#include <QPointer>

#include <functional>
#include <optional>

class QCheckBox;
class QLabel;
class QMessageBox;
class QPushButton;

namespace stepcom {

class SequenceEditor;
class SequencePoints;
class SequenceRunPanel;
class MoveHere;
class XYPlot;

// "Sequence": the machine's own cycle, built and run in the window. Taught points (jog there,
// "Teach here"), the steps as an editable list with loops, an XY preview of the points and the
// path between them, the .stepseq file (docs/sequence.md) opened and saved, and the run with
// its cycles, single step and lost-step check. After every edit the whole sequence is judged
// by the file's own checks -- written out, read back by SequenceParser and walked by
// SequenceCheck with what the session knows -- so the page and `stepcomctl run` refuse the
// same things with the same words.
class SequencePage : public Page
{
    Q_OBJECT
public:
    explicit SequencePage(DeviceSession *session, QWidget *parent = nullptr);

    QString title() const override;
    QString iconName() const override { return QStringLiteral("sequence"); }
    Stage stage() const override { return Stage::MoveAndRun; }
    bool needsDevice() const override { return true; }

    // Reads a .stepseq file; false and why (a box) when it is refused.
    bool openFile(const QString &path);
    // Writes the sequence to `path` (atomically); false and why when it cannot.
    bool saveFile(const QString &path);
    QString fileName() const { return m_path; }
    bool isModified() const { return m_modified; }
    // The sequence as edited, when the file's checks let it be read; the problems otherwise.
    std::optional<Sequence> sequence() const { return m_valid; }
    QStringList problems() const { return m_problems; }
    // Questions (run, discard changes) answered without a box: tests and the shots.
    void setConfirmer(std::function<bool(const QString &question)> confirm);

    SequencePoints *points() const { return m_points; }
    SequenceEditor *editor() const { return m_editor; }
    SequenceRunPanel *runPanel() const { return m_run; }
    XYPlot *preview() const { return m_preview; }
    MoveHere *moveHere() const { return m_moveHere; }
    QLabel *problemLabel() const { return m_problemLabel; }
    QCheckBox *outputsOffBox() const { return m_outputsOff; }

Q_SIGNALS:
    // "Running sequence: cycle 3 of 10, step 4", empty when none runs (the machine strip).
    void runText(const QString &text);

protected:
    void retranslate() override;

private:
    void judge();
    void edited();
    void redrawPreview();
    void updateMarker();
    void newSequence();
    void chooseOpen();
    void chooseSave(bool as);
    bool mayDiscard();
    void showFileName();
    Sequence edit() const;

    SequencePoints *m_points;
    SequenceEditor *m_editor;
    SequenceRunPanel *m_run;
    XYPlot *m_preview;
    MoveHere *m_moveHere;
    QLabel *m_file;
    QLabel *m_limits;
    QLabel *m_problemLabel;
    QLabel *m_hint; // what to do first, while there is nothing to judge
    QCheckBox *m_outputsOff;
    QPushButton *m_new;
    QPushButton *m_open;
    QPushButton *m_save;
    QPushButton *m_saveAs;
    QList<QWidget *> m_groups;
    QString m_path;
    TravelLimits m_fileLimits;
    std::optional<Sequence> m_valid;
    QStringList m_problems;
    bool m_modified = false;
    std::function<bool(const QString &)> m_confirm;
    QPointer<QMessageBox> m_errorBox;

public:
    QMessageBox *errorBox() const { return m_errorBox; }
};

} // namespace stepcom
