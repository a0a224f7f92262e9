// Soak: thousands of Modbus transactions against the simulator on a bad line -- lost answers,
// broken CRCs, late answers, exception answers and the port hanging up every few hundred
// answers, through an adapter that echoes every byte it sends (STEPCOM_SOAK_ECHO=0: without) --
// while the status poller runs, motors are jogged and parameters written, the way a technician
// would. It asserts what the tool promises on such a line:
//   - no crash, no hang: every write, jog and request ends, within generous bounds (QTRY_);
//   - the link recovers: after every hang-up the session connects again and reads;
//   - every failed write is reported, and never shown as written: a key is "in sync" only when
//     the controller holds that value; the store's device value is always what the simulator
//     really holds (or unknown), checked after every write and for every key at the end;
//   - a jog cut off by the hang-up is reported as possibly still running, and the stop goes
//     out as soon as the link is back: no motor is left running;
//   - memory stays flat (resident size after warm-up vs. at the end; not under sanitizers).
// STEPCOM_SOAK_TRANSACTIONS sets the length (default 800, under a minute); scripts/soak.sh
// runs a long one. STEPCOM_SOAK_SEED picks other fault dice.

#include "bus/modbuslink.h"
#include "bus/trafficlog.h"
#include "device/poller.h"
#include "session/devicesession.h"
#include "session/jogcontroller.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"
#include "session/sessioninternals.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QLoggingCategory>
#include <QRandomGenerator>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <unistd.h>

#include <memory>

using namespace stepcom;
using State = JogController::State;

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

int envInt(const char *name, int fallback)
{
    bool ok = false;
    const int v = qEnvironmentVariableIntValue(name, &ok);
    return ok && v > 0 ? v : fallback;
}

