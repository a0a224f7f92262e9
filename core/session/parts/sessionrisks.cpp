#include "session/parts/sessionrisks.h"
#include "session/parts/sessionline.h"

namespace stepcom {

SessionRisks::SessionRisks(const SessionLine *line, QObject *parent)
    : QObject(parent)
    , m_line(line)
{}

void SessionRisks::guard(Risk risk, Proceed proceed)
{
    guard(risk, m_line->deviceInView(), std::move(proceed));
}

void SessionRisks::guard(Risk risk, int id, Proceed proceed)
{
    if (m_guard)
        m_guard(risk, id, std::move(proceed));
    else
        proceed(QString());
}

} // namespace stepcom
