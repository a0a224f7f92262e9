#include "support/replaydecoder.h"

#include "bus/bigendian.h"
#include "bus/request.h" // exceptionText
#include "bus/rtuframe.h"
#include "map/registermap.h"

namespace stepcom {

namespace {

constexpr int kOwedKept = 8;

using bigendian::wordAt;

int functionOf(const QByteArray &pdu)
{
    return pdu.isEmpty() ? 0 : quint8(pdu.at(0)) & 0x7F;
}

// The words a write request sets, by address.
QMap<quint16, quint16> writtenWords(const QByteArray &pdu)
{
    QMap<quint16, quint16> out;
    const int fc = functionOf(pdu);
    if (fc == 0x06 && pdu.size() >= 5)
        out.insert(wordAt(pdu, 1), wordAt(pdu, 3));
    if (fc == 0x10 && pdu.size() >= 6) {
        const quint16 address = wordAt(pdu, 1);
        const int count = wordAt(pdu, 3);
        for (int i = 0; i < count && 6 + 2 * i + 1 < pdu.size(); ++i)
            out.insert(quint16(address + i), wordAt(pdu, 6 + 2 * i));
    }
    return out;
}

} // namespace

ReplayDecoder::ReplayDecoder(const RegisterMap *map)
    : m_map(map)
{}

bool ReplayDecoder::split(const QByteArray &raw, Framing framing, int *unit, QByteArray *pdu)
{
    const bool rtu = raw.size() >= 4 && RtuFrame::crcOk(raw);
    const bool tcp =
        raw.size() >= 8 && raw.at(2) == 0 && raw.at(3) == 0 && wordAt(raw, 4) == raw.size() - 6;
    if (rtu && framing != Framing::Tcp) {
        *unit = quint8(raw.at(0));
        *pdu = raw.mid(1, raw.size() - 3);
        return true;
    }
    if (tcp && framing != Framing::Rtu) {
        *unit = quint8(raw.at(6));
        *pdu = raw.mid(7);
        return true;
    }
    return false;
}

void ReplayDecoder::feed(const LogLine &line, qint64 ms, qint64 lineNo, const Sink &sink)
{
    m_state.ms = ms;
    m_answeredUnit = 0;
    if (line.type == LogLine::Type::Frame)
        frame(line, ms, lineNo, sink);
    else if (line.type == LogLine::Type::Mark)
        mark(line, ms, lineNo, sink);
}

void ReplayDecoder::finish(qint64 ms, const Sink &sink)
{
    if (m_pending)
        timedOut(*std::exchange(m_pending, std::nullopt), ms, 0, sink);
}

void ReplayDecoder::emitEvent(const Sink &sink, qint64 ms, int device, ReplayEvent::Kind kind,
                              const QString &text, qint64 lineNo) const
{
    if (sink)
        sink(ReplayEvent{ms, device, kind, text, lineNo});
}

QString ReplayDecoder::describe(const QByteArray &pdu) const
{
    const int fc = functionOf(pdu);
    if (pdu.size() < 5)
        return QStringLiteral("FC%1").arg(fc, 2, 16, QLatin1Char('0'));
    const quint16 address = wordAt(pdu, 1);
    if (fc == 0x05) {
        const Parameter *p = m_map ? m_map->coilAt(address) : nullptr;
        return QStringLiteral("command %1")
            .arg(p ? p->key : QStringLiteral("coil %1").arg(address + 1));
    }
    const int count = fc == 0x06 ? 1 : wordAt(pdu, 3);
    QString where = QString::number(40001 + address);
    if (count > 1)
        where += QLatin1Char('-') + QString::number(40001 + address + count - 1);
    if (fc == 0x03)
        return QStringLiteral("read %1").arg(where);
    QStringList keys;
    for (int i = 0; m_map && i < count; ++i) {
        const Parameter *p = m_map->holdingAt(quint16(address + i));
        if (p && !keys.contains(p->key))
            keys << p->key;
    }
    return QStringLiteral("write %1").arg(keys.isEmpty() ? where : keys.join(QStringLiteral(", ")));
}

bool ReplayDecoder::fits(const Pending &p, int unit, const QByteArray &a)
{
    if (a.isEmpty() || p.pdu.isEmpty() || unit != p.unit)
        return false;
    const int fc = functionOf(p.pdu);
    if (functionOf(a) != fc)
        return false;
    if (quint8(a.at(0)) & 0x80)
        return true; // an exception to this function
    switch (fc) {
    case 0x03:
        return a.size() >= 2 && p.pdu.size() >= 5 && quint8(a.at(1)) == 2 * wordAt(p.pdu, 3) &&
               a.size() == 2 + quint8(a.at(1));
    case 0x05:
    case 0x06:
    case 0x10:
        return a.size() >= 5 && p.pdu.size() >= 5 && wordAt(a, 1) == wordAt(p.pdu, 1);
    default:
        return true;
    }
}

void ReplayDecoder::frame(const LogLine &line, qint64 ms, qint64 lineNo, const Sink &sink)
{
    int unit = 0;
    QByteArray pdu;
    if (!line.sent && m_framing != Framing::Tcp && !split(line.bytes, m_framing, &unit, &pdu)) {
        // Bytes that came together between two requests are logged as they came: answers
        // owed to earlier attempts, one after the other. Each whole frame counts.
        QByteArray rest = line.bytes;
        bool cut = false;
        while (true) {
            const int length = RtuFrame::answerLength(rest);
            if (length <= 0 || length >= rest.size() || !RtuFrame::crcOk(rest.left(length)))
                break;
            LogLine one = line;
            one.bytes = rest.left(length);
            rest.remove(0, length);
            frame(one, ms, lineNo, sink);
            cut = true;
        }
        if (cut) {
            LogLine last = line;
            last.bytes = rest;
            frame(last, ms, lineNo, sink);
        }
        return;
    }
    if (!split(line.bytes, m_framing, &unit, &pdu) || pdu.isEmpty())
        return; // a frame cut short or damaged on the wire: StepCom dropped it too
    if (line.sent) {
        if (m_pending)
            timedOut(*std::exchange(m_pending, std::nullopt), ms, lineNo, sink);
        if (unit != 0) // a broadcast has no answer
            m_pending = Pending{unit, pdu, lineNo};
        return;
    }
    if (m_pending && fits(*m_pending, unit, pdu)) {
        // A read coming back as it went out is the adapter's echo, not the answer.
        if (functionOf(pdu) == 0x03 && pdu == m_pending->pdu)
            return;
        answered(*std::exchange(m_pending, std::nullopt), pdu, ms, lineNo, sink);
        return;
    }
    for (qsizetype i = m_owed.size() - 1; i >= 0; --i) {
        if (fits(m_owed.at(i), unit, pdu)) {
            emitEvent(sink, ms, unit, ReplayEvent::Kind::LateAnswer,
                      tr("late answer (discarded): %1").arg(describe(m_owed.at(i).pdu)), lineNo);
            m_owed.remove(i);
            return;
        }
    }
}

void ReplayDecoder::timedOut(const Pending &p, qint64 ms, qint64 lineNo, const Sink &sink)
{
    ReplayDevice &d = m_state.devices[p.unit];
    d.answering = false;
    ++d.requests;
    ++d.errors;
    d.lastError = tr("no answer: %1").arg(describe(p.pdu));
    d.lastErrorMs = ms;
    const bool estop = m_map && functionOf(p.pdu) == 0x05 && p.pdu.size() >= 5 && [&] {
        const Parameter *c = m_map->coilAt(wordAt(p.pdu, 1));
        return c && c->command == CommandClass::Emergency;
    }();
    if (estop)
        emitEvent(sink, ms, p.unit, ReplayEvent::Kind::EmergencyStop,
                  tr("E-STOP sent, not acknowledged"), p.lineNo);
    emitEvent(sink, ms, p.unit, ReplayEvent::Kind::Timeout, d.lastError,
              lineNo ? lineNo : p.lineNo);
    m_owed.append(p);
    if (m_owed.size() > kOwedKept)
        m_owed.removeFirst();
}

void ReplayDecoder::answered(const Pending &p, const QByteArray &a, qint64 ms, qint64 lineNo,
                             const Sink &sink)
{
    // An answer came over the line: it is up (a log that begins in the middle of a
    // connection, a later part of a rotated one, has no line saying so).
    m_state.linkUp = true;
    ReplayDevice &d = m_state.devices[p.unit];
    d.answering = true;
    d.lastAnswerMs = ms;
    ++d.requests;
    m_answeredUnit = p.unit;
    if (quint8(a.at(0)) & 0x80) {
        ++d.errors;
        const int code = a.size() > 1 ? quint8(a.at(1)) : 0;
        d.lastError = tr("refused (%1): %2").arg(exceptionText(code), describe(p.pdu));
        d.lastErrorMs = ms;
        emitEvent(sink, ms, p.unit, ReplayEvent::Kind::Exception, d.lastError, lineNo);
        return;
    }
    const int fc = functionOf(p.pdu);
    if (fc == 0x03) {
        const quint16 address = wordAt(p.pdu, 1);
        for (int i = 0; 2 + 2 * i + 1 < a.size(); ++i) {
            d.words.insert(quint16(address + i), wordAt(a, 2 + 2 * i));
        }
        return;
    }
    if (fc == 0x05) {
        const Parameter *c = m_map ? m_map->coilAt(wordAt(p.pdu, 1)) : nullptr;
        const QString name = c ? c->key : QStringLiteral("coil %1").arg(wordAt(p.pdu, 1) + 1);
        d.lastCommand = name;
        const bool estop = c && c->command == CommandClass::Emergency;
        emitEvent(sink, ms, p.unit,
                  estop ? ReplayEvent::Kind::EmergencyStop : ReplayEvent::Kind::Command,
                  estop ? tr("E-STOP acknowledged") : name, lineNo);
        return;
    }
    if (fc != 0x06 && fc != 0x10)
        return;
    // The values before and after, per parameter the write touched.
    const QMap<quint16, quint16> words = writtenWords(p.pdu);
    const QHash<QString, qint64> before = m_map ? d.values(*m_map) : QHash<QString, qint64>();
    for (auto it = words.cbegin(); it != words.cend(); ++it) {
        d.words.insert(it.key(), it.value());
        d.written.insert(it.key(), it.value());
    }
    QStringList parts;
    if (m_map) {
        const QHash<QString, qint64> after = d.values(*m_map);
        for (auto it = words.cbegin(); it != words.cend(); ++it) {
            const Parameter *param = m_map->holdingAt(it.key());
            if (!param || param->address != it.key() || !after.contains(param->key))
                continue;
            const qint64 now = after.value(param->key);
            parts << (before.contains(param->key) && before.value(param->key) != now
                          ? QStringLiteral("%1 %2 → %3")
                                .arg(param->key, param->displayRaw(before.value(param->key)),
                                     param->displayRaw(now))
                          : QStringLiteral("%1 = %2").arg(param->key, param->displayRaw(now)));
        }
    }
    if (parts.isEmpty())
        parts << describe(p.pdu);
    emitEvent(sink, ms, p.unit, ReplayEvent::Kind::Write, parts.join(QStringLiteral(", ")), lineNo);
}

void ReplayDecoder::mark(const LogLine &line, qint64 ms, qint64 lineNo, const Sink &sink)
{
    const QByteArray &kind = line.kind;
    const bool up = kind == "linkup" ||
                    (!m_marked && kind == "event" && line.text.startsWith(u"connected to "));
    const bool down = kind == "linkdown" ||
                      (!m_marked && kind == "error" && line.text.startsWith(u"link lost: "));
    const bool connecting = kind == "event" && (line.text.startsWith(u"connecting to ") ||
                                                line.text.startsWith(u"disconnected: "));
    if (up || down || connecting) {
        // Whatever was on the wire is not answered over a new connection. A read cut short
        // says nothing; a write or a command may or may not have acted: that is worth a marker.
        if (m_pending && functionOf(m_pending->pdu) != 0x03)
            timedOut(*m_pending, ms, lineNo, sink);
        m_pending.reset();
        m_owed.clear();
    }
    if (up) {
        m_state.linkUp = true;
        emitEvent(sink, ms, 0, ReplayEvent::Kind::LinkUp, line.text, lineNo);
    } else if (down) {
        m_state.linkUp = false;
        for (ReplayDevice &d : m_state.devices)
            d.answering = false;
        emitEvent(sink, ms, 0, ReplayEvent::Kind::LinkDown, line.text, lineNo);
    } else if (kind == "restart") {
        // "id 2: motor1.speed 222 → 120 rpm"
        const int id = line.text.section(QLatin1Char(' '), 1, 1).remove(QLatin1Char(':')).toInt();
        if (id > 0) {
            ReplayDevice &d = m_state.devices[id];
            d.restartMs = ms;
            d.restartText = line.text;
        }
        emitEvent(sink, ms, id, ReplayEvent::Kind::Restart, line.text, lineNo);
    } else if (kind == "possible-restart") {
        // "id 1 may have restarted: silent 1.6 s; ...": not a restart the device list claims.
        const int id = line.text.section(QLatin1Char(' '), 1, 1).toInt();
        emitEvent(sink, ms, id, ReplayEvent::Kind::PossibleRestart, line.text, lineNo);
    } else if (kind == "user") {
        emitEvent(sink, ms, 0, ReplayEvent::Kind::User, line.text, lineNo);
    } else if (connecting && line.text.startsWith(u"disconnected: ")) {
        m_state.linkUp = false;
    }
}

} // namespace stepcom
