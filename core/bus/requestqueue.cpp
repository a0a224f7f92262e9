#include "bus/requestqueue.h"

namespace stepcom {

void RequestQueue::push(QueuedRequest item)
{
    auto it = m_items.begin();
    while (it != m_items.end() && it->request.priority <= item.request.priority)
        ++it;
    m_items.insert(it, std::move(item));
}

void RequestQueue::pushFront(QueuedRequest item)
{
    auto it = m_items.begin();
    while (it != m_items.end() && it->request.priority < item.request.priority)
        ++it;
    m_items.insert(it, std::move(item));
}

QueuedRequest RequestQueue::takeNext()
{
    return m_items.takeFirst();
}

int RequestQueue::count(Priority p) const
{
    int n = 0;
    for (const QueuedRequest &q : m_items)
        n += q.request.priority == p ? 1 : 0;
    return n;
}

QList<QueuedRequest> RequestQueue::takeFrom(Priority p)
{
    QList<QueuedRequest> taken;
    for (auto it = m_items.begin(); it != m_items.end();) {
        if (it->request.priority >= p) {
            taken << std::move(*it);
            it = m_items.erase(it);
        } else {
            ++it;
        }
    }
    return taken;
}

QList<QueuedRequest> RequestQueue::takeAll()
{
    return std::exchange(m_items, {});
}

} // namespace stepcom
