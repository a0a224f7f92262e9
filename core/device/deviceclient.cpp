#include "device/deviceclient.h"

#include "bus/modbuslink.h"

#include <QCoreApplication>

#include <memory>

namespace stepcom {

namespace {

const QString kDeviceId = QStringLiteral("device.id");
const QString kDeviceBaud = QStringLiteral("device.baud");

} // namespace

DeviceClient::DeviceClient(ModbusLink *link, const RegisterMap &map, QObject *parent)
    : QObject(parent)
    , m_link(link)
    , m_map(map)
    , m_limits(std::make_shared<QHash<int, ReadLimits>>())
{}

int DeviceClient::currentUnit() const
{
    return m_unitId > 0 ? m_unitId : m_link->settings().deviceId;
}

const ReadLimits &DeviceClient::readLimits(int unit) const
{
    static const ReadLimits none;
    const auto it = m_limits->constFind(unit);
    return it == m_limits->cend() ? none : *it;
}

ReadCostModel DeviceClient::costModel(int unit) const
{
    const LinkSettings &s = m_link->settings();
    // The controller's own answer time once the line showed it apart from the wire's (a fast
    // firmware answers in 2 ms: another request then costs less than reading across a gap);
    // the manual's until then.
    const double answerMs = m_link->answerTimeMs(unit).value_or(double(m_map.answerDelayMs()));
    return ReadCostModel::forBaud(s.transport == LinkSettings::Transport::Rtu ? s.baud : 0,
                                  answerMs);
}

QList<ReadBlock> DeviceClient::planRead(const QList<const Parameter *> &params) const
{
    return planRead(currentUnit(), params);
}

QList<ReadBlock> DeviceClient::planRead(int unit, const QList<const Parameter *> &params) const
{
    const ReadLimits &limits = readLimits(unit);
    QList<const Parameter *> present;
    for (const Parameter *p : params) {
        if (p && !limits.isUnsupported(p->key))
            present << p;
    }
    ReadPlanner::MayRead mayRead;
    if (!limits.isEmpty())
        mayRead = [this, limits](int first, int last) {
            return limits.mayRead(m_map, first, last);
        };
    return ReadPlanner::plan(present, m_map.maxRegistersPerRequest(), costModel(unit), mayRead);
}

ReadLimits::Lesson DeviceClient::noteRefused(int unit, const ReadBlock &block, const Result &result)
{
    if (result.ok || result.exceptionCode != 2)
        return ReadLimits::Lesson::None;
    QString key;
    const ReadLimits::Lesson lesson = (*m_limits)[unit].learn(m_map, block, &key);
    if (lesson == ReadLimits::Lesson::GapsRefused || lesson == ReadLimits::Lesson::Unsupported)
        Q_EMIT readLimitsLearned(unit, lesson, key);
    return lesson;
}

namespace {

// One read of several blocks; a block refused for what the controller lacks is planned again
// within what it accepts, and only the rest is an error.
struct ReadJob : std::enable_shared_from_this<ReadJob>
{
    DeviceClient *client = nullptr;
    int unit = 0; // the controller asked, whatever the link's id is by the time it answers
    QList<const Parameter *> params;
    Priority priority = Priority::Read;
    std::function<void(const ReadOutcome &)> done;
    ReadOutcome outcome;
    int pending = 0;
    int index = 0;

    void submit(const QList<ReadBlock> &blocks)
    {
        pending += int(blocks.size());
        outcome.reads += int(blocks.size());
        for (const ReadBlock &block : blocks) {
            Request req = Request::read(block.address, block.count, priority);
            req.unitId = unit;
            req.what = DeviceClient::tr("read block %1/%2").arg(++index).arg(outcome.reads);
            auto self = shared_from_this();
            client->submit(
                req, [self, block](const Result &r) { self->answered(block, r); }, client);
        }
    }

    QList<const Parameter *> inside(const ReadBlock &block) const
    {
        QList<const Parameter *> out;
        for (const Parameter *p : params) {
            if (p->address >= block.address && p->lastAddress() <= block.lastAddress())
                out << p;
        }
        return out;
    }

    void answered(const ReadBlock &block, const Result &r)
    {
        if (r.ok) {
            for (const Parameter *p : inside(block))
                outcome.values.insert(
                    p->key, p->decode(r.values.constData() + (p->address - block.address)));
        } else if (client->noteRefused(unit, block, r) != ReadLimits::Lesson::None) {
            // Read again what this block held, planned within what is known now.
            submit(client->planRead(unit, inside(block)));
        } else {
            outcome.errors << r.errorText;
        }
        if (--pending == 0)
            finish();
    }

