#pragma once

// The session: the parts it hands out and what only the whole can do. Each part has its own
// header under session/parts/, included by the callers that need it; this one includes no
// client, store, poller or planner header, so touching those rebuilds only their users.
#include "map/registermap.h"     // RegisterMap::builtin(), the constructor's default
#include "motion/travellimits.h" // TravelLimits
#include "session/parts/sessionrisks.h"
#include "session/restartwatch.h" // RestartWatch::Zeros, ::Evidence, in signals

#include <QHash>
#include <QObject>
#include <QSet>

#include <functional>
#include <memory>

namespace stepcom {

class BusPoller;
class DeviceClient;
class DeviceMemory;
class JogController;
class LinkHealth;
class ModbusLink;
class MotionSupervisor;
class ParameterStore;
class Poller;
class ReadLimits;
class Reconnector;
class SessionConnection;
class SessionLine;
class SessionLog;
class SessionParameters;
class SessionStatus;
class SimulatorStarter;
class StepMove;
struct LinkSettings;
struct ReadOutcome;
struct Result;

// One controller connection and everything known about it. Every front-end (the window,
// stepcomctl, the benchmark, the screenshot tool, the tests) works through this front door:
// it hands out its parts -- connection(), status(), parameters(), line(), motion(), jog() --
// and does itself only what needs the whole: commands and the emergency stop, saving and the
// factory reset, live or not, the simulator, restarts. It owns the link, the typed client, the
// store, the poller and the parts, which work on its state (they are its friends); the link's
// and the poller's own objects are not handed out. Its declarations are grouped by concern,
// each group naming the .cpp that implements it (docs/architecture.md, "Who owns what").
class DeviceSession : public QObject
{
    Q_OBJECT
public:
    enum class Severity { Info, Warning, Error };
    Q_ENUM(Severity)
    // Why every jog must stop now (the rules live here; the window reports what happened).
    enum class JogStop { PageLeft, FocusLost, WindowClosing };
    Q_ENUM(JogStop)
    // The risk guard's words, here too: every front-end names them DeviceSession::Risk.
    using Risk = SessionRisks::Risk;
    using Proceed = SessionRisks::Proceed;
    using RiskGuard = SessionRisks::Guard;
    // A command answered after this long is said with its answer time ("answered after 0.8 s").
    static constexpr qint64 kSlowAnswerMs = 300;

    explicit DeviceSession(const RegisterMap &map = RegisterMap::builtin(),
                           QObject *parent = nullptr);
    ~DeviceSession() override;

    // -- Its parts and what it holds (devicesession.cpp) --
    const RegisterMap &map() const;
    // The values the session knows, what the controller holds and what the user edited (its
    // store, the model pages and forms bind to), and reading and writing them
    // (parts/sessionparameters.h).
    SessionParameters *parameters() const { return m_parameters; }
    JogController *jog() const { return m_jog; }
    // The live status poll of the device in view and its recording (parts/sessionstatus.h).
    SessionStatus *status() const { return m_status; }
    // Follows motion commands to their judged outcome and keeps each axis' reference state.
    MotionSupervisor *motion() const { return m_motion; }
    // Step jogs and move-to over the single move, judged by the supervisor.
    StepMove *stepMove() const { return m_step; }
    // StepCom's software travel limits (not controller registers): steps and move-to beyond
    // them are refused, a hold-to-move jog crossing them is stopped on the next poll.
    const TravelLimits &travelLimits() const { return m_limits; }
    void setTravelLimits(const TravelLimits &limits);
    // The risk guard (parts/sessionrisks.h): a front-end installs its backup there; the session
    // asks it before saveToFlash, factoryReset and changeLink, a front-end before what it starts.
    SessionRisks *risks() const { return m_risks; }

    // -- Connection (its part: parts/sessionconnection.h; what the session does when the link
    // opens or drops: devicesessionconnect.cpp) --
    SessionConnection *connection() const { return m_connection; }
    // The devices of its line, the one in view, and a new id or baud for it
    // (parts/sessionline.h).
    SessionLine *line() const { return m_line; }
    // Every frame of every connection, in a file a day (session/sessionlog.h): made on first
    // use and logging from then on, so only a front-end that asks for a log writes one.
    SessionLog *log();
    // Live (the default, as the window wants it): read everything after connecting, poll the
    // status while connected, read back what a failed write left uncertain. stepcomctl turns it
    // off, so a command puts on the wire only what it names.
    // Turning it off while connected stops the polls; on again reads everything and polls
    // (devicesession.cpp).
    void setLive(bool live);
    bool isLive() const { return m_live; }
    // The built-in simulator, injected by programs that offer --sim (the session owns it).
    void setSimulator(std::unique_ptr<SimulatorStarter> simulator);
    SimulatorStarter *simulatorStarter() const { return m_sim.get(); }

    // -- Commands and stops (devicesession.cpp) --
    // Pulse a command coil by key, say how it went and emit commandFinished; emergency ones
    // jump the queue.
    void command(const QString &key);
    // The one command path: pulse this coil and hand the result to `done`, which reports it.
    void command(const Parameter &coil, std::function<void(const Result &)> done);
    // Always goes out at once, ahead of everything queued; never asks.
    void emergencyStop();
    void saveToFlash();
    void factoryReset(); // the caller confirmed what will be lost
    // Stop every jog for this reason; returns how many stops were sent or scheduled.
    int stopJogging(JogStop why);

