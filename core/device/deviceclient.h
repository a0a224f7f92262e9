#pragma once

#include "bus/request.h"
#include "device/readlimits.h"
#include "device/readplanner.h"
#include "device/writeplanner.h"
#include "map/registermap.h"

#include <QHash>
#include <QObject>

#include <functional>
#include <memory>

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
    QStringList refused;    // keys whose request the controller answered with an exception
    QList<WriteMismatch> mismatches;
    QStringList errors;

    // The one answer to "is it verified?": acknowledged and read back equal.
    bool verified(const QString &key) const;
    // Acknowledged but read back other (or not at all): null when it read back equal or was
    // not acknowledged.
    const WriteMismatch *mismatch(const QString &key) const;
    // Sent without a good answer (no answer, a lost link): whether the controller took it is
    // not known.
    bool uncertain(const QString &key) const;
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
    // The wire-time model for the link's current baud (TCP: the answer delay only), with
    // `unit`'s own answer time once the line measured it (ModbusLink::answerTimeMs).
    ReadCostModel costModel(int unit) const;
    // The cheapest reads of the parameters this controller has, within what it accepts.
    QList<ReadBlock> planRead(const QList<const Parameter *> &params) const;
    QList<ReadBlock> planRead(int unit, const QList<const Parameter *> &params) const;
    // What each controller on the line refuses to read, by unit id (a lesson is per id).
    const ReadLimits &readLimits() const { return readLimits(currentUnit()); }
    const ReadLimits &readLimits(int unit) const;
    QHash<int, ReadLimits> allReadLimits() const { return *m_limits; }
    void setAllReadLimits(const QHash<int, ReadLimits> &limits) { *m_limits = limits; }
    // Another client on the same line learns from and plans with the same limits.
    void shareReadLimits(DeviceClient *other) { other->m_limits = m_limits; }
    // A read of `block` sent to `unit` was answered with exception 02: learn from it (said
    // once, by signal).
    ReadLimits::Lesson noteRefused(const ReadBlock &block, const Result &result)
    {
        return noteRefused(currentUnit(), block, result);
    }
    ReadLimits::Lesson noteRefused(int unit, const ReadBlock &block, const Result &result);

    void read(const QList<const Parameter *> &params, Priority priority,
              std::function<void(const ReadOutcome &)> done);
    void readAll(std::function<void(const ReadOutcome &)> done);
    // Validates everything first (one bad value: nothing is sent), writes in planned blocks,
    // reads every value back and compares. Writing device.id or device.baud makes the link
    // follow the controller to its new id or baud before the read-back.
    void write(const QList<ParameterWrite> &writes, std::function<void(const WriteOutcome &)> done);
    // Pulse a coil (FF00). Emergency commands jump the queue.
    void command(const Parameter &coil, std::function<void(const Result &)> done);

    // The controller this client speaks to on a line of several; 0 (the default): the link's
    // device id at the moment each request goes out.
    void setUnitId(int id) { m_unitId = id; }
    int unitId() const { return m_unitId; }
    // The id the next request goes to: the set unit id, else the link's device id.
    int currentUnit() const;
    // Queue a request for this client's controller.
    quint64 submit(Request request, ResultCallback callback, QObject *context);

    static Priority priorityFor(const Parameter &coil);
    // Save to flash and factory reset: the firmware may write its flash before it answers.
    static constexpr int kSlowCommandTimeoutMs = 5000;
    // Empty when every write is allowed, else one message per bad value.
    static QStringList validate(const QList<ParameterWrite> &writes);

Q_SIGNALS:
    // Something new about what this controller reads: gaps refused, or a parameter it lacks.
    void readLimitsLearned(int unit, stepcom::ReadLimits::Lesson lesson, const QString &key);

private:
    ModbusLink *m_link;
    RegisterMap m_map;
    std::shared_ptr<QHash<int, ReadLimits>> m_limits;
    int m_unitId = 0;
};

} // namespace stepcom