    void finish()
    {
        for (const Parameter *p : std::as_const(params)) {
            if (client->readLimits(unit).isUnsupported(p->key) &&
                !outcome.unsupported.contains(p->key))
                outcome.unsupported << p->key;
        }
        outcome.ok = outcome.errors.isEmpty();
        done(outcome);
    }
};

} // namespace

void DeviceClient::read(const QList<const Parameter *> &params, Priority priority,
                        std::function<void(const ReadOutcome &)> done)
{
    auto job = std::make_shared<ReadJob>();
    job->client = this;
    job->unit = currentUnit();
    job->priority = priority;
    job->done = std::move(done);
    for (const Parameter *p : params) {
        if (p && p->readable())
            job->params << p;
    }
    const QList<ReadBlock> blocks = planRead(job->unit, params);
    if (blocks.isEmpty()) {
        const ReadLimits &limits = readLimits(job->unit);
        const bool allUnsupported =
            !job->params.isEmpty() &&
            std::all_of(job->params.cbegin(), job->params.cend(),
                        [&limits](const Parameter *p) { return limits.isUnsupported(p->key); });
        if (!params.isEmpty() && !allUnsupported)
            job->outcome.errors << tr("nothing readable among the parameters asked for");
        QTimer::singleShot(0, this, [job] { job->finish(); });
        return;
    }
    job->submit(blocks);
}

void DeviceClient::readAll(std::function<void(const ReadOutcome &)> done)
{
    read(m_map.holdings(), Priority::Read, std::move(done));
}

QStringList DeviceClient::validate(const QList<ParameterWrite> &writes)
{
    QStringList problems;
    QSet<QString> seen;
    for (const ParameterWrite &w : writes) {
        if (!w.parameter) {
            problems << tr("unknown parameter");
            continue;
        }
        if (!w.parameter->writable())
            problems << tr("%1 is read-only").arg(w.parameter->key);
        else if (const QString why = w.parameter->checkRaw(w.raw); !why.isEmpty())
            problems << why;
        if (seen.contains(w.parameter->key))
            problems << tr("%1 is given twice").arg(w.parameter->key);
        seen.insert(w.parameter->key);
    }
    return problems;
}

bool WriteOutcome::verified(const QString &key) const
{
    return written.contains(key) && !mismatch(key);
}

const WriteMismatch *WriteOutcome::mismatch(const QString &key) const
{
    for (const WriteMismatch &m : mismatches) {
        if (m.key == key)
            return &m;
    }
    return nullptr;
}

bool WriteOutcome::uncertain(const QString &key) const
{
    return !written.contains(key) && !notWritten.contains(key) && !refused.contains(key);
}

namespace {

// One write-and-verify run; steps chain through callbacks, never a nested event loop.
struct WriteJob : std::enable_shared_from_this<WriteJob>
{
    DeviceClient *client = nullptr;
    QList<Request> requests;          // ordinary parameters, planned
    QList<ParameterWrite> all;        // everything, for the read-back
    QList<ParameterWrite> linkWrites; // device.id / device.baud, written last
    std::function<void(const WriteOutcome &)> done;
    WriteOutcome outcome;
    QHash<quint16, const Parameter *> byAddress;

    void writeNext(int index)
    {
        if (index >= requests.size()) {
            writeLinkSettings(0);
            return;
        }
        auto self = shared_from_this();
        client->submit(
            requests.at(index),
            [self, index](const Result &r) {
                const QStringList keys = self->requests.at(index).what.split(QStringLiteral(", "));
                if (!r.ok) {
                    self->outcome.errors << r.errorText;
                    if (r.exceptionCode != 0) // answered: it did not take them
                        self->outcome.refused += keys;
                    for (int i = index + 1; i < self->requests.size(); ++i)
                        self->outcome.notWritten +=
                            self->requests.at(i).what.split(QStringLiteral(", "));
                    for (const ParameterWrite &w : std::as_const(self->linkWrites))
                        self->outcome.notWritten << w.parameter->key;
                    self->verify();
                    return;
                }
                self->outcome.written += keys;
                self->writeNext(index + 1);
            },
            client);
    }

    void writeLinkSettings(int index)
    {
        if (index >= linkWrites.size()) {
            verify();
            return;
        }
        const ParameterWrite w = linkWrites.at(index);
        Request req = Request::write(w.parameter->address, w.parameter->encode(w.raw));
        req.what = w.parameter->key;
        auto self = shared_from_this();
        client->submit(
            req,
            [self, index, w](const Result &r) {
                if (!r.ok) {
                    self->outcome.errors << r.errorText;
                    if (r.exceptionCode != 0)
                        self->outcome.refused << w.parameter->key;
                    self->verify();
                    return;
                }
                self->outcome.written << w.parameter->key;
                ModbusLink *link = self->client->link();
                if (w.parameter->key == kDeviceId) {
                    link->setDeviceId(int(w.raw)); // the controller answers at its new id now
                    self->writeLinkSettings(index + 1);
                } else if (w.parameter->key == kDeviceBaud &&
                           link->settings().transport == LinkSettings::Transport::Rtu) {
                    LinkSettings s = link->settings();
                    s.baud = int(w.raw);
                    auto connection = std::make_shared<QMetaObject::Connection>();
                    *connection = QObject::connect(
                        link, &ModbusLink::opened, self->client,
                        [self, index, connection](bool ok, const QString &reason) {
                            QObject::disconnect(*connection);
                            if (!ok) {
                                self->outcome.errors
                                    << DeviceClient::tr(
                                           "could not reopen the port at the new baud: %1")
                                           .arg(reason);
                                self->finish();
                                return;
                            }
                            self->writeLinkSettings(index + 1);
                        });
                    link->open(s);
                } else {
                    self->writeLinkSettings(index + 1);
                }
            },
            client);
    }

