#pragma once

#include "bus/linksettings.h"

#include <QList>
#include <QObject>

namespace stepcom {

class ModbusLink;

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
        QString detail; // what it answered, e.g. "step angle 1.80"
    };

    explicit BusScanner(QObject *parent = nullptr);
    ~BusScanner() override;

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
    void finish(bool cancelled, const QString &error);

    ModbusLink *m_link = nullptr;
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
