#include "profile/profileapplyresult.h"

namespace stepcom {

using State = AppliedKey::State;

QStringList ProfileApplyResult::keysIn(AppliedKey::State state) const
{
    QStringList out;
    for (const AppliedKey &k : keys) {
        if (k.state == state)
            out << k.key;
    }
    return out;
}

const AppliedKey *ProfileApplyResult::key(const QString &key) const
{
    for (const AppliedKey &k : keys) {
        if (k.key == key)
            return &k;
    }
    return nullptr;
}

bool ProfileApplyResult::ok() const
{
    return end == End::Done &&
           std::all_of(keys.cbegin(), keys.cend(),
                       [](const AppliedKey &k) {
                           return k.state == State::Verified || k.state == State::Unchanged;
                       }) &&
           (!flashAsked || savedToFlash == true);
}

QStringList ProfileApplyResult::problems() const
{
    QStringList out;
    for (const AppliedKey &k : keys) {
        if (k.state != State::Verified && k.state != State::Unchanged)
            out << describe(k);
    }
    return out;
}

QString ProfileApplyResult::describe(const AppliedKey &k, const QString &name)
{
    const QString who = name.isEmpty() ? k.key : name;
    const auto value = [&k](qint64 raw) {
        return k.parameter ? k.parameter->displayRaw(raw) : QString::number(raw);
    };
    switch (k.state) {
    case State::Unchanged:
        return tr("%1: already %2").arg(who, value(k.wanted));
    case State::Verified:
        return tr("%1: %2 (written, verified)").arg(who, value(k.wanted));
    case State::Written:
        return k.readBack ? tr("%1: wrote %2, the controller holds %3")
                                .arg(who, value(k.wanted), value(*k.readBack))
                          : tr("%1: wrote %2, could not read it back").arg(who, value(k.wanted));
    case State::Refused:
        return tr("%1: %2 refused: %3").arg(who, value(k.wanted), k.reason);
    case State::NotWritten:
        return tr("%1: not written (%2)").arg(who, k.reason);
    case State::NotKnown:
        return tr("%1: not known whether %2 was written (%3)").arg(who, value(k.wanted), k.reason);
    case State::Lost:
        return tr("%1: wrote %2, then the controller held %3 again (%4)")
            .arg(who, value(k.wanted), k.readBack ? value(*k.readBack) : QStringLiteral("?"),
                 k.reason);
    }
    return who;
}

} // namespace stepcom