    // -- Restarts (sessionrestart.cpp): controllerRestarted() and controllerMayHaveRestarted()
    // say it --
    // A status read of device `id` a front-end made itself rather than through the polls
    // (stepcomctl's monitor of several): `values` (raw, by key) when it was answered. Watched
    // for a restart per device as the polls' own reads are.
    void statusSampled(int id, bool ok, const QHash<QString, qint64> &values);

Q_SIGNALS:
    // -- Reading and writing --
    void message(stepcom::DeviceSession::Severity severity, const QString &text);
    void travelLimitsChanged();
    // -- Commands and stops --
    void commandFinished(const QString &key, bool ok);
    // After emergencyStop(): which controllers acknowledged their E-STOP, and which did not
    // (in the order of the list).
    void emergencyStopFinished(const QList<int> &acknowledged, const QList<int> &notAcknowledged);
    // emergencyStop() was asked for, before anything is cancelled or sent: work that runs
    // device after device (a profile applied to several) stops here.
    void emergencyStopRequested();
    // -- Restarts --
    // Controller `id` restarted (power off?): what it read afterwards differs from what the
    // session held (`lost`: "motor1.speed 222 → 120 rpm"), or an axis that stood still went to
    // 0 (`seen`: the silence and each axis). Its followed motions ended, its references are
    // gone; its values shown are the ones read after the restart.
    void controllerRestarted(int id, const QStringList &lost,
                             const stepcom::RestartWatch::Evidence &seen);
    // Controller `id` may have restarted: it answers again after a silence with every axis at
    // 0, but only axes that were moving went there (a motion may end at 0) and nothing else it
    // holds differs. Its followed motions ended "not known", its references are not known.
    void controllerMayHaveRestarted(int id, const stepcom::RestartWatch::Evidence &seen);

private:
    friend class SessionInternals;  // tests and the benchmark's link measurements
    friend class SessionConnection; // works on the session's link
    friend class SessionLine;       // and on its devices
    friend class SessionParameters; // and on its client

    void say(Severity severity, const QString &text);
    // -- Connection (devicesessionconnect.cpp) --
    void openLink(const LinkSettings &settings);
    // The reconnector's attempt: the same line (or the simulator) again, limits kept.
    void reopen(const LinkSettings &settings);
    void onOpened(bool ok, const QString &reason);
    void onLost(const QString &reason);
    // What a connect found already known of this controller, said once in words.
    void sayKnownLimits(int id);
    // `lesson`: a ReadLimits::Lesson (kept out of this header with the client's).
    void learnt(int unit, int lesson, const QString &key);
    // -- Reading, writing, commands (devicesession.cpp) --
    void guardedCommand(Risk risk, const QString &key);
    // After a factory reset: show what it holds now, and say where that is not the factory's.
    void factoryResetReadBack(const ReadOutcome &r);
    void emergencyStopAll(const QList<int> &ids);
    // The devices not in view, for the background poll.
    void updateBackground();
    // -- Restarts (sessionrestart.cpp) --
    // A restart of the controllers seen and said.
    void watchRestarts();
    void checkRestart(int id, const QString &why, stepcom::RestartWatch::Zeros zeros,
                      const stepcom::RestartWatch::Evidence &seen);
    void restartChecked(int id, const QString &why, stepcom::RestartWatch::Zeros zeros,
                        const stepcom::RestartWatch::Evidence &seen,
                        const QHash<QString, qint64> &held, const ReadOutcome &read);

    ModbusLink *m_link;
    SessionConnection *m_connection;
    SessionLine *m_line;
    DeviceClient *m_client;
    ParameterStore *m_store;
    SessionParameters *m_parameters;
    Poller *m_poller;
    SessionStatus *m_status;
    MotionSupervisor *m_motion; // made before the jog controller, which follows it
    LinkHealth *m_health;
    JogController *m_jog;
    StepMove *m_step;
    TravelLimits m_limits;
    SessionRisks *m_risks;
    BusPoller *m_bus;
    DeviceMemory *m_memory; // what the store held for each device not in view
    QList<int> m_deviceIds; // the line's devices in order; empty: the link's id alone
    std::unique_ptr<SimulatorStarter> m_sim;
    bool m_usingSim = false;
    bool m_readAfterConnect = false;
    bool m_readAllAfterStatus = false; // live values first: read everything after one status
    bool m_live = true;
    QHash<QString, QHash<int, ReadLimits>> m_knownLimits; // by lineKey(), then unit id
    Reconnector *m_reconnector = nullptr;
    bool m_estopPending = false; // pressed while the link was down: sent first when it is back
    bool m_resumeStatus = false; // the status poll ran when the link was lost
    QSet<QString> m_restored;    // "line#id" taken from the saved settings, not said yet
    RestartWatch *m_restarts = nullptr;
    SessionLog *m_log = nullptr;
    QSet<int> m_checkingRestart; // devices being read again after a suspected restart
};

} // namespace stepcom
