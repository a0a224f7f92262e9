#include "profile/profileapply.h"

#include "device/writereview.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"

namespace stepcom {

using State = AppliedKey::State;

ProfileApply::ProfileApply(DeviceSession *session, const Profile &profile, int id, QObject *parent)
    : QObject(parent)
    , m_session(session)
    , m_profile(profile)
    , m_id(id > 0 ? id : session->line()->deviceInView())
{
    connect(session, &DeviceSession::emergencyStopRequested, this, [this] {
        if (!m_busy)
            return;
        m_stopped = true;
        for (AppliedKey &k : m_result.keys) {
            if (k.state != State::NotWritten || !k.reason.isEmpty())
                continue;
            k.reason = tr("not done: E-STOP");
        }
        end(ProfileApplyResult::End::Stopped,
            tr("stopped by the E-STOP: nothing more was sent for this profile"));
    });
    connect(session->connection(), &SessionConnection::disconnected, this,
            [this](const QString &reason) {
                if (m_busy)
                    m_lost = reason.isEmpty()
                                 ? tr("the link was closed")
                                 : tr("the link went away during the apply (%1)").arg(reason);
            });
    connect(session, &DeviceSession::controllerRestarted, this,
            [this](int device) { m_restarted = m_restarted || (m_busy && device == m_id); });
    connect(session, &DeviceSession::controllerMayHaveRestarted, this,
            [this](int device) { m_restarted = m_restarted || (m_busy && device == m_id); });
}

bool ProfileApply::announce(Step step)
{
    const quint64 generation = m_generation;
    Q_EMIT progress(step);
    return generation == m_generation; // not ended by whoever heard it (an E-STOP)
}

bool ProfileApply::isInView() const
{
    return m_session && m_id == m_session->line()->deviceInView();
}

void ProfileApply::read(std::function<void()> next)
{
    if (!announce(Step::Reading))
        return;
    const quint64 generation = m_generation;
    QPointer<ProfileApply> self(this);
    m_session->line()->readDevice(
        m_id, Profile::profileParameters(m_session->map(), true),
        [this, self, generation, next](const ReadOutcome &r) {
            if (!self || generation != m_generation || !m_session)
                return;
            m_before = r.values;
            // The device in view shows what was just read, and its backup need not read again.
            if (isInView())
                m_session->parameters()->store()->setDeviceValues(r.values);
            m_readErrors = r.errors;
            m_unsupported = r.unsupported;
            m_differences.clear();
            m_compared = r.ok;
            if (r.ok) {
                for (const ProfileDifference &row : ProfileDiff::differences(
                         ProfileDiff::compare(m_session->map(), m_profile, r.values))) {
                    if (!row.linkSetting || (m_includeLink && isInView()))
                        m_differences << row;
                }
            }
            next();
        });
}

void ProfileApply::compare()
{
    if (m_busy || !m_session)
        return;
    read([this] { Q_EMIT compared(m_compared); });
}

QList<ProfileDifference> ProfileApply::leftOutLinkSettings() const
{
    QList<ProfileDifference> out;
    if (!m_session || (m_includeLink && isInView()))
        return out;
    for (const ProfileDifference &row :
         ProfileDiff::differences(ProfileDiff::compare(m_session->map(), m_profile, m_before))) {
        if (row.linkSetting)
            out << row;
    }
    return out;
}

QStringList ProfileApply::differingKeys() const
{
    QStringList keys;
    for (const ProfileDifference &row : m_differences)
        keys << row.parameter->key;
    return keys;
}

QStringList ProfileApply::questions(const QStringList &keys) const
{
    if (!m_session)
        return {};
    const QList<ParameterWrite> writes =
        ProfileDiff::writesFor(m_session->map(), m_profile, keys, m_includeLink, nullptr);
    return WriteReview::problems(
        m_session->map(),
        [this](const QString &key) {
            const auto it = m_before.constFind(key);
            return it == m_before.cend() ? std::nullopt : std::optional<qint64>(*it);
        },
        writes);
}

void ProfileApply::apply(const QStringList &keys)
{
    if (m_busy || !m_session)
        return;
    m_busy = true;
    m_stopped = false;
    m_restarted = false;
    m_lost.clear();
    m_keys = keys;
    m_result = ProfileApplyResult();
    m_result.id = m_id;
    m_result.flashAsked = m_saveToFlash;
    if (m_compared) {
        plan();
        return;
    }
    read([this] {
        if (m_compared) {
            plan();
            return;
        }
        // Nothing known of what it holds: nothing is written.
        for (const QString &key : std::as_const(m_keys)) {
            AppliedKey k;
            k.key = key;
            k.parameter = m_session->map().find(key);
            k.wanted = m_profile.values.value(key);
            k.reason = tr("the controller could not be read");
            m_result.keys << k;
        }
        // A closing link fails what is queued before it says it closed: hear that first.
        const quint64 generation = m_generation;
        QMetaObject::invokeMethod(
            this,
            [this, generation] {
                if (generation != m_generation)
                    return;
                if (!m_lost.isEmpty() || !m_session || !m_session->connection()->isConnected())
                    end(ProfileApplyResult::End::LinkLost,
                        m_lost.isEmpty() ? tr("the link was lost") : m_lost);
                else
                    end(ProfileApplyResult::End::Failed,
                        tr("the controller could not be read: %1")
                            .arg(m_readErrors.join(QLatin1String("; "))));
            },
            Qt::QueuedConnection);
    });
}

void ProfileApply::plan()
{
    const RegisterMap &map = m_session->map();
    for (const Parameter *p : Profile::profileParameters(map, true)) {
        if (!m_keys.contains(p->key))
            continue;
        AppliedKey k;
        k.key = p->key;
        k.parameter = p;
        const auto wanted = m_profile.values.constFind(p->key);
        if (const auto it = m_before.constFind(p->key); it != m_before.cend())
            k.before = *it;
        if (wanted == m_profile.values.cend()) {
            k.reason = tr("the profile holds no value");
        } else if (m_unsupported.contains(p->key)) {
            k.wanted = *wanted;
            k.reason = tr("this controller does not have it");
        } else if (Profile::isLinkSetting(p->key) && !(m_includeLink && isInView())) {
            k.wanted = *wanted;
            k.reason = tr("the device id and baud are applied only to the device in view, when "
                          "asked for");
        } else {
            k.wanted = *wanted;
            if (k.before == k.wanted) {
                k.state = State::Unchanged;
            } else if (!p->writable()) {
                k.state = State::Refused;
                k.refusal = AppliedKey::Refusal::OutOfRange;
                k.reason = tr("it is read-only");
            } else if (const QString why = p->checkRaw(k.wanted); !why.isEmpty()) {
                k.state = State::Refused;
                k.refusal = AppliedKey::Refusal::OutOfRange;
                k.reason = why;
            }
        }
        m_result.keys << k;
    }
    for (const QString &key : std::as_const(m_keys)) {
        if (!map.find(key)) {
            AppliedKey k;
            k.key = key;
            k.reason = tr("not a setting of this register map");
            m_result.keys << k;
        }
    }
    if (m_refuseQuestioned) {
        // Each key judged on what the controller holds once the others are written too.
        const QList<ParameterWrite> writes = pendingWrites();
        for (const ParameterWrite &w : writes) {
            const QStringList asked = WriteReview::problems(
                map,
                [this, &writes, &w](const QString &key) -> std::optional<qint64> {
                    for (const ParameterWrite &o : writes) {
                        if (o.parameter->key == key && o.parameter != w.parameter)
                            return o.raw;
                    }
                    const auto it = m_before.constFind(key);
                    return it == m_before.cend() ? std::nullopt : std::optional<qint64>(*it);
                },
                {w});
            if (asked.isEmpty())
                continue;
            AppliedKey *k = keyOf(w.parameter->key);
            k->state = State::Refused;
            k->refusal = AppliedKey::Refusal::Questioned;
            k->reason = asked.join(QLatin1Char(' '));
        }
    }
    if (pendingWrites().isEmpty()) {
        if (m_saveToFlash)
            saveToFlash();
        else
            end(ProfileApplyResult::End::Done);
        return;
    }
    backUp();
}

AppliedKey *ProfileApply::keyOf(const QString &key)
{
    for (AppliedKey &k : m_result.keys) {
        if (k.key == key)
            return &k;
    }
    return nullptr;
}

QList<ParameterWrite> ProfileApply::pendingWrites() const
{
    QList<ParameterWrite> writes;
    for (const AppliedKey &k : m_result.keys) {
        if (k.state == State::NotWritten && k.reason.isEmpty() && k.parameter)
            writes.append({k.parameter, k.wanted});
    }
    return writes;
}

bool ProfileApply::mayGoOn()
{
    if (!m_session) {
        end(ProfileApplyResult::End::LinkLost, tr("the session ended"));
        return false;
    }
    if (!m_lost.isEmpty()) {
        for (AppliedKey &k : m_result.keys) {
            if (k.state == State::NotWritten && k.reason.isEmpty())
                k.reason = tr("the link was lost before it was sent");
        }
        end(ProfileApplyResult::End::LinkLost, m_lost);
        return false;
    }
    return true;
}

void ProfileApply::backUp()
{
    if (!mayGoOn())
        return;
    if (!announce(Step::BackingUp))
        return;
    const quint64 generation = m_generation;
    QPointer<ProfileApply> self(this);
    m_session->risks()->guard(DeviceSession::Risk::Apply, m_id,
                              [this, self, generation](const QString &refusal) {
                                  if (!self || generation != m_generation)
                                      return;
                                  if (refusal.isEmpty()) {
                                      write();
                                      return;
                                  }
                                  if (!mayGoOn())
                                      return;
                                  for (AppliedKey &k : m_result.keys) {
                                      if (k.state == State::NotWritten && k.reason.isEmpty())
                                          k.reason = refusal;
                                  }
                                  end(ProfileApplyResult::End::Failed, refusal);
                              });
}

void ProfileApply::write()
{
    if (!mayGoOn())
        return;
    if (!announce(Step::Writing))
        return;
    const quint64 generation = m_generation;
    QPointer<ProfileApply> self(this);
    const QList<ParameterWrite> writes = pendingWrites();
    // An E-STOP from here on ends the apply at once: what the controller took is not known.
    for (AppliedKey &k : m_result.keys) {
        if (k.state == State::NotWritten && k.reason.isEmpty()) {
            k.state = State::NotKnown;
            k.reason = tr("stopped by the E-STOP while writing");
        }
    }
    m_session->line()->writeDevice(m_id, writes, [this, self, generation](const WriteOutcome &w) {
        if (self && generation == m_generation)
            written(w);
    });
}

void ProfileApply::written(const WriteOutcome &w)
{
    m_result.writeErrors = w.errors;
    for (AppliedKey &k : m_result.keys) {
        if (k.state != State::NotKnown)
            continue;
        k.reason.clear();
        if (w.verified(k.key)) {
            k.state = State::Verified;
        } else if (const WriteMismatch *m = w.mismatch(k.key)) {
            k.state = State::Written;
            k.readBack = m->got;
        } else if (w.refused.contains(k.key)) {
            k.state = State::Refused;
            k.refusal = AppliedKey::Refusal::Controller;
            const auto said = std::find_if(w.errors.cbegin(), w.errors.cend(),
                                           [&k](const QString &e) { return e.contains(k.key); });
            k.reason = said != w.errors.cend() ? *said : tr("refused by the controller");
        } else if (w.notWritten.contains(k.key)) {
            k.state = State::NotWritten;
            k.reason = tr("not sent: an earlier write failed");
        } else {
            k.reason = m_lost.isEmpty() ? tr("sent without a good answer") : m_lost;
        }
    }
    // A new device id, verified: the controller (and the link) are there now.
    if (const AppliedKey *k = keyOf(QStringLiteral("device.id")); k && k->state == State::Verified)
        m_id = int(k->wanted);
    if (!m_lost.isEmpty()) {
        end(ProfileApplyResult::End::LinkLost, m_lost);
        return;
    }
    if (!w.ok || m_restarted) {
        readBack(); // what it holds now, where the write left it uncertain
        return;
    }
    if (m_saveToFlash)
        saveToFlash();
    else
        end(ProfileApplyResult::End::Done);
}

void ProfileApply::readBack()
{
    if (!mayGoOn())
        return;
    QList<const Parameter *> params;
    for (const AppliedKey &k : std::as_const(m_result.keys)) {
        if (k.parameter &&
            (k.state == State::Verified || k.state == State::Written || k.state == State::NotKnown))
            params << k.parameter;
    }
    const auto finish = [this] {
        if (m_restarted)
            end(ProfileApplyResult::End::Restarted,
                tr("the controller restarted during the apply: what it held then was lost "
                   "unless saved to flash"));
        else
            end(ProfileApplyResult::End::Done);
    };
    if (params.isEmpty()) {
        finish();
        return;
    }
    if (!announce(Step::ReadingBack))
        return;
    const quint64 generation = m_generation;
    QPointer<ProfileApply> self(this);
    m_session->line()->readDevice(
        m_id, params, [this, self, generation, finish](const ReadOutcome &r) {
            if (!self || generation != m_generation)
                return;
            if (!r.ok) {
                // A closing link fails what is queued before it says it closed: hear that first.
                QMetaObject::invokeMethod(
                    this,
                    [this, generation, finish] {
                        if (generation != m_generation)
                            return;
                        if (m_lost.isEmpty() && m_session && m_session->connection()->isConnected())
                            finish();
                        else
                            end(ProfileApplyResult::End::LinkLost,
                                m_lost.isEmpty() ? tr("the link was lost") : m_lost);
                    },
                    Qt::QueuedConnection);
            }
            for (AppliedKey &k : m_result.keys) {
                const auto it = r.values.constFind(k.key);
                if (it == r.values.cend())
                    continue; // not read: what was known of it stands
                if (*it == k.wanted) {
                    if (k.state != State::Verified) {
                        k.state = State::Verified;
                        k.reason.clear();
                    }
                } else if (k.state == State::Verified) {
                    // Verified before, its old value now: only a restart undoes a write.
                    k.state = State::Lost;
                    k.readBack = *it;
                    k.reason = tr("the controller restarted");
                    m_restarted = true;
                } else if (k.state == State::Written) {
                    k.readBack = *it;
                } else if (k.state == State::NotKnown) {
                    k.state = State::NotWritten;
                    k.reason =
                        tr("the controller holds %1")
                            .arg(k.parameter ? k.parameter->displayRaw(*it) : QString::number(*it));
                }
            }
            if (r.ok)
                finish();
        });
}

void ProfileApply::saveToFlash()
{
    if (!mayGoOn())
        return;
    const Parameter *coil = m_session->map().find(QStringLiteral("save_to_flash"));
    if (!coil || !isInView()) {
        m_result.savedToFlash = false;
        m_result.flashError = !coil ? tr("this map has no save_to_flash command")
                                    : tr("saved to flash only on the device in view");
        end(ProfileApplyResult::End::Done);
        return;
    }
    if (!announce(Step::SavingToFlash))
        return;
    const quint64 generation = m_generation;
    QPointer<ProfileApply> self(this);
    m_session->risks()->guard(DeviceSession::Risk::SaveToFlash, m_id,
                              [this, self, generation, coil](const QString &refusal) {
                                  if (!self || generation != m_generation || !mayGoOn())
                                      return;
                                  if (!refusal.isEmpty()) {
                                      m_result.savedToFlash = false;
                                      m_result.flashError = refusal;
                                      end(ProfileApplyResult::End::Done);
                                      return;
                                  }
                                  m_session->command(
                                      *coil, [this, self, generation](const Result &r) {
                                          if (!self || generation != m_generation)
                                              return;
                                          if (r.ok) {
                                              m_result.savedToFlash = true;
                                          } else {
                                              m_result.flashError = r.errorText;
                                              if (r.exceptionCode != 0) // answered: not saved
                                                  m_result.savedToFlash = false;
                                          }
                                          // Unanswered, or a restart said: is what was verified
                                          // still there?
                                          if (!r.ok || m_restarted)
                                              readBack();
                                          else
                                              end(ProfileApplyResult::End::Done);
                                      });
                              });
}

void ProfileApply::end(ProfileApplyResult::End how, const QString &error)
{
    if (!m_busy)
        return;
    ++m_generation;
    m_busy = false;
    m_compared = false;            // the next apply reads again
    if (m_result.keys.isEmpty()) { // ended before the plan: none of them was sent
        for (const QString &key : std::as_const(m_keys)) {
            AppliedKey k;
            k.key = key;
            k.parameter = m_session ? m_session->map().find(key) : nullptr;
            k.wanted = m_profile.values.value(key);
            k.reason = error;
            m_result.keys << k;
        }
    }
    m_result.end = how;
    m_result.error = error;
    if (how == ProfileApplyResult::End::Restarted && m_result.savedToFlash == true)
        m_result.savedToFlash.reset(); // what it saved is not known
    Q_EMIT finished(m_result);
}

} // namespace stepcom
