#pragma once

#include "bus/linksettings.h"
#include "bus/serialadapter.h"
#include "listen/estopconfirmation.h"
#include "listen/framefinder.h"
#include "listen/listendecoder.h"

#include <QElapsedTimer>
#include <QObject>

QT_BEGIN_NAMESPACE
class QSerialPort;
class QTimer;
QT_END_NAMESPACE

namespace stepcom {

class RegisterMap;

// A serial line another master drives, heard from the side: the port opened read-only (a
// listener never puts a byte on the line), its bytes through FrameFinder and ListenDecoder as
// they arrive, every frame and every paired request said at once. The time base is ms since
// open(); a quiet line is looked at every kTickMs so a frame cut short and a request never
// answered are said without waiting for the next byte. The one frame it may send is the E-STOP
// (with the read that confirms it), never another.
class LineListener : public QObject
{
    Q_OBJECT
public:
    static constexpr int kTickMs = 20;

    explicit LineListener(const RegisterMap *map, QObject *parent = nullptr);
    ~LineListener() override;

    // Opens the port read-only at the line's baud, parity and stop bits; false and why not.
    // With setMayTransmit(true) before, it opens for writing too, for the one frame StepCom
    // may send into another master's line: the E-STOP (sendEmergencyStop).
    bool open(const LinkSettings &settings, QString *error);
    void setMayTransmit(bool may) { m_mayTransmit = may; }
    void close();
    bool isOpen() const;
    const LinkSettings &settings() const { return m_settings; }
    // The adapter behind the port, once open (SerialAdapter::summary(), empty when not known).
    QString adapterText() const { return m_adapter.summary(); }

    // Bytes heard from a source other than the port (a recorded line, a test): as if they had
    // arrived at `ms`.
    void feed(const QByteArray &bytes, qint64 ms);
    // The quiet line until `ms` (the timer calls it with the clock).
    void idle(qint64 ms);
    // The end: a request still waiting had no answer; bytes held are no frame.
    void finish();
    // ms since open() on the listener's clock.
    qint64 now() const { return m_clock.isValid() ? m_clock.elapsed() : 0; }

    // Sends the E-STOP to `unit` in the first silence after the other master's frame (once an
    // answer ended a pair, or the line has been quiet for a silence), and again until the
    // controller is heard to take it (EstopConfirmation: its copy past the adapter's echo, then
    // its motion state read back the same way). False when the port was not opened to transmit
    // or the map has no E-STOP.
    bool sendEmergencyStop(int unit);
    bool isSending() const { return m_estop.isActive(); }
    // The E-STOP request (the map's estop coil set, FC05) to `unit`; empty when the map has
    // none.
    static QByteArray emergencyStopFrame(const RegisterMap &map, int unit);

    const FrameFinder &finder() const { return m_finder; }
    const ListenDecoder &decoder() const { return m_decoder; }

Q_SIGNALS:
    void frameHeard(const stepcom::HeardFrame &frame);
    void heard(const stepcom::HeardEvent &event);
    // The port failed (unplugged): nothing more will be heard.
    void lost(const QString &reason);
    // sendEmergencyStop: each frame as it went out (`estop`: the E-STOP, else the read of the
    // motion state), the try it was; then the verdict in words, once.
    void frameSent(const QByteArray &frame, bool estop, int attempt);
    void emergencyStopSettled(bool acknowledged, const QString &text);
    // The adapter returned StepCom's own frame though the line's echo option is off (said
    // once): from then on the first copy of each frame is taken for the echo.
    void echoSuspected();

private:
    void readPort();
    void emitAll(const QList<HeardFrame> &frames);
    void sendDue(qint64 ms);
    void sendNow(const QByteArray &frame);
    void sayVerdict();

    const RegisterMap *m_map;
    LinkSettings m_settings;
    SerialAdapter m_adapter;
    QSerialPort *m_port = nullptr;
    QTimer *m_tick = nullptr;
    QElapsedTimer m_clock;
    bool m_mayTransmit = false;
    EstopConfirmation m_estop;
    bool m_verdictOwed = false; // an E-STOP whose verdict is not said yet
    bool m_echoLearned = false; // the adapter was heard to echo though the option is off
    qint64 m_lastByteMs = 0;    // when the line last carried a byte
    FrameFinder m_finder;
    ListenDecoder m_decoder;
};

} // namespace stepcom
