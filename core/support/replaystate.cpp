#include "support/replaystate.h"

#include "map/registermap.h"

namespace stepcom {

QString ReplayEvent::kindName(Kind kind)
{
    switch (kind) {
    case Kind::Write:
        return QStringLiteral("write");
    case Kind::Command:
        return QStringLiteral("command");
    case Kind::EmergencyStop:
        return QStringLiteral("estop");
    case Kind::Exception:
        return QStringLiteral("exception");
    case Kind::Timeout:
        return QStringLiteral("timeout");
    case Kind::LateAnswer:
        return QStringLiteral("late-answer");
    case Kind::LinkUp:
        return QStringLiteral("link-up");
    case Kind::LinkDown:
        return QStringLiteral("link-down");
    case Kind::Restart:
        return QStringLiteral("restart");
    case Kind::PossibleRestart:
        return QStringLiteral("possible-restart");
    case Kind::User:
        break;
    }
    return QStringLiteral("user");
}

namespace {

// Every holding parameter whose words are all in `words`, decoded.
QHash<QString, qint64> decodeAll(const RegisterMap &map, const QMap<quint16, quint16> &words)
{
    QHash<QString, qint64> out;
    for (const Parameter *p : map.holdings()) {
        quint16 w[2] = {0, 0};
        bool known = true;
        for (int i = 0; i < p->words && known; ++i) {
            const auto it = words.constFind(quint16(p->address + i));
            known = it != words.cend();
            if (known)
                w[i] = it.value();
        }
        if (known)
            out.insert(p->key, p->decode(w));
    }
    return out;
}

} // namespace

QHash<QString, qint64> ReplayDevice::values(const RegisterMap &map) const
{
    return decodeAll(map, words);
}

QHash<QString, qint64> ReplayDevice::writtenValues(const RegisterMap &map) const
{
    return decodeAll(map, written);
}

QJsonObject ReplayState::toJson(const RegisterMap &map) const
{
    QJsonObject devicesJson;
    for (auto it = devices.cbegin(); it != devices.cend(); ++it) {
        const ReplayDevice &d = it.value();
        const auto toJson = [&map](const QHash<QString, qint64> &raw) {
            QJsonObject o;
            for (auto v = raw.cbegin(); v != raw.cend(); ++v)
                // raw / scale, correctly rounded: the double `stepcomctl read --json` prints
                o.insert(v.key(), map.find(v.key())->toEngineering(v.value()));
            return o;
        };
        QJsonObject o{{QStringLiteral("answering"), d.answering},
                      {QStringLiteral("values"), toJson(d.values(map))},
                      {QStringLiteral("written"), toJson(d.writtenValues(map))}};
        if (!d.lastError.isEmpty()) {
            o.insert(QStringLiteral("last_error"), d.lastError);
            o.insert(QStringLiteral("last_error_s"), double(d.lastErrorMs) / 1000.0);
        }
        if (!d.lastCommand.isEmpty())
            o.insert(QStringLiteral("last_command"), d.lastCommand);
        // What the window's device list says of it: requests, how many failed, a restart.
        o.insert(QStringLiteral("requests"), d.requests);
        o.insert(QStringLiteral("errors"), d.errors);
        if (d.restartMs >= 0) {
            o.insert(QStringLiteral("restart_s"), double(d.restartMs) / 1000.0);
            o.insert(QStringLiteral("restart"), d.restartText);
        }
        devicesJson.insert(QString::number(it.key()), o);
    }
    return {{QStringLiteral("at_s"), double(ms) / 1000.0},
            {QStringLiteral("link_up"), linkUp},
            {QStringLiteral("devices"), devicesJson}};
}

QStringList ReplayState::diff(const ReplayState &before, const RegisterMap &map) const
{
    QStringList lines;
    QList<int> ids = devices.keys();
    for (const int id : before.devices.keys()) {
        if (!ids.contains(id))
            ids << id;
    }
    std::sort(ids.begin(), ids.end());
    const QString unknown = tr("(unknown)");
    for (const int id : std::as_const(ids)) {
        const QHash<QString, qint64> a = before.devices.value(id).values(map);
        const QHash<QString, qint64> b = devices.value(id).values(map);
        for (const Parameter *p : map.holdings()) {
            const bool inA = a.contains(p->key);
            const bool inB = b.contains(p->key);
            if (inA == inB && (!inA || a.value(p->key) == b.value(p->key)))
                continue;
            lines << QStringLiteral("id %1  %2  %3 → %4")
                         .arg(id)
                         .arg(p->key, inA ? p->displayRaw(a.value(p->key)) : unknown,
                              inB ? p->displayRaw(b.value(p->key)) : unknown);
        }
    }
    return lines;
}

} // namespace stepcom
