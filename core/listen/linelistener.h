#pragma once

#include "bus/linksettings.h"
#include "bus/serialadapter.h"
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
// answered are said without waiting for the next byte.
class LineListener : public QObject
{
    Q_OBJECT
public:
    static constexpr int kTickMs = 20;

    explicit LineListener(const RegisterMap *map, QObject *parent = nullptr);
    ~LineListener() override;

    // Opens the port read-only at the line's baud, parity and stop bits; false and why not.
    // With setMayTransmit(true) before, it opens for writing too, for the one frame StepCom
    // may send into another master's line: the E-STOP (sendInSilence).
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

    // Sends `frame` in the first silence after the other master's frame (once an answer ended
    // a pair, or the line has been quiet for a silence), and again at the next silence until
    // the controller's answer to it is heard (a copy: FC05/FC06), at most kSendTries times.
    // False when the port was not opened to transmit.
    bool sendInSilence(const QByteArray &frame);
    static constexpr int kSendTries = 10;
    static constexpr int kAnswerWaitMs = 300;
    bool isSending() const { return !m_outgoing.isEmpty(); }
    // The E-STOP request (the map's emergency coil set, FC05) to `unit`; empty when the map has
    // no emergency coil.
    static QByteArray emergencyStopFrame(const RegisterMap &map, int unit);

    const FrameFinder &finder() const { return m_finder; }
    const ListenDecoder &decoder() const { return m_decoder; }

Q_SIGNALS:
    void frameHeard(const stepcom::HeardFrame &frame);
    void heard(const stepcom::HeardEvent &event);
    // The port failed (unplugged): nothing more will be heard.
    void lost(const QString &reason);
    // sendInSilence: each time the frame went out; its answer heard; or given up.
    void frameSent(const QByteArray &frame, int attempt);
    void frameAnswered(const QByteArray &frame);
    void sendFailed(const QByteArray &frame);

private:
    void readPort();
    void emitAll(const QList<HeardFrame> &frames);
    void sendNow();

    const RegisterMap *m_map;
    LinkSettings m_settings;
    SerialAdapter m_adapter;
    QSerialPort *m_port = nullptr;
    QTimer *m_tick = nullptr;
    QElapsedTimer m_clock;
    bool m_mayTransmit = false;
    QByteArray m_outgoing; // the frame to send into the line, until its answer is heard
    int m_tries = 0;
    qint64 m_sentAtMs = -1;  // when it last went out
    qint64 m_lastByteMs = 0; // when the line last carried a byte
    FrameFinder m_finder;
    ListenDecoder m_decoder;
};

} // namespace stepcom
