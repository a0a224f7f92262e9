#include "session/idlist.h"

#include <QRegularExpression>

namespace stepcom {

std::optional<QList<int>> IdList::parse(const QString &text, QString *error, bool allowRepeats)
{
    auto fail = [&](const QString &why) -> std::optional<QList<int>> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    static const QRegularExpression part(
        QStringLiteral("^\\s*(\\d{1,3})\\s*(?:-\\s*(\\d{1,3})\\s*)?$"));
    QList<int> ids;
    const QStringList parts = text.split(QLatin1Char(','));
    for (const QString &p : parts) {
        const QRegularExpressionMatch m = part.match(p);
        if (!m.hasMatch())
            return fail(tr("'%1' is not a device id or a range of ids (e.g. 1,2,3 or 1-3)")
                            .arg(p.trimmed()));
        const int first = m.captured(1).toInt();
        const int last = m.captured(2).isEmpty() ? first : m.captured(2).toInt();
        if (first < 1 || first > 255 || last < 1 || last > 255)
            return fail(tr("'%1': device ids are 1-255").arg(p.trimmed()));
        if (last < first)
            return fail(tr("'%1': the range runs backwards").arg(p.trimmed()));
        for (int id = first; id <= last; ++id) {
            if (!allowRepeats && ids.contains(id))
                return fail(tr("device id %1 is given twice").arg(id));
            ids.append(id);
        }
    }
    return ids;
}

QString IdList::format(const QList<int> &ids)
{
    QStringList parts;
    for (int id : ids)
        parts << QString::number(id);
    return parts.join(QLatin1Char(','));
}

} // namespace stepcom
