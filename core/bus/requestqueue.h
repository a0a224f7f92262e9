#pragma once

#include "bus/request.h"

#include <QList>
#include <QObject>
#include <QPointer>

namespace stepcom {

struct QueuedRequest
{
    quint64 id = 0;
    Request request;
    ResultCallback callback;
    QPointer<QObject> context; // callback dropped when the context is gone
    bool hasContext = false;
    int attempts = 0;
};

// Requests waiting for the line, by priority, first come first served within one priority.
// Pure data structure so its ordering rules can be tested without a bus.
class RequestQueue
{
public:
    void push(QueuedRequest item);
    // Put a request back at the head of its priority (a retry keeps its place).
    void pushFront(QueuedRequest item);
    QueuedRequest takeNext();
    bool isEmpty() const { return m_items.isEmpty(); }
    int size() const { return int(m_items.size()); }
    int count(Priority p) const;
    // Remove and return every request of priority p or lower (higher number).
    QList<QueuedRequest> takeFrom(Priority p);
    QList<QueuedRequest> takeAll();

private:
    QList<QueuedRequest> m_items; // kept sorted by priority, stable
};

} // namespace stepcom
