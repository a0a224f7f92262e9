#pragma once

#include "ctloptions.h"
#include "ctlrunner.h"
#include "map/registermap.h"
#include "session/devicesession.h"

#include <QJsonObject>
#include <QJsonValue>
#include <QStringList>
#include <QTextStream>

#include <functional>

namespace stepcom {

struct Parameter;

// What every stepcomctl command works over (app/ctl/commands): the options, the map, the link,
// where it prints and what it comes to. A command is a function of it; the runner (CtlRunner)
// owns it, chooses the command and ends the run. Its messages are CtlRunner::tr(), the context
// their translations have always had.
class CtlContext
{
public:
    CtlContext(CtlRunner *owner, const CtlOptions &runOptions, const RegisterMap &runMap);

    // The run's QObject: the parent of what a command makes and the context of its connections,
    // so nothing outlives the run.
    QObject *runner() const;

    // Opens the link the options name (once: the next id of several reuses it), then `next`.
    void connectThen(std::function<void()> next);
    // Runs `next` once the session's risk guard let `risk` go on; fails (nothing done) when not.
    void guardThen(DeviceSession::Risk risk, std::function<void()> next);
    // Says "stepcomctl: message" on the error stream and ends the run with `code`.
    void fail(int code, const QString &message);
    // Ends the command with `code` (CtlRunner::Exit); the runner goes on to the next id or ends.
    void finish(int code);

    // --id with several ids: the command runs for each in turn over the one link.
    bool isMulti() const { return options.ids.size() > 1; }
    // --json: the runner keeps what a command prints for the object at the end.
    bool isEnveloped() const { return options.json; }

    // A value with its label or unit, as the commands print it.
    QString valueText(const Parameter &p, qint64 raw) const;
    // A value in engineering units as JSON: a number.
    static QJsonValue jsonValue(const Parameter &p, qint64 raw);
    // The errors of one read, each answer said once: on a dead line every block of the read
    // gets the same "no answer", which is said for the first with how many more had it.
    static QStringList condensed(const QStringList &errors);

    CtlOptions options;
    RegisterMap map;
    DeviceSession *session = nullptr; // made by connectThen, a child of the runner
    QTextStream out;
    QTextStream err;
    QString outBuffer; // --json or several ids: what `out` printed for this run
    QString errBuffer; // and `err`, said at the end (prefixed with the id)
    // The exit code of a link that cannot be opened or read: DeviceError, except for diff,
    // where 1 already means "different".
    int linkError = CtlRunner::DeviceError;
    int idIndex = 0;        // --id with several: the one this run is for
    QJsonObject result;     // --json: what the current run came to
    QStringList liveErrors; // monitor, listen: the errors already said as they came

private:
    // The session's risk guard, as the window installs one: a backup of the controller's
    // settings before every risky operation (unless --no-backup), said where.
    void installRiskGuard();
    // --log FILE: the session log of this run.
    void startLog();

    CtlRunner *m_runner;
};

} // namespace stepcom
