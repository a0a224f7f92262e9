#pragma once

#include "widgets/fields/elidedlabel.h"

#include <QFrame>
#include <QTimer>

#include <functional>
#include <optional>

class QLabel;
class QToolButton;

namespace stepcom {

class DeviceSession;
class EmergencyStop;
class Led;

// The strip under the pages that a technician trusts at a glance: per motor the
// position (large fixed-width digits that never jump or clip), the motion state in words and
// colour, referenced or not; the inputs and outputs as lamps with their roles; the link's
// state and what the line showed; the device in view when a line has several; and the E-STOP
// at its end. Not a dock: it cannot be closed or tabbed away. Everything not known shows "—"
// in grey, never a guess. It reads what the status poll already put in the store.
class MachineStrip : public QFrame
{
    Q_OBJECT
public:
    enum class Motion { Unknown, Idle, Running, AtLimit };

    MachineStrip(DeviceSession *session, EmergencyStop *estop, QWidget *parent = nullptr);

    int motorCount() const { return int(m_motors.size()); }
    QLabel *positionLabel(int motor) const;
    QLabel *motionLabel(int motor) const;
    QLabel *referenceLabel(int motor) const;
    Motion motion(int motor) const;
    Led *inputLed(int n) const { return m_inputLeds.value(n - 1); }
    Led *outputLed(int n) const { return m_outputLeds.value(n - 1); }
    QLabel *linkLabel() const { return m_link; }
    QLabel *lineLabel() const { return m_line; }
    ElidedLabel *deviceLabel() const { return m_device; }
    QToolButton *emergencyStopButton() const { return m_estopButton; }
    // The one-row form for a short window (1024×600): smaller digits, less padding.
    void setCompact(bool compact);
    bool isCompact() const { return m_compact; }
    // The name the user gave a device of the line (the device list's), for "the device in view".
    void setDeviceNamer(std::function<QString(int)> namer);
    // A replay: the link as the log shows it at the moment -- up and `answering` or
    // not, or down -- and `line` (the log's line settings) instead of the session's, until
    // endReplay().
    void showReplayLink(bool linkUp, bool answering, const QString &line);
    void endReplay();
    // "Pendant: 1 phone watching" / "Pendant: jogging from 192.168.1.23"; empty hides it.
    void setPendantText(const QString &text);
    QLabel *pendantLabel() const { return m_pendant; }
    // "Running sequence: cycle 3 of 10, step 4" (the Sequence page's run); empty hides it.
    void setSequenceText(const QString &text);
    QLabel *sequenceLabel() const { return m_sequence; }
    // A proof of an axis failed at the user's own settings: "Motor 1 lost steps at 300 rpm" and
    // a button (`action`, e.g. "Use 225 rpm…") that runs `onAction`; an empty text hides both.
    void setProofWarning(const QString &text, const QString &action,
                         std::function<void()> onAction);
    QLabel *proofWarningLabel() const { return m_proofWarning; }
    QToolButton *proofActionButton() const { return m_proofAction; }

protected:
    void changeEvent(QEvent *event) override;

private:
    struct MotorView
    {
        QString positionKey;
        QString runningKey;
        QLabel *caption = nullptr;
        QLabel *position = nullptr;
        QLabel *motion = nullptr;
        QLabel *reference = nullptr;
        Motion state = Motion::Unknown;
    };

    void retranslate();
    void applyFonts();
    void scheduleRefresh();
    void refresh();
    void refreshLink();
    Motion motionOf(int motor, std::optional<qint64> running) const;
    // The roles the motors' parameters give input `n` ("Motor 1 negative limit"), or none.
    QStringList inputRoles(int n) const;

    DeviceSession *m_session;
    QList<MotorView> m_motors;
    QStringList m_inputKeys;
    QStringList m_outputKeys;
    QList<Led *> m_inputLeds;
    QList<Led *> m_outputLeds;
    QLabel *m_inputsCaption;
    QLabel *m_outputsCaption;
    QLabel *m_link;
    ElidedLabel *m_line;
    ElidedLabel *m_device; // a long name gives way: the strip must not widen the window
    QLabel *m_pendant;     // who watches or jogs from a phone (PendantActions)
    QLabel *m_sequence;    // the run of the Sequence page
    QLabel *m_proofWarning;
    QToolButton *m_proofAction;
    std::function<void()> m_onProofAction;
    QToolButton *m_estopButton;
    std::function<QString(int)> m_namer;
    struct ReplayLink
    {
        bool linkUp = false;
        bool answering = false;
        QString line;
    };
    std::optional<ReplayLink> m_replay;
    bool m_compact = false;
    QTimer m_refresh; // the store's per-key signals, one update a cycle
};

} // namespace stepcom
