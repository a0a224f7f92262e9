#pragma once

#include "bus/linksettings.h"

#include <QElapsedTimer>
#include <QHash>
#include <QList>
#include <QObject>

namespace stepcom {

class ModbusLink;
class RegisterMap;

// Finds controllers whose id or baud was forgotten: tries every baud rate and device id on one
// port with a one-register read and lists whoever answers (an exception answer counts: it is a
// controller at that id and baud). Never writes.
class BusScanner : public QObject
{
    Q_OBJECT
public:
    struct Found
    {
        int baud = 0;
        int deviceId = 0;
        QString where; // "9600 8N1", or "192.168.1.20:502" over TCP
        QSerialPort::Parity parity = QSerialPort::NoParity;
        // Milliseconds from the probe to its answer; an answer after the probe's timeout was
        // taken when it came (it names its id) and says the controller needs a longer timeout.
        qint64 answerMs = -1;
        bool late = false;
        int exceptionCode = 0;    // it answered the probe with this exception
        QList<qint64> stepAngles; // raw step angle of each motor that answered (1.80° = 180)
        int motorsInMap = 0;      // how many motors the map describes
        QString detail;           // what answered, in words: describe() without id and baud
        // "id 7 at 9600 8N1 — a 2-axis controller, step angle 1.80°"
        QString summary() const;
    };

    // What to scan. The dialog and `stepcomctl scan` both fill one and call start(Plan).
    struct Plan
    {
        LinkSettings base; // the port (or host), stop bits, answer delay, echo
        QList<int> bauds;  // tried in this order; ignored over a network (base.baud there)
        QList<QSerialPort::Parity> parities; // empty: base.parity; ignored over a network
        QList<int> ids;                      // tried in this order at each baud and parity
        // 0: fitted to the baud and the line (probeTimeoutMs()); longer for slow controllers,
        // never shorter than the fitted one.
        int probeTimeoutMs = 0;
        bool stopAtFirst = false;
    };

    explicit BusScanner(QObject *parent = nullptr);
    ~BusScanner() override;
    // The map that says where each motor's step angle is (the built-in one by default).
    void setMap(const RegisterMap *map) { m_map = map; }

    // "a 2-axis controller, step angle 1.80°" — what a person reads, from what the device
    // showed: an exception, one motor's step angle, or every motor's.
    static QString describe(const Found &found, const RegisterMap &map);
    // "9600 8N1" / "host:502".
    static QString where(const LinkSettings &settings);

    // A USB adapter's latency (an FTDI chip's latency timer is 16 ms) on top of the wire.
    static constexpr int kUsbMarginMs = 16;
    // A converter or gateway on a network adds its own buffering.
    static constexpr int kNetworkMarginMs = 30;
    // Opening a serial line waits this long for it to be quiet; also the quiet time after
    // bytes arrived that no probe was waiting for.
    static constexpr int kOpenQuietMs = 50;
    // How long after a line's last probe its late answers are listened for: the probe timeout
    // once more after that probe's own, or half as long again as the slowest answer seen in
    // this scan (`slowestAnswerMs`, < 0: none), so more controllers like it among the last ids
    // are found too. An answer that comes while later ids are probed is taken then anyway.
    static int lateListenMs(int probeTimeoutMs, qint64 slowestAnswerMs);
    // The shortest wait for a probe's answer on `line` (its baud and parity; over a network
    // the converter's baud as given): the request's frame, the controller's answer delay, the
    // longest answer frame to a probe, and the margin.
    static int fittedProbeTimeoutMs(const LinkSettings &line);
    // The wait a probe gets on `line` when `askedMs` was asked for (0: fitted).
    static int probeTimeoutMs(const LinkSettings &line, int askedMs);
    // The link timeout that suits a controller that answered after `answerMs`: half as long
    // again, in steps of 50 ms, never below the link's default 500 ms.
    static int suggestedTimeoutMs(qint64 answerMs);
    // The lines a plan tries, in order: one per baud and parity (just the base on a network).
    static QList<LinkSettings> lines(const Plan &plan);
    // When nobody answers: every probe waits out its timeout, plus opening each line.
    static qint64 worstCaseMs(const Plan &plan);

    void start(const Plan &plan);
    // The ids firstId..lastId at `bauds` with base's parity (the dialog's first form).
    void start(const LinkSettings &base, const QList<int> &bauds, int firstId, int lastId,
               int probeTimeoutMs = 0, bool stopAtFirst = false);
    void cancel();
    bool isRunning() const { return m_running; }
    const QList<Found> &found() const { return m_found; }
    int total() const { return m_total; }

Q_SIGNALS:
    void progress(int done, int total, int baud, int deviceId);
    // A line is being tried: `line` as where() says it, each probe waiting `probeTimeoutMs`.
    void lineStarted(const QString &line, int probeTimeoutMs);
    void foundDevice(const stepcom::BusScanner::Found &found);
    void finished(bool cancelled, const QString &error);

private:
    void openNextLine();
    void probeNext();
    // An answer (on time or late) from `id` on the current line: a Found, not yet described.
    Found foundAt(int id, int exceptionCode, const QList<quint16> &values, qint64 answerMs) const;
    void onLateAnswer(int unit, int exceptionCode, const QList<quint16> &values);
    // After a probe answered: read every motor's step angle in one request, then report.
    void identify(Found found);
    void report(Found found);
    void finish(bool cancelled, const QString &error);

    ModbusLink *m_link = nullptr;
    const RegisterMap *m_map = nullptr;
    Plan m_plan;
    QList<LinkSettings> m_lines;
    int m_lineIndex = -1;
    int m_idIndex = 0;
    int m_timeoutMs = 0;
    bool m_running = false;
    int m_done = 0;
    int m_total = 0;
    QList<Found> m_found;
    QElapsedTimer m_clock;
    QHash<int, qint64> m_probedAt; // ids probed on this line: when (m_clock)
    QList<Found> m_late;           // found by a late answer, identified before the next probe
    bool m_waitedForLate = false;  // this line's last probe's late answers were waited for
    qint64 m_lastProbeAtMs = 0;    // m_clock's time of this line's last probe
    qint64 m_slowestMs = -1;       // the slowest late answer of this scan
};

} // namespace stepcom
