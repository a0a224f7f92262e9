#pragma once

#include "session/devicesession.h"
#include "session/parts/sessionstatus.h"
#include "session/parts/sessionparameters.h"

namespace stepcom {

// The session's parts, for the tests that check them and for the benchmark's measurements of
// the link itself. Front-ends never include this: they use the session's own API.
class SessionInternals
{
public:
    static ModbusLink *link(const DeviceSession &session) { return session.m_link; }
    static DeviceClient *client(const DeviceSession &session) { return session.m_client; }
    static Poller *poller(const DeviceSession &session) { return session.m_poller; }
};

} // namespace stepcom
