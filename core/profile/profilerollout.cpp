#include "profile/profilerollout.h"

#include "profile/backupstore.h"
#include "session/devicesession.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"

#include <QTimer>

namespace stepcom {

ProfileRollout::ProfileRollout(DeviceSession *session, const Profile &profile, QObject *parent)
    : QObject(parent)
    , m_session(session)
    , m_profile(profile)
    , m_backupDir(BackupStore::defaultDirectory())
{
    connect(session, &DeviceSession::emergencyStopRequested, this, [this] {
        if (m_busy)
            stopAll();
    });
}

const RolloutDevice *ProfileRollout::device(int id) const
{
    for (const RolloutDevice &d : m_devices) {
        if (d.id == id)
            return &d;
    }
    return nullptr;
}

void ProfileRollout::compare(const QList<int> &ids, const QHash<int, QString> &names)
{
    if (m_busy)
        return;
    m_devices.clear();
    for (int id : ids) {
        RolloutDevice d;
        d.id = id;
        d.name = names.value(id);
        m_devices.append(d);
    }
    m_index = 0;
    m_busy = true;
    m_compared = false;
    m_applied = false;
    m_stopped = false;
    compareNext();
}

void ProfileRollout::compareNext()
{
    if (m_index >= m_devices.size() || !m_session) {
        m_busy = false;
        m_compared = true;
        Q_EMIT compared();
        return;
    }
    const int id = m_devices.at(m_index).id;
    const quint64 generation = m_generation;
    QPointer<ProfileRollout> self(this); // the dialog holding it may be gone by the answer
    m_session->line()->readDevice(
        id, Profile::profileParameters(m_session->map(), true),
        [this, self, generation](const ReadOutcome &r) {
            if (!self || generation != m_generation)
                return;
            RolloutDevice &d = m_devices[m_index];
            d.before = r.values;
            if (!r.ok) {
                end(d, RolloutDevice::State::Failed,
                    tr("could not be read: %1").arg(r.errors.join(QLatin1String("; "))));
            } else {
                d.state = RolloutDevice::State::Compared;
                for (const ProfileDifference &row : ProfileDiff::differences(
                         ProfileDiff::compare(m_session->map(), m_profile, r.values))) {
                    if (row.linkSetting)
                        continue; // one id or baud for several devices: never from here
                    d.differences << row;
                    d.chosen << row.parameter->key;
                }
            }
            ++m_index;
            compareNext();
        });
}

void ProfileRollout::choose(int id, const QStringList &keys)
{
    for (RolloutDevice &d : m_devices) {
        if (d.id != id)
            continue;
        d.chosen.clear();
        for (const ProfileDifference &row : std::as_const(d.differences)) {
            if (keys.contains(row.parameter->key))
                d.chosen << row.parameter->key;
        }
    }
}

int ProfileRollout::chosenValues() const
{
    int n = 0;
    for (const RolloutDevice &d : m_devices) {
        if (d.state == RolloutDevice::State::Compared)
            n += int(d.chosen.size());
    }
    return n;
}

int ProfileRollout::chosenDevices() const
{
    int n = 0;
    for (const RolloutDevice &d : m_devices)
        n += d.state == RolloutDevice::State::Compared && !d.chosen.isEmpty() ? 1 : 0;
    return n;
}

void ProfileRollout::apply()
{
    if (m_busy || !m_compared || m_applied)
        return;
    m_busy = true;
    m_index = 0;
    applyNext();
}

void ProfileRollout::applyNext()
{
    while (m_index < m_devices.size() &&
           m_devices.at(m_index).state != RolloutDevice::State::Compared)
        ++m_index; // failed when read: stays failed
    if (m_index >= m_devices.size() || !m_session || m_stopped) {
        m_busy = false;
        m_applied = true;
        Q_EMIT finished(allOk());
        return;
    }
    RolloutDevice &d = m_devices[m_index];
    auto next = [this] {
        ++m_index;
        // After the stack of this device has unwound; an E-STOP in between is seen first.
        QTimer::singleShot(0, this, &ProfileRollout::applyNext);
    };
    if (d.chosen.isEmpty()) {
        end(d, RolloutDevice::State::Skipped,
            d.differences.isEmpty() ? tr("it already holds the profile's values")
                                    : tr("no value was chosen for it"));
        next();
        return;
    }
    QStringList errors;
    const QList<ParameterWrite> writes =
        ProfileDiff::writesFor(m_session->map(), m_profile, d.chosen, false, &errors);
    if (!errors.isEmpty()) {
        end(d, RolloutDevice::State::Failed, errors.join(QLatin1String("; ")));
        next();
        return;
    }
    const BackupStore::Saved saved =
        BackupStore(m_backupDir)
            .save(m_session->map(), d.before, BackupStore::Operation::Apply,
                  m_session->line()->describeDevice(d.id));
    if (!saved.ok()) {
        end(d, RolloutDevice::State::Failed,
            tr("no backup of its settings could be saved (%1): nothing was written")
                .arg(saved.error));
        next();
        return;
    }
    d.backup = saved.path;
    const quint64 generation = m_generation;
    QPointer<ProfileRollout> self(this);
    m_session->line()->writeDevice(
        d.id, writes, [this, self, generation, writes, next](const WriteOutcome &w) {
            if (!self || generation != m_generation)
                return;
            RolloutDevice &device = m_devices[m_index];
            QStringList problems = w.errors;
            for (const ParameterWrite &pw : writes) {
                const QString &key = pw.parameter->key;
                const bool mismatch =
                    std::any_of(w.mismatches.cbegin(), w.mismatches.cend(),
                                [&](const WriteMismatch &m) { return m.key == key; });
                if (w.written.contains(key) && !mismatch)
                    device.verified << key;
                else if (mismatch)
                    problems << tr("%1 reads back other than written").arg(key);
            }
            if (!w.notWritten.isEmpty())
                problems << tr("not written: %1").arg(w.notWritten.join(QLatin1String(", ")));
            if (w.ok && device.verified.size() == writes.size())
                end(device, RolloutDevice::State::Written, QString());
            else
                end(device, RolloutDevice::State::Failed,
                    problems.isEmpty() ? tr("not every value could be verified")
                                       : problems.join(QLatin1String("; ")));
            next();
        });
}

void ProfileRollout::end(RolloutDevice &d, RolloutDevice::State state, const QString &reason)
{
    d.state = state;
    d.reason = reason;
    Q_EMIT deviceFinished(d.id);
}

void ProfileRollout::stopAll()
{
    ++m_generation; // the answers still on their way belong to nothing now
    m_stopped = true;
    m_busy = false;
    const bool applying = m_compared;
    for (qsizetype i = m_index; i < m_devices.size(); ++i) {
        RolloutDevice &d = m_devices[i];
        if (d.state != RolloutDevice::State::Pending && d.state != RolloutDevice::State::Compared)
            continue;
        if (applying && i == m_index && d.state == RolloutDevice::State::Compared &&
            !d.chosen.isEmpty())
            end(d, RolloutDevice::State::Failed,
                tr("stopped by the E-STOP while writing: what it holds now was not verified"));
        else
            end(d, RolloutDevice::State::Skipped, tr("not done: E-STOP"));
    }
    if (applying) {
        m_applied = true;
        Q_EMIT finished(false);
    } else {
        m_compared = true;
        Q_EMIT compared();
    }
}

bool ProfileRollout::allOk() const
{
    return !m_stopped &&
           std::none_of(m_devices.cbegin(), m_devices.cend(), [](const RolloutDevice &d) {
               return d.state == RolloutDevice::State::Failed;
           });
}

QString ProfileRollout::describe(const RolloutDevice &d)
{
    const QString who =
        d.name.isEmpty() ? tr("id %1").arg(d.id) : tr("id %1 (%2)").arg(d.id).arg(d.name);
    switch (d.state) {
    case RolloutDevice::State::Pending:
        return tr("%1: waiting").arg(who);
    case RolloutDevice::State::Compared:
        return tr("%1: %n value(s) differ", nullptr, int(d.differences.size())).arg(who);
    case RolloutDevice::State::Written:
        return tr("%1: written and verified, %n value(s)", nullptr, int(d.verified.size()))
            .arg(who);
    case RolloutDevice::State::Skipped:
        return tr("%1: skipped, %2").arg(who, d.reason);
    case RolloutDevice::State::Failed:
        return d.verified.isEmpty()
                   ? tr("%1: FAILED, %2").arg(who, d.reason)
                   : tr("%1: FAILED, %2 (%n value(s) verified)", nullptr, int(d.verified.size()))
                         .arg(who, d.reason);
    }
    return who;
}

} // namespace stepcom
