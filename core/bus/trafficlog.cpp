#include "bus/trafficlog.h"

#include "bus/bigendian.h"
#include "map/registermap.h"

namespace stepcom {

namespace {

using bigendian::wordAt;

QString registerRange(quint16 address, int count, const RegisterMap *map)
{
    QString text = QString::number(40001 + address);
    if (count > 1)
        text += QLatin1Char('-') + QString::number(40001 + address + count - 1);
    if (map) {
        QStringList keys;
        for (int i = 0; i < count && keys.size() < 4; ++i) {
            const Parameter *p = map->holdingAt(quint16(address + i));
            if (p && (keys.isEmpty() || keys.last() != p->key))
                keys << p->key;
        }
        if (!keys.isEmpty())
            text += QStringLiteral(" (") + keys.join(QLatin1String(", ")) +
                    (count > 4 ? QStringLiteral(", …)") : QStringLiteral(")"));
    }
    return text;
}

QString valuesText(const QByteArray &pdu, int from, int count)
{
    QStringList values;
    for (int i = 0; i < count && from + 2 * i + 1 < pdu.size(); ++i) {
        if (i == 12) {
            values << QStringLiteral("…");
            break;
        }
        values << QString::number(wordAt(pdu, from + 2 * i));
    }
    return values.join(QLatin1String(", "));
}

} // namespace

TrafficLog::TrafficLog(QObject *parent)
    : QObject(parent)
{}

void TrafficLog::setCapacity(int entries)
{
    m_capacity = std::max(10, entries);
    if (m_entries.size() > m_capacity)
        m_entries.remove(0, m_entries.size() - m_capacity);
}

void TrafficLog::clear()
{
    m_entries.clear();
    Q_EMIT cleared();
}

void TrafficLog::append(TrafficEntry entry)
{
    if (m_entries.size() >= m_capacity)
        m_entries.removeFirst();
    m_entries.append(entry);
    Q_EMIT entryAdded(m_entries.last());
}

void TrafficLog::addFrame(TrafficEntry::Direction direction, const QByteArray &raw, int pduOffset,
                          int crcBytes, const Request *context)
{
    TrafficEntry e;
    e.time = QDateTime::currentDateTime();
    e.direction = direction;
    e.bytes = raw;
    const qsizetype pduSize = raw.size() - pduOffset - crcBytes;
    const QByteArray pdu = pduSize > 0 ? raw.mid(pduOffset, pduSize) : QByteArray();
    e.summary = pduSize > 0 ? describePdu(direction, pdu, context, m_map)
                            : QStringLiteral("incomplete frame");
    e.kind = pduSize > 0 ? kindOf(context, pdu) : TrafficEntry::Kind::Error;
    append(e);
}

void TrafficLog::addEvent(const QString &text, TrafficEntry::Kind kind)
{
    TrafficEntry e;
    e.time = QDateTime::currentDateTime();
    e.direction = TrafficEntry::Direction::Event;
    e.kind = kind;
    e.summary = text;
    append(e);
}

TrafficEntry::Kind TrafficLog::kindOf(const Request *context, const QByteArray &pdu)
{
    if (!pdu.isEmpty() && (quint8(pdu.at(0)) & 0x80))
        return TrafficEntry::Kind::Error; // an exception answer
    if (!context)
        return TrafficEntry::Kind::Event;
    switch (context->type) {
    case Request::Type::ReadHolding:
        return context->priority == Priority::Poll ? TrafficEntry::Kind::Poll
                                                   : TrafficEntry::Kind::Read;
    case Request::Type::WriteHolding:
        return TrafficEntry::Kind::Write;
    case Request::Type::WriteCoil:
        return TrafficEntry::Kind::Command;
    }
    return TrafficEntry::Kind::Event;
}

QString TrafficLog::describePdu(TrafficEntry::Direction direction, const QByteArray &pdu,
                                const Request *context, const RegisterMap *map)
{
    if (pdu.isEmpty())
        return QStringLiteral("empty");
    const int fc = quint8(pdu.at(0));
    const bool sent = direction == TrafficEntry::Direction::Sent;
    if (fc & 0x80)
        return QStringLiteral("exception to FC%1: %2")
            .arg(fc & 0x7F, 2, 16, QLatin1Char('0'))
            .arg(pdu.size() > 1 ? exceptionText(quint8(pdu.at(1))) : QStringLiteral("?"));
    switch (fc) {
    case 0x03:
        if (sent && pdu.size() >= 5)
            return QStringLiteral("read %1").arg(
                registerRange(wordAt(pdu, 1), wordAt(pdu, 3), map));
        if (!sent && pdu.size() >= 2) {
            const int count = quint8(pdu.at(1)) / 2;
            QString text = QStringLiteral("= %1").arg(valuesText(pdu, 2, count));
            if (context && context->type == Request::Type::ReadHolding)
                text = QStringLiteral("%1 %2").arg(QString::number(40001 + context->address), text);
            return text;
        }
        break;
    case 0x05:
        if (pdu.size() >= 5) {
            const quint16 address = wordAt(pdu, 1);
            QString name = QString::number(address + 1).rightJustified(5, QLatin1Char('0'));
            if (map) {
                if (const Parameter *p = map->coilAt(address))
                    name += QStringLiteral(" (%1)").arg(p->key);
            }
            const quint16 value = wordAt(pdu, 3);
            const QString state = value == 0xFF00   ? QStringLiteral("ON")
                                  : value == 0x0000 ? QStringLiteral("OFF")
                                                    : QStringLiteral("0x%1?").arg(value, 4, 16);
            return QStringLiteral("%1 coil %2 %3")
                .arg(sent ? QStringLiteral("write") : QStringLiteral("ok"), name, state);
        }
        break;
    case 0x06:
        if (pdu.size() >= 5)
            return QStringLiteral("%1 %2 = %3")
                .arg(sent ? QStringLiteral("write") : QStringLiteral("ok"),
                     registerRange(wordAt(pdu, 1), 1, map))
                .arg(wordAt(pdu, 3));
        break;
    case 0x10:
        if (pdu.size() >= 5) {
            const quint16 address = wordAt(pdu, 1);
            const int count = wordAt(pdu, 3);
            if (sent)
                return QStringLiteral("write %1 = %2")
                    .arg(registerRange(address, count, map), valuesText(pdu, 6, count));
            return QStringLiteral("ok %1").arg(registerRange(address, count, map));
        }
        break;
    default:
        return QStringLiteral("function 0x%1").arg(fc, 2, 16, QLatin1Char('0'));
    }
    return QStringLiteral("malformed FC%1 frame").arg(fc, 2, 16, QLatin1Char('0'));
}

QString TrafficLog::format(const TrafficEntry &entry)
{
    const char *dir = entry.direction == TrafficEntry::Direction::Sent       ? "TX"
                      : entry.direction == TrafficEntry::Direction::Received ? "RX"
                                                                             : "--";
    QString hex = QString::fromLatin1(entry.bytes.toHex(' ').toUpper());
    return QStringLiteral("%1  %2  %3%4")
        .arg(entry.time.toString(QStringLiteral("HH:mm:ss.zzz")), QLatin1String(dir),
             hex.isEmpty() ? QString() : hex + QStringLiteral("  "), entry.summary);
}

} // namespace stepcom
