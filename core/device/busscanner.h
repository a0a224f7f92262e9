#pragma once

#include "bus/linksettings.h"

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
        QString where;            // "9600 8N1", or "192.168.1.20:502" over TCP
        int exceptionCode = 0;    // it answered the probe with this exception
        QList<qint64> stepAngles; // raw step angle of each motor that answered (1.80° = 180)
        int motorsInMap = 0;      // how many motors the map describes
        QString detail;           // what answered, in words: describe() without id and baud
        // "id 7 at 9600 8N1 — a 2-axis controller, step angle 1.80°"
        QString summary() const;
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

    // `base` supplies the port (or TCP host), parity and stop bits; ids and bauds are tried in
    // the order given (bauds ignored on TCP). A probe waits `probeTimeoutMs` for an answer.
    void start(const LinkSettings &base, const QList<int> &bauds, int firstId, int lastId,
               int probeTimeoutMs = 150, bool stopAtFirst = false);
    void cancel();
    bool isRunning() const { return m_running; }
    const QList<Found> &found() const { return m_found; }
    int total() const { return m_total; }

Q_SIGNALS:
    void progress(int done, int total, int baud, int deviceId);
    void foundDevice(const stepcom::BusScanner::Found &found);
    void finished(bool cancelled, const QString &error);

private:
    void openNextBaud();
    void probeNext();
    // After a probe answered: read every motor's step angle in one request, then report.
    void identify(Found found);
    void report(Found found);
    void finish(bool cancelled, const QString &error);

    ModbusLink *m_link = nullptr;
    const RegisterMap *m_map = nullptr;
    LinkSettings m_base;
    QList<int> m_bauds;
    int m_baudIndex = -1;
    int m_firstId = 1;
    int m_lastId = 247;
    int m_id = 0;
    int m_timeoutMs = 150;
    bool m_stopAtFirst = false;
    bool m_running = false;
    int m_done = 0;
    int m_total = 0;
    QList<Found> m_found;
};

} // namespace stepcom
