#pragma once

#include "bus/request.h"
#include "device/readlimits.h"
#include "device/readplanner.h"
#include "device/writeplanner.h"
#include "map/registermap.h"

#include <QHash>
#include <QObject>

#include <functional>

namespace stepcom {

class ModbusLink;

struct ReadOutcome
{
    bool ok = false;
    QHash<QString, qint64> values; // raw, by key: whatever could be read
    QStringList errors;
    QStringList unsupported; // asked for, but this controller does not have them (not an error)
    int reads = 0;
};

struct WriteMismatch
{
    QString key;
    qint64 wanted = 0;
    std::optional<qint64> got; // nullopt: could not be read back
};

struct WriteOutcome
{
    bool ok = false;
    QStringList written;    // keys the controller acknowledged
    QStringList notWritten; // keys never sent because something before them failed
    QList<WriteMismatch> mismatches;
    QStringList errors;
};

// A typed view of one controller over a ModbusLink: read parameters by key, write them with
// read-back verification, pulse commands. Every operation is asynchronous and reports once.
class DeviceClient : public QObject
{
    Q_OBJECT
public:
    DeviceClient(ModbusLink *link, const RegisterMap &map, QObject *parent = nullptr);

    const RegisterMap &map() const { return m_map; }
    ModbusLink *link() const { return m_link; }
    // The wire-time model for the link's current baud (TCP: the answer delay only).
    ReadCostModel costModel() const;
    // The cheapest reads of the parameters this controller has, within what it accepts.
    QList<ReadBlock> planRead(const QList<const Parameter *> &params) const;
    const ReadLimits &readLimits() const { return m_limits; }
    void setReadLimits(const ReadLimits &limits) { m_limits = limits; }
    // A read of `block` was answered with exception 02: learn from it (said once, by signal).
    ReadLimits::Lesson noteRefused(const ReadBlock &block, const Result &result);

    void read(const QList<const Parameter *> &params, Priority priority,
              std::function<void(const ReadOutcome &)> done);
    void readAll(std::function<void(const ReadOutcome &)> done);
    // Validates everything first (one bad value: nothing is sent), writes in planned blocks,
    // reads every value back and compares. Writing device.id or device.baud makes the link
    // follow the controller to its new id or baud before the read-back.
    void write(const QList<ParameterWrite> &writes, std::function<void(const WriteOutcome &)> done);
    // Pulse a coil (FF00). Emergency commands jump the queue.
    void command(const Parameter &coil, std::function<void(const Result &)> done);

    static Priority priorityFor(const Parameter &coil);
    // Empty when every write is allowed, else one message per bad value.
    static QStringList validate(const QList<ParameterWrite> &writes);

Q_SIGNALS:
    // Something new about what this controller reads: gaps refused, or a parameter it lacks.
    void readLimitsLearned(stepcom::ReadLimits::Lesson lesson, const QString &key);

private:
    ModbusLink *m_link;
    RegisterMap m_map;
    ReadLimits m_limits;
};

} // namespace stepcom
