#include "profile/profilerollout.h"

#include "session/devicesession.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"

#include <QTimer>

namespace stepcom {

ProfileRollout::ProfileRollout(DeviceSession *session, const Profile &profile, QObject *parent)
    : QObject(parent)
    , m_session(session)
    , m_profile(profile)
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
    qDeleteAll(m_applies);
    m_applies.clear();
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

ProfileApply *ProfileRollout::applyOf(int id)
{
    ProfileApply *&apply = m_applies[id];
    if (!apply) {
        // device.id and device.baud are never applied here (the default): one id for several
        // devices would make them collide.
        apply = new ProfileApply(m_session, m_profile, id, this);
        connect(apply, &ProfileApply::finished, this, &ProfileRollout::applied);
    }
    return apply;
}

void ProfileRollout::compareNext()
{
    if (m_index >= m_devices.size() || !m_session) {
        m_busy = false;
        m_compared = true;
        Q_EMIT compared();
        return;
    }
    ProfileApply *apply = applyOf(m_devices.at(m_index).id);
    const quint64 generation = m_generation;
    auto *once = new QObject(this);
    connect(apply, &ProfileApply::compared, once, [this, apply, once, generation](bool ok) {
        once->deleteLater();
        if (generation != m_generation)
            return;
        RolloutDevice &d = m_devices[m_index];
        d.before = apply->before();
        if (!ok) {
            end(d, RolloutDevice::State::Failed,
                tr("could not be read: %1").arg(apply->readErrors().join(QLatin1String("; "))));
        } else {
            d.state = RolloutDevice::State::Compared;
            d.differences = apply->differences();
            d.chosen = apply->differingKeys();
        }
        ++m_index;
        compareNext();
    });
    apply->compare();
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
    if (d.chosen.isEmpty()) {
        end(d, RolloutDevice::State::Skipped,
            d.differences.isEmpty() ? tr("it already holds the profile's values")
                                    : tr("no value was chosen for it"));
        ++m_index;
        QTimer::singleShot(0, this, &ProfileRollout::applyNext);
        return;
    }
    applyOf(d.id)->apply(d.chosen);
}

void ProfileRollout::applied(const ProfileApplyResult &result)
{
    if (!m_busy || m_index >= m_devices.size() || m_devices.at(m_index).id != result.id)
        return;
    RolloutDevice &d = m_devices[m_index];
    d.result = result;
    d.verified = result.keysIn(AppliedKey::State::Verified);
    if (result.ok()) {
        end(d, RolloutDevice::State::Written, QString());
    } else {
        const QStringList problems = result.problems();
        QStringList why;
        if (!result.error.isEmpty())
            why << result.error;
        if (result.error.isEmpty() || result.end != ProfileApplyResult::End::Failed)
            why += problems;
        end(d, RolloutDevice::State::Failed,
            why.isEmpty() ? tr("not every value could be verified")
                          : why.join(QLatin1String("; ")));
    }
    if (m_stopped) { // the E-STOP that ended this apply ends the rollout too
        m_busy = false;
        m_applied = true;
        Q_EMIT finished(false);
        return;
    }
    ++m_index;
    // After the stack of this device has unwound; an E-STOP in between is seen first.
    QTimer::singleShot(0, this, &ProfileRollout::applyNext);
}

void ProfileRollout::end(RolloutDevice &d, RolloutDevice::State state, const QString &reason)
{
    d.state = state;
    d.reason = reason;
    Q_EMIT deviceFinished(d.id);
}

void ProfileRollout::stopAll()
{
    ++m_generation; // the comparisons still on their way belong to nothing now
    m_stopped = true;
    const bool applying = m_compared;
    // Applying: the device being written ends through its own ProfileApply (it hears the
    // E-STOP too, right after this), which then ends the rollout.
    ProfileApply *current = applying && m_index < m_devices.size()
                                ? m_applies.value(m_devices.at(m_index).id)
                                : nullptr;
    const bool waitForCurrent = current && current->isBusy();
    for (qsizetype i = m_index + (waitForCurrent ? 1 : 0); i < m_devices.size(); ++i) {
        RolloutDevice &d = m_devices[i];
        if (d.state == RolloutDevice::State::Pending || d.state == RolloutDevice::State::Compared)
            end(d, RolloutDevice::State::Skipped, tr("not done: E-STOP"));
    }
    if (waitForCurrent)
        return;
    m_busy = false;
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
