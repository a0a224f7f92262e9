#include "device/readlimits.h"

#include "map/registermap.h"

#include <QRegularExpression>
#include <QStringList>

namespace stepcom {

bool ReadLimits::isEmpty() const
{
    return !m_gapFree && m_unsupported.isEmpty() && m_split.isEmpty();
}

QString ReadLimits::toText() const
{
    QStringList words(m_unsupported.cbegin(), m_unsupported.cend());
    words.sort();
    if (m_gapFree)
        words.prepend(QStringLiteral("gaps"));
    return words.join(QLatin1Char(','));
}

ReadLimits ReadLimits::fromText(const QString &text)
{
    ReadLimits limits;
    const QRegularExpression key(QStringLiteral("^[A-Za-z][A-Za-z0-9_.]*$"));
    for (const QString &word : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const QString w = word.trimmed();
        if (w == QLatin1String("gaps"))
            limits.m_gapFree = true;
        else if (key.match(w).hasMatch())
            limits.m_unsupported.insert(w);
    }
    return limits;
}

bool ReadLimits::mayRead(const RegisterMap &map, int first, int last) const
{
    for (int address = first; address <= last; ++address) {
        const Parameter *p = map.holdingAt(quint16(address));
        if (!p) {
            if (m_gapFree)
                return false;
            continue;
        }
        if (m_unsupported.contains(p->key))
            return false;
    }
    // In a range refused as a whole, one parameter a read until the culprit is known.
    for (const ReadBlock &s : m_split) {
        const int from = std::max<int>(first, s.address);
        const int to = std::min<int>(last, s.lastAddress());
        const Parameter *seen = nullptr;
        for (int address = from; address <= to; ++address) {
            const Parameter *p = map.holdingAt(quint16(address));
            if (!p)
                continue;
            if (seen && p != seen)
                return false;
            seen = p;
        }
    }
    return true;
}

ReadLimits::Lesson ReadLimits::learn(const RegisterMap &map, const ReadBlock &block, QString *key)
{
    if (!mayRead(map, block.address, block.lastAddress()))
        return Lesson::AlreadyKnown;
    bool gap = false;
    QList<const Parameter *> inside;
    for (int address = block.address; address <= block.lastAddress(); ++address) {
        const Parameter *p = map.holdingAt(quint16(address));
        if (!p)
            gap = true;
        else if (!inside.contains(p))
            inside << p;
    }
    if (gap && !m_gapFree) {
        m_gapFree = true;
        return Lesson::GapsRefused;
    }
    if (inside.size() == 1 && !gap) {
        m_unsupported.insert(inside.constFirst()->key);
        if (key)
            *key = inside.constFirst()->key;
        return Lesson::Unsupported;
    }
    if (inside.size() > 1 && !m_split.contains(block)) {
        m_split << block;
        return Lesson::Split;
    }
    return Lesson::None;
}

} // namespace stepcom
