#include "trafficprobe.h"

#include "device/poller.h"
#include "device/readplanner.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"
#include "widgets/docks/trafficmodel.h"
#include "widgets/docks/trafficview.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QLineEdit>
#include <QTableView>

namespace stepcom::bench {

namespace {

double residentMb()
{
    QFile statm(QStringLiteral("/proc/self/statm"));
    if (!statm.open(QIODevice::ReadOnly))
        return 0;
    const QList<QByteArray> fields = statm.readAll().split(' ');
    return fields.value(1).toDouble() * 4096.0 / (1024.0 * 1024.0);
}

QByteArray frame(const QByteArray &pdu)
{
    return QByteArray(1, '\x01') + pdu + QByteArray(2, '\0');
}

QByteArray answer(int count, quint32 seed)
{
    QByteArray pdu;
    pdu.append('\x03');
    pdu.append(char(count * 2));
    for (int i = 0; i < count; ++i) {
        const quint16 v = quint16(seed * 7 + quint32(i) * 13);
        pdu.append(char(v >> 8));
        pdu.append(char(v & 0xFF));
    }
    return frame(pdu);
}

} // namespace

TrafficResult measureTrafficView(int baud, double framesPerSecond, int seconds)
{
    TrafficResult r;
    r.baud = baud;
    r.framesPerSecond = framesPerSecond;
    r.seconds = seconds;
    const qint64 total = qint64(framesPerSecond * seconds);
    const int perBatch = std::max(1, int(framesPerSecond * TrafficModel::kBatchMs / 1000.0 + 0.5));

    TrafficLog log;
    log.setMap(&RegisterMap::builtin());
    TrafficView view;
    view.setLog(&log);
    view.resize(1000, 320);
    view.show();
    QCoreApplication::processEvents();
    const double before = residentMb();

    // The reads of the live status plan, as the poller sends them.
    const RegisterMap &map = RegisterMap::builtin();
    QList<const Parameter *> status;
    for (const QString &key : Poller::statusKeys(map))
        status << map.find(key);
    QList<Request> requests;
    QList<QByteArray> asks;
    for (const ReadBlock &b :
         ReadPlanner::plan(status, map.maxRegistersPerRequest(),
                           ReadCostModel::forBaud(baud, map.answerDelayMs()))) {
        requests << Request::read(b.address, b.count, Priority::Poll);
        QByteArray pdu(1, '\x03');
        for (const quint16 v : {b.address, b.count}) {
            pdu.append(char(v >> 8));
            pdu.append(char(v & 0xFF));
        }
        asks << frame(pdu);
    }
    QElapsedTimer batchTimer;
    qint64 fed = 0;
    quint32 seed = 0;
    while (fed < total) {
        batchTimer.start();
        for (int i = 0; i < perBatch && fed < total; ++seed) {
            for (int k = 0; k < requests.size(); ++k, i += 2, fed += 2) {
                log.addFrame(TrafficEntry::Direction::Sent, asks.at(k), 1, 2, &requests.at(k));
                log.addFrame(TrafficEntry::Direction::Received, answer(requests.at(k).count, seed),
                             1, 2, &requests.at(k));
            }
        }
        view.model()->flush();
        QCoreApplication::processEvents(); // the view lays out, as in the window
        view.repaint();                    // and paints all of itself: the upper bound
        // The last tenth, with the view full: what the window pays after an hour.
        if (fed >= total * 9 / 10)
            r.batchMs.add(double(batchTimer.nsecsElapsed()) / 1e6);
    }
    r.kept = view.model()->storedCount();
    r.capacity = view.model()->capacity();
    r.memoryMb = residentMb() - before;

    // Showing the polls of the whole hour, then a search over it.
    QElapsedTimer filterTimer;
    filterTimer.start();
    view.model()->setKindShown(TrafficEntry::Kind::Poll, true);
    QCoreApplication::processEvents();
    r.showPollsMs = double(filterTimer.nsecsElapsed()) / 1e6;
    filterTimer.start();
    view.findChild<QLineEdit *>(QStringLiteral("search"))->setText(QStringLiteral("motor1"));
    QCoreApplication::processEvents();
    r.searchMs = double(filterTimer.nsecsElapsed()) / 1e6;
    r.rowsShown = view.model()->rowCount();
    r.measured = true;
    return r;
}

} // namespace stepcom::bench