    void verify()
    {
        QList<const Parameter *> params;
        for (const ParameterWrite &w : std::as_const(all)) {
            if (outcome.written.contains(w.parameter->key))
                params << w.parameter;
        }
        if (params.isEmpty()) {
            finish();
            return;
        }
        auto self = shared_from_this();
        client->read(params, Priority::Command, [self](const ReadOutcome &read) {
            for (const ParameterWrite &w : std::as_const(self->all)) {
                if (!self->outcome.written.contains(w.parameter->key))
                    continue;
                const auto it = read.values.constFind(w.parameter->key);
                if (it == read.values.cend())
                    self->outcome.mismatches.append({w.parameter->key, w.raw, std::nullopt});
                else if (*it != w.raw)
                    self->outcome.mismatches.append({w.parameter->key, w.raw, *it});
            }
            self->outcome.errors += read.errors;
            self->finish();
        });
    }

    void finish()
    {
        for (const WriteMismatch &m : std::as_const(outcome.mismatches)) {
            const Parameter *p = client->map().find(m.key);
            outcome.errors << (m.got ? DeviceClient::tr("%1: wrote %2 but the controller holds %3")
                                           .arg(m.key, p->formatRaw(m.wanted), p->formatRaw(*m.got))
                                     : DeviceClient::tr("%1: wrote %2 but could not read it back")
                                           .arg(m.key, p->formatRaw(m.wanted)));
        }
        outcome.ok = outcome.errors.isEmpty();
        done(outcome);
    }
};

} // namespace

void DeviceClient::write(const QList<ParameterWrite> &writes,
                         std::function<void(const WriteOutcome &)> done)
{
    auto job = std::make_shared<WriteJob>();
    job->client = this;
    job->done = std::move(done);
    job->all = writes;
    job->outcome.errors = validate(writes);
    if (!job->outcome.errors.isEmpty()) {
        for (const ParameterWrite &w : writes) {
            if (w.parameter)
                job->outcome.notWritten << w.parameter->key;
        }
        QTimer::singleShot(0, this, [job] { job->done(job->outcome); });
        return;
    }
    QList<ParameterWrite> ordinary;
    for (const ParameterWrite &w : writes) {
        if (w.parameter->key == kDeviceId || w.parameter->key == kDeviceBaud)
            job->linkWrites << w;
        else
            ordinary << w;
    }
    // The id first, then the baud: each answers before it takes effect.
    std::sort(job->linkWrites.begin(), job->linkWrites.end(),
              [](const ParameterWrite &a, const ParameterWrite &b) {
                  return a.parameter->key == kDeviceId && b.parameter->key != kDeviceId;
              });
    job->requests = WritePlanner::plan(ordinary, m_map.maxRegistersPerRequest());
    job->writeNext(0);
}

Priority DeviceClient::priorityFor(const Parameter &coil)
{
    return coil.command == CommandClass::Emergency ? Priority::Emergency : Priority::Command;
}

void DeviceClient::command(const Parameter &coil, std::function<void(const Result &)> done)
{
    Request req = Request::coil(coil.address, true, priorityFor(coil));
    req.what = coil.key;
    // Stops are safe to repeat; anything that moves or changes state is not.
    req.retryable = coil.command == CommandClass::Emergency || coil.command == CommandClass::Output;
    // Saving to flash or restoring the factory values, the firmware may write its flash before
    // it answers: give it its own time (never less than the line's), and never repeat it.
    if (coil.command == CommandClass::Setting || coil.command == CommandClass::Destructive)
        req.timeoutMs = std::max(kSlowCommandTimeoutMs, m_link->settings().timeoutMs);
    // A command goes to the controller that was in view when it was given, even if the view
    // moves to another device before it reaches the wire.
    if (m_unitId == 0)
        req.unitId = m_link->settings().deviceId;
    submit(req, std::move(done), this);
}

quint64 DeviceClient::submit(Request request, ResultCallback callback, QObject *context)
{
    if (m_unitId > 0)
        request.unitId = m_unitId;
    return m_link->submit(std::move(request), std::move(callback), context);
}

} // namespace stepcom
