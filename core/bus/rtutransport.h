#pragma once

#include "bus/linkbackend.h"
#include "bus/serialadapter.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QModbusPdu>
#include <QPointer>
#include <QTimer>

#include <optional>

QT_BEGIN_NAMESPACE
class QIODevice;
QT_END_NAMESPACE

namespace stepcom {

// Modbus RTU of StepCom's own over a QIODevice: a serial port, or a TCP socket to a
// transparent RS-485/Ethernet converter. QModbusRtuSerialClient matched answers by unit and
// function only, could not skip an adapter's echo and has no TCP transport; here an answer
// is taken by what it says, never by when it came: from the right unit, with the content
// AnswerCheck allows (an FC03 answer carries the count asked for, FC05/06/10 answers repeat
// address and value or count), and after a timeout the next frame is the answer that request
// still owes. Every other frame is discarded (and reported); after trouble the line must go
// quiet before the next request.
//
// An adapter's echo is known only where it cannot be an answer: an FC03 or FC10 request's
// own bytes coming back (an FC05/06 answer IS a copy of the request). The line learns it from
// the first such transaction -- and learns that there is none when an answer comes without
// the copy -- so a wrong echo setting corrects itself; until it knows, the setting decides.
class RtuTransport : public LinkBackend
{
    Q_OBJECT
public:
    explicit RtuTransport(QObject *parent = nullptr);
    ~RtuTransport() override;

    void open(const LinkSettings &settings) override;
    void close() override;
    void send(int unit, const QModbusRequest &request, int timeoutMs) override;
    void setQuietTimeMs(int ms) override { m_quietMs = ms; }
    void requireQuiet() override;
    void setScanMode(bool on) override { m_scan = on; }
    QString adapterText() const override { return m_adapter.summary(); }

    // Empty when `path` can be a serial port; otherwise why not ("not a serial port").
    static QString notASerialPort(const QString &path);
    // What the line showed about echo so far (reset on open): Unknown until a read or a block
    // write has been answered.
    enum class Echo { Unknown, Yes, No };
    Echo echoSeen() const { return m_echoSeen; }
    // How long after an attempt that timed out its answer is still expected, in timeouts (the
    // set one, the request's own if longer, or the latest an owed answer of this line came if
    // later still): a different request waits until then (or until that answer came), the
    // same request may go again and take it.
    static constexpr int kOwedTimeouts = 2;

private:
    struct Pending
    {
        int unit = 1;
        QModbusRequest request;
        QByteArray adu;
        int timeoutMs = 500;
    };

    // An attempt that timed out: its answer may still come, and a controller answers in
    // order, so the next frames are its until it came or `untilMs` passed.
    struct Owed
    {
        QByteArray adu;
        double untilMs = 0;
        double sentAtMs = 0;
    };

    double nowMs() const { return double(m_clock.nsecsElapsed()) / 1e6; }
    void fail(const QString &reason);
    void onReadyRead();
    void scheduleWrite();
    void writeNow();
    void processBuffer();
    void discard(const QByteArray &bytes, const QString &why);
    void finish(LinkAnswer answer);
    void onTimeout();
    void pruneOwed();
    double owedUntilMs() const;
    // The oldest answer `unit` owes (an index into m_owed), or -1.
    qsizetype oldestOwed(quint8 unit) const;
    // That owed answer came: the controller showed how late it answers.
    void owedAnswerCame(qsizetype index);
    // An answer to `owedAdu` could pass the content check of the request pending now (same
    // unit, function and shape): only then does the request wait for it.
    bool couldPassForPending(const QByteArray &owedAdu) const;
    // A frame (function code and data) is what `adu` asked for.
    static bool answers(const QByteArray &adu, int functionCode, const QByteArray &data);
    void takeStrayFrames();
    // Scan mode: name the unit of a foreign answer frame (CRC checked by the caller).
    void reportForeign(const QByteArray &frame);
    // The request's copy comes back before its answer: learnt, else the setting.
    bool expectEcho() const
    {
        return m_echoSeen == Echo::Yes || (m_echoSeen == Echo::Unknown && m_settings.echo);
    }
    void learnEcho(bool echoes);
    // The complete, checked answer frame at the start of m_rx, or empty.
    QByteArray checkedAnswerAtStart() const;

    LinkSettings m_settings;
    QPointer<QIODevice> m_device;
    SerialAdapter m_adapter; // the port's adapter, from sysfs once open
    bool m_opening = false;
    bool m_failing = false;
    double m_byteMs = 0; // one character on the line (0 on a pty or TCP: no wire)
    double m_gapMs = 0;  // the silence before a request (3.5 characters)
    int m_quietMs = 100;
    bool m_scan = false;
    QElapsedTimer m_clock;
    double m_lastRxMs = -1;
    double m_quietFromMs = 0;
    bool m_needQuiet = false;
    std::optional<Pending> m_pending;
    bool m_waiting = false;
    double m_sentAtMs = 0;
    bool m_echoStripped = false;
    Echo m_echoSeen = Echo::Unknown;
    // An FC05/06 request its first copy answered: a second copy right after is an echo's.
    QByteArray m_copyAnswered;
    QByteArray m_rx;    // bytes of the current transaction
    QByteArray m_stray; // bytes that arrived between transactions
    QStringList m_discarded;
    int m_crcErrors = 0;
    QList<Owed> m_owed;
    double m_lateMs = 0; // the latest an owed answer came, after its attempt went (since open)
    static constexpr double kMaxLateMs = 5000; // beyond this an owed answer is not waited for
    int m_unit = 1;
    int m_strayParsed = 0; // bytes of m_stray already cut into frames
    QTimer m_writeTimer;
    QTimer m_timeoutTimer;
};

} // namespace stepcom
