#pragma once

#include "base/page.h"

#include <QFileDialog>
#include <QPointer>
#include <QTimer>

class QLabel;
class QPushButton;
class QSpinBox;
class QSplitter;
class QToolButton;

namespace stepcom {

class PositionPlot;
class StatusRecorder;
class MoveHere;
class XYPlot;

// "Plots": each motor's position over time and the XY view of the tool's path (motor 1 = X,
// motor 2 = Y), with pause, fit, export (PNG of both plots, CSV of the visible samples) and
// recording of every status sample to CSV. Owns the session's StatusRecorder, which samples
// after each status poll cycle whether or not the page is shown.
class PlotPage : public Page
{
    Q_OBJECT
public:
    explicit PlotPage(DeviceSession *session, QWidget *parent = nullptr);
    ~PlotPage() override;

    QString title() const override;
    QString iconName() const override { return QStringLiteral("plots"); }
    Stage stage() const override { return Stage::MoveAndRun; }
    bool needsDevice() const override { return true; }

    StatusRecorder *recorder() const { return m_recorder; }
    PositionPlot *positionPlot() const { return m_positions; }
    XYPlot *xyPlot() const { return m_xy; }
    MoveHere *moveHere() const { return m_moveHere; }
    QPushButton *pauseButton() const { return m_pause; }
    QPushButton *recordButton() const { return m_record; }
    // The save dialog while one is open (non-modal; tests pick a file through it).
    QFileDialog *fileDialog() const { return m_dialog; }

    void setPaused(bool paused);
    bool isPaused() const;
    void fit();
    void clearTrace();
    // A replay's whole path up to its moment as the trace: the recorder holds only
    // the last half hour of it. Samples recorded after it go on feeding the trace as live ones.
    void showTrace(const QList<QPointF> &path);

    // The direct forms of the buttons (tests and scripts): false and an error naming the path.
    bool exportPng(const QString &path, QString *error);
    bool exportCsv(const QString &path, QString *error);
    bool startRecording(const QString &path, QString *error);
    void stopRecording();
    // "Recording to …: N samples", the last error, or empty.
    QString recordingStatus() const;

protected:
    void retranslate() override;

private:
    enum class FileAction { Png, Csv, Record };
    void askForFile(FileAction action);
    void fileChosen(FileAction action, const QString &path);
    void scheduleXY();
    void updateXY();
    void updateRecordingStatus();
    void showError(const QString &error);

    StatusRecorder *m_recorder;
    PositionPlot *m_positions;
    XYPlot *m_xy;
    MoveHere *m_moveHere;
    QSplitter *m_splitter;
    QPushButton *m_pause;
    QPushButton *m_fit;
    QPushButton *m_clear;
    QLabel *m_windowLabel;
    QSpinBox *m_window;
    QPushButton *m_exportPng;
    QPushButton *m_exportCsv;
    QPushButton *m_record;
    QLabel *m_status;
    QPointer<QFileDialog> m_dialog;
    QString m_error;
    QTimer m_xyTimer;
    QTimer m_statusTimer;
    qint64 m_fedUntilMs = -1; // the last sample (elapsedMs) already in the XY trace
};

} // namespace stepcom
