#pragma once

#include "bus/linkbackend.h"

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
// is taken only if it can be the answer: not sooner than the request's frame plus the
// controller's answer delay, from the right unit, with the content AnswerCheck allows. Every
// other frame is discarded (and reported); after trouble the line must go quiet before the
// next request.
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

    // Empty when `path` can be a serial port; otherwise why not ("not a serial port").
    static QString notASerialPort(const QString &path);
    // An answer sooner than the request's frame plus the answer delay minus this is stale.
    static constexpr double kEarlyMarginMs = 3.0;
    // How long after an attempt that timed out its answer is still expected, in timeouts: a
    // different request waits until then (or until that answer came), the same request may
    // go again and take it.
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
    void takeStrayFrames();
    // Scan mode: name the unit of a foreign answer frame (CRC checked by the caller).
    void reportForeign(const QByteArray &frame);

    LinkSettings m_settings;
    QPointer<QIODevice> m_device;
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
    double m_earliestMs = 0;
    bool m_echoStripped = false;
    QByteArray m_rx;    // bytes of the current transaction
    QByteArray m_stray; // bytes that arrived between transactions
    QStringList m_discarded;
    int m_crcErrors = 0;
    QList<Owed> m_owed;
    int m_unit = 1;
    int m_strayParsed = 0; // bytes of m_stray already cut into frames
    QTimer m_writeTimer;
    QTimer m_timeoutTimer;
};

} // namespace stepcom