// Resident set size of this process in MiB, from /proc/self/statm (Linux).
double residentMiB()
{
    QFile statm(QStringLiteral("/proc/self/statm"));
    if (!statm.open(QIODevice::ReadOnly))
        return -1;
    const QList<QByteArray> fields = statm.readAll().split(' ');
    if (fields.size() < 2)
        return -1;
    return double(fields.at(1).toLongLong()) * double(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

} // namespace

class TestSoak : public QObject
{
    Q_OBJECT

    QTemporaryDir dir;
    std::unique_ptr<SimHost> sim;
    std::unique_ptr<DeviceSession> session;
    std::unique_ptr<JogController> jog;
    QRandomGenerator dice;
    QString linkPath;

    // What the soak saw, for the summary and the assertions.
    quint64 dispatched = 0;
    quint64 finished = 0;
    QSet<quint64> open; // requests put on the wire and not finished yet, by id
    int reconnects = 0;
    int writesOk = 0;
    int writesFailed = 0;
    int keysFailed = 0;
    int jogs = 0;
    int jogsCutOff = 0;
    int possiblyRunningWarnings = 0;
    QList<const Parameter *> writable;

    SimDevice *device() const { return sim->device(); }

    // The store must never claim a value the controller does not hold.
    void checkStoreIsTruthful(const Parameter *p, const char *when)
    {
        const std::optional<qint64> claimed = session->parameters()->store()->deviceValue(p->key);
        const std::optional<qint64> truth = device()->value(p->key);
        QVERIFY(truth);
        if (claimed && *claimed != *truth)
            QFAIL(qPrintable(QStringLiteral("%1: the store says the controller holds %2, it "
                                            "holds %3 (%4)")
                                 .arg(p->key, p->formatRaw(*claimed), p->formatRaw(*truth),
                                      QLatin1String(when))));
    }

    // A technician plugs the cable back in: wait for the port, connect, read everything.
    void reconnect()
    {
        QTRY_VERIFY_WITH_TIMEOUT(!sim->rtuPath().isEmpty(), 20000);
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        QSignalSpy connected(session->connection(), &SessionConnection::connected);
        LinkSettings s = session->connection()->settings();
        s.portName = linkPath;
        session->connection()->connectTo(s);
        QTRY_VERIFY_WITH_TIMEOUT(!connected.isEmpty(), 20000);
        if (!connected.last().at(0).toBool())
            return; // the port went away again at once: the loop tries again
        ++reconnects;
        // The read may fail on this line; either way it ends.
        QTRY_VERIFY_WITH_TIMEOUT(!read.isEmpty() || !session->connection()->isConnected(), 60000);
    }

    qint64 randomRaw(const Parameter *p)
    {
        qint64 lo = p->rawMin;
        qint64 hi = p->rawMax;
        if (p->localKey == QLatin1String("speed")) { // keep jogs slow and short
            lo = 30;
            hi = 600;
        } else {
            hi = std::min(hi, lo + 100000); // sizes a person would type
        }
        return lo + qint64(dice.bounded(quint64(hi - lo + 1)));
    }

    void writeSome()
    {
        QList<ParameterWrite> writes;
        const int n = 1 + int(dice.bounded(4));
        for (int i = 0; i < n; ++i) {
            const Parameter *p = writable.at(int(dice.bounded(qsizetype(writable.size()))));
            bool duplicate = false;
            for (const ParameterWrite &w : std::as_const(writes))
                duplicate = duplicate || w.parameter == p;
            if (!duplicate)
                writes.append({p, randomRaw(p)});
        }
        ParameterStore *store = session->parameters()->store();
        store->revertAll();
        for (const ParameterWrite &w : std::as_const(writes))
            QCOMPARE(store->edit(w.parameter->key, w.raw), QString());
        writes = store->pendingWrites(); // an edit to the value the device holds is no edit
        if (writes.isEmpty())
            return;
        std::optional<WriteOutcome> done;
        QHash<QString, ParameterStore::Entry> after; // the store when the outcome arrived; a
                                                     // hang-up right after may clear it again
        bool reported = false;
        QObject scope;
        connect(session->parameters(), &SessionParameters::writeFinished, &scope,
                [&](const WriteOutcome &o) {
                    done = o;
                    for (const ParameterWrite &w : std::as_const(writes))
                        after.insert(w.parameter->key, store->entry(w.parameter->key));
                });
        connect(session.get(), &DeviceSession::message, &scope,
                [&](DeviceSession::Severity severity, const QString &) {
                    reported = reported || severity == DeviceSession::Severity::Error;
                });
        session->parameters()->writeChanges();
        if (!QTest::qWaitFor([&] { return done.has_value(); }, 60000)) {
            reportHang();
            QFAIL("a parameter write never finished");
        }
        const WriteOutcome outcome = *done;

        QSet<QString> mismatched;
        for (const WriteMismatch &m : outcome.mismatches)
            mismatched.insert(m.key);
        if (outcome.ok) {
            ++writesOk;
            QVERIFY(outcome.errors.isEmpty() && mismatched.isEmpty());
        } else {
            ++writesFailed;
            QVERIFY2(!outcome.errors.isEmpty(), "a failed write without a reason");
            QVERIFY2(reported, "a failed write was not reported to the user");
        }
        for (const ParameterWrite &w : std::as_const(writes)) {
            const QString &key = w.parameter->key;
            const ParameterStore::Entry e = after.value(key);
            const bool confirmed = outcome.written.contains(key) && !mismatched.contains(key);
            if (confirmed) {
                QVERIFY2(e.state == ParameterStore::State::InSync, qPrintable(key));
                QCOMPARE(e.device, std::optional<qint64>(w.raw));
            } else {
                ++keysFailed;
                QVERIFY2(!outcome.ok, qPrintable(key + QStringLiteral(" failed in an ok write")));
                // Never shown as written: the edit is held, marked failed, with the reason.
                // (What the controller holds is checked below: the old value, the new one
                // after a lost answer, or unknown until it is read back.)
                QVERIFY2(
                    e.state == ParameterStore::State::WriteFailed && e.edited == w.raw &&
                        !e.error.isEmpty(),
                    qPrintable(
                        key + QStringLiteral(" after a failed write: state %1").arg(int(e.state))));
            }
            checkStoreIsTruthful(w.parameter, "after a write");
            if (QTest::currentTestFailed())
                return;
        }
    }

    // What the link was doing when something never ended, so a hang names its request.
    void reportHang()
    {
        const ModbusLink *link = SessionInternals::link(*session);
        qWarning("hang: link state %d, busy %d, queued %d, open requests %lld", int(link->state()),
                 int(link->isBusy()), link->queuedCount(), static_cast<long long>(open.size()));
        const QList<TrafficEntry> &log = link->traffic()->entries();
        for (qsizetype i = std::max<qsizetype>(0, log.size() - 40); i < log.size(); ++i)
            qWarning("  %s", qPrintable(TrafficLog::format(log.at(i))));
    }

    void jogOnce()
    {
        const int motor = 1 + int(dice.bounded(2));
        QSignalSpy warnings(jog.get(), &JogController::warning);
        if (!jog->press(motor, dice.bounded(2) ? JogController::Direction::Forward
                                               : JogController::Direction::Reverse))
            return; // refused (not connected, or the motor runs): said why, nothing sent
        ++jogs;
        QTest::qWait(50 + int(dice.bounded(250))); // the hand holds the button
        jog->release(motor);
        // Ends in Idle, or -- the line broke meanwhile -- in a reported "possibly running".
        QTRY_VERIFY_WITH_TIMEOUT(!jog->isBusy() || jog->state(motor) == State::PossiblyRunning ||
                                     jog->state(motor) == State::StillRunning,
                                 30000);
        if (jog->state(motor) == State::PossiblyRunning) {
            ++jogsCutOff;
            QVERIFY2(!warnings.isEmpty(), "a jog cut off without a warning");
            QVERIFY(warnings.last().at(1).toString().contains(QLatin1String("possibly")));
            ++possiblyRunningWarnings;
            return; // the stop goes out after the reconnect; checked in settle()
        }
        if (jog->state(motor) == State::StillRunning) {
            // The stop's answer or the check was lost on this line: warned, and the user
            // presses stop again.
            QVERIFY(!warnings.isEmpty());
            jog->stop(motor, QStringLiteral("soak"));
            QTRY_VERIFY_WITH_TIMEOUT(!jog->isBusy() || !session->connection()->isConnected(),
                                     30000);
        }
        if (jog->state(motor) == State::Idle)
            QTRY_VERIFY_WITH_TIMEOUT(!device()->running(motor), 5000); // reported stopped: is
    }

    // The link is back and everything went quiet: nothing left running or pending.
    void settle()
    {
        for (int m = 1; m <= jog->motorCount(); ++m) {
            if (jog->state(m) != State::Idle && session->connection()->isConnected())
                jog->stop(m, QStringLiteral("soak"));
        }
        QTRY_VERIFY_WITH_TIMEOUT(!jog->isBusy() || !session->connection()->isConnected(), 30000);
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(dir.isValid());
        // Every bad CRC and late answer is expected here; thousands of warnings help nobody.
        QLoggingCategory::setFilterRules(QStringLiteral("qt.modbus*=false"));
        linkPath = dir.filePath(QStringLiteral("controller"));
        dice.seed(quint32(envInt("STEPCOM_SOAK_SEED", 7)));
    }

    void soak()
    {
        const int target = envInt("STEPCOM_SOAK_TRANSACTIONS", 800);
        SimOptions options;
        options.rtu = true;
        options.linkPath = linkPath;
        options.answerDelayMs = 5; // more transactions a second; the faults are what counts
        // An adapter that hears itself, on top of everything (STEPCOM_SOAK_ECHO=0: without).
        options.echo = qEnvironmentVariable("STEPCOM_SOAK_ECHO") != u"0";
        options.faults.drop = 0.03;
        options.faults.corruptCrc = 0.03;
        options.faults.late = 0.03;
        options.faults.lateMs = 400; // past the client's timeout: the answer arrives too late
        options.faults.exception = 0.02;
        options.faults.exceptionCode = 6; // "busy"
        options.faults.hangupAfter = std::max(150, target / 6);
        options.faults.hangupPauseMs = 300;
        options.faults.seed = quint32(envInt("STEPCOM_SOAK_SEED", 7));
        sim = std::make_unique<SimHost>();
        QString error;
        QVERIFY2(sim->start(options, &error), qPrintable(error));

        session = std::make_unique<DeviceSession>(device()->map());
        session->status()->setIntervalMs(20);
        jog = std::make_unique<JogController>(session.get());
        jog->setSettleMs(60);
        for (int m = 1; m <= 2; ++m) {
            for (const char *k : {"speed", "pitch", "move_distance", "start_frequency"})
                writable << device()->map().blockParameter(QStringLiteral("motor"), m,
                                                           QLatin1String(k));
        }
        for (const char *k : {"arc.speed", "line.speed", "line.end_x", "arc.middle_y"})
            writable << device()->map().find(QLatin1String(k));
        for (const Parameter *p : std::as_const(writable))
            QVERIFY(p && p->writable());

        connect(SessionInternals::link(*session), &ModbusLink::dispatched, this,
                [this](quint64 id, const Request &) {
                    ++dispatched;
                    open.insert(id);
                });
        connect(SessionInternals::link(*session), &ModbusLink::finished, this,
                [this](quint64 id, const Request &, const Result &) {
                    ++finished;
                    open.remove(id);
                });

        LinkSettings s;
        s.portName = linkPath;
        s.timeoutMs = 250;
        s.retries = 2;
        s.answerDelayMs = 5; // the simulator's, or its answers would be too soon to be answers
        s.echo = sim->options().echo;
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        session->connection()->connectTo(s);
        QTRY_VERIFY_WITH_TIMEOUT(!read.isEmpty(), 30000);

        double warmRss = -1;
        int round = 0;
        while (finished < quint64(target)) {
            if (!session->connection()->isConnected()) {
                settle();
                reconnect();
                if (QTest::currentTestFailed())
                    return;
                continue;
            }
            if (warmRss < 0 && finished > quint64(target) / 5)
                warmRss = residentMiB();
            switch (round++ % 3) {
            case 0:
            case 1:
                writeSome();
                break;
            default:
                jogOnce();
                break;
            }
            if (QTest::currentTestFailed())
                return;
        }

        // Quiet down: back on the line, nothing running, nothing pending, nothing lost.
        if (!session->connection()->isConnected())
            reconnect();
        settle();
        QTRY_VERIFY_WITH_TIMEOUT(session->connection()->isConnected(), 30000);
        session->status()->stop();
        QTRY_VERIFY_WITH_TIMEOUT(!SessionInternals::link(*session)->isBusy() &&
                                     SessionInternals::link(*session)->queuedCount() == 0,
                                 30000);
        QVERIFY2(open.isEmpty(), "a request put on the wire never finished");
        for (int m = 1; m <= 2; ++m) {
            QTRY_VERIFY_WITH_TIMEOUT(!device()->running(m), 10000);
            QCOMPARE(jog->state(m), State::Idle);
        }
        for (const Parameter *p : device()->map().holdings()) {
            if (p->writable())
                checkStoreIsTruthful(p, "at the end");
        }

        const SimHost::Stats st = sim->stats();
        const double endRss = residentMiB();
        qInfo("soak (echo %s): %llu transactions (%llu put on the wire), %d reconnects, writes %d "
              "ok / %d failed (%d keys), %d jogs (%d cut off by a hang-up); simulator: %d dropped, "
              "%d corrupted, %d late, %d exceptions; RSS %.1f -> %.1f MiB",
              sim->options().echo ? "on" : "off", static_cast<unsigned long long>(finished),
              static_cast<unsigned long long>(dispatched), reconnects, writesOk, writesFailed,
              keysFailed, jogs, jogsCutOff, st.dropped, st.corrupted, st.late, st.exceptions,
              warmRss, endRss);
        // It was a bad line indeed, and the tool came through every kind of fault.
        QVERIFY(reconnects >= 1);
        QVERIFY(writesOk > 0 && writesFailed > 0);
        QVERIFY(st.dropped > 0 && st.corrupted > 0 && st.late > 0 && st.exceptions > 0);

        if (kSanitized || qEnvironmentVariableIsSet("STEPCOM_SANITIZED"))
            QSKIP("resident size is meaningless under sanitizers (quarantine, shadow memory)");
        QVERIFY(warmRss > 0 && endRss > 0);
        QVERIFY2(endRss - warmRss < 20.0,
                 qPrintable(QStringLiteral("resident size grew by %1 MiB").arg(endRss - warmRss)));
    }

    void cleanupTestCase()
    {
        jog.reset();
        session.reset();
        sim.reset();
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestSoak, Guiless)
#include "tst_soak.moc"
