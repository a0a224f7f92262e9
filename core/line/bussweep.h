#pragma once

#include "device/deviceclient.h" // ReadOutcome

#include <QHash>
#include <QList>
#include <QObject>
#include <QPointer>

namespace stepcom {

class DeviceSession;

// Reads the same parameters from every device of a list, one device after the other over the
// session's one link (the device in view's live poll and any command still go in between),
// for what covers a whole machine: every device saved into a folder, the machine's report.
// An E-STOP ends it: the devices not read yet are reported as not read.
class BusSweep : public QObject
{
    Q_OBJECT
public:
    explicit BusSweep(DeviceSession *session, QObject *parent = nullptr);

    void start(const QList<int> &ids, const QList<const Parameter *> &params);
    bool isBusy() const { return m_busy; }
    QList<int> ids() const { return m_ids; }
    // Each device's outcome (ok, values, errors), once read.
    ReadOutcome outcome(int id) const { return m_outcomes.value(id); }
    bool allOk() const;

Q_SIGNALS:
    void deviceRead(int id, bool ok);
    void finished(bool allOk);

private:
    void next();

    QPointer<DeviceSession> m_session;
    QList<int> m_ids;
    QList<const Parameter *> m_params;
    QHash<int, ReadOutcome> m_outcomes;
    int m_index = 0;
    bool m_busy = false;
    quint64 m_generation = 0;
};

} // namespace stepcom
