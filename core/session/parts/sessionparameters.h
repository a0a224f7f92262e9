#pragma once

#include "bus/request.h"           // Priority
#include "device/deviceclient.h"   // ReadOutcome, WriteOutcome, in signals
#include "device/parameterstore.h" // what store() hands out
#include "device/writeplanner.h"   // ParameterWrite

#include <QList>
#include <QObject>

#include <functional>

namespace stepcom {

class DeviceSession;
struct Parameter;

// The parameters of the device in view: what the controller holds and what the user edited
// (the store, a model pages and forms bind to), and reading and writing them. Owned by the
// DeviceSession that hands it out (parameters()); the session keeps the store up to date.
class SessionParameters : public QObject
{
    Q_OBJECT
public:
    SessionParameters(DeviceSession *session, ParameterStore *store);

    ParameterStore *store() const { return m_store; }
    // Read everything into the store (reading never writes); readFinished() follows.
    void readAll();
    // Read these parameters (or all) and hand the outcome over; the store is left alone.
    void read(const QList<const Parameter *> &params, std::function<void(const ReadOutcome &)> done,
              Priority priority = Priority::Read);
    void readAll(std::function<void(const ReadOutcome &)> done);
    // Write every edit held in the store, verify, and update the store.
    void writeChanges();
    // `done` (optional) hears this write's outcome, after the store has taken it.
    void write(const QList<ParameterWrite> &writes,
               std::function<void(const WriteOutcome &)> done = {});

Q_SIGNALS:
    void readFinished(bool ok);
    void writeFinished(const stepcom::WriteOutcome &outcome);

private:
    // After a failed write, read back what the controller holds for the keys whose request went
    // out without a good answer.
    void readBackUncertain(const QList<ParameterWrite> &writes, const WriteOutcome &outcome);

    DeviceSession *m_session;
    ParameterStore *m_store;
};

} // namespace stepcom
