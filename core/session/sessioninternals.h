#pragma once

#include "session/devicesession.h"

namespace stepcom {

// What the session does not hand out -- its link, client and poller -- for the tests that must
// fake or watch the wire itself (the requests as they go out, the poller's own timing) and for
// the benchmark's measurements of the link. Everything else is reached through the parts
// (connection(), status(), parameters(), line()); front-ends never include this.
class SessionInternals
{
public:
    static ModbusLink *link(const DeviceSession &session) { return session.m_link; }
    static DeviceClient *client(const DeviceSession &session) { return session.m_client; }
    static Poller *poller(const DeviceSession &session) { return session.m_poller; }
};

} // namespace stepcom
