#pragma once

#include <QObject>
#include <QString>

#include <functional>

namespace stepcom {

class SessionLine;

// The session's risk guard: before an operation after which a controller's settings cannot be
// had back unless saved first, the guard a front-end installs (the window's backup, stepcomctl's
// backup) runs and says whether it may go on. The session asks it before saveToFlash,
// factoryReset and a new id or baud; a front-end asks it before what it starts itself (a
// profile applied). Owned by the DeviceSession that hands it out (risks()).
class SessionRisks : public QObject
{
    Q_OBJECT
public:
    // Operations after which the controller's settings cannot be had back unless saved first.
    enum class Risk { Apply, FactoryReset, SaveToFlash, DeviceId, Baud };
    Q_ENUM(Risk)
    // Runs before a risky operation on controller `id`, then calls `proceed` once: with an empty
    // text when it may go on, else why it may not (nothing is done then).
    using Proceed = std::function<void(const QString &refusal)>;
    using Guard = std::function<void(Risk risk, int id, Proceed proceed)>;

    SessionRisks(const SessionLine *line, QObject *parent);

    // Installed by a front-end; an empty one takes it away.
    void setGuard(Guard guard) { m_guard = std::move(guard); }
    bool hasGuard() const { return bool(m_guard); }
    // Runs `proceed` after the guard (at once, agreed, without one), for the device in view or
    // for device `id` of the line.
    void guard(Risk risk, Proceed proceed);
    void guard(Risk risk, int id, Proceed proceed);

private:
    const SessionLine *m_line;
    Guard m_guard;
};

} // namespace stepcom
