#include "support/logline.h"

#include <QDate>

namespace stepcom {

namespace {

bool digits(QByteArrayView text, qsizetype from, qsizetype count, int *out)
{
    int v = 0;
    for (qsizetype i = from; i < from + count; ++i) {
        const char c = text.at(i);
        if (c < '0' || c > '9')
            return false;
        v = v * 10 + (c - '0');
    }
    *out = v;
    return true;
}

qsizetype skipSpaces(QByteArrayView text, qsizetype at)
{
    while (at < text.size() && text.at(at) == ' ')
        ++at;
    return at;
}

} // namespace

bool LogLine::parseStamp(QByteArrayView t, qint64 *stamp)
{
    // yyyy-MM-dd HH:mm:ss.zzz
    if (t.size() < 23 || t.at(4) != '-' || t.at(7) != '-' || t.at(10) != ' ' || t.at(13) != ':' ||
        t.at(16) != ':' || t.at(19) != '.')
        return false;
    int y = 0, mo = 0, d = 0, h = 0, mi = 0, s = 0, ms = 0;
    if (!digits(t, 0, 4, &y) || !digits(t, 5, 2, &mo) || !digits(t, 8, 2, &d) ||
        !digits(t, 11, 2, &h) || !digits(t, 14, 2, &mi) || !digits(t, 17, 2, &s) ||
        !digits(t, 20, 3, &ms))
        return false;
    const QDate date(y, mo, d);
    if (!date.isValid() || h > 23 || mi > 59 || s > 60)
        return false;
    *stamp = date.toJulianDay() * kDayMs + ((h * 60 + mi) * 60 + s) * 1000 + ms;
    return true;
}

QString LogLine::stampText(qint64 stamp)
{
    const QDate date = QDate::fromJulianDay(stamp / kDayMs);
    const qint64 ms = stamp % kDayMs;
    return QStringLiteral("%1 %2:%3:%4.%5")
        .arg(date.toString(QStringLiteral("yyyy-MM-dd")))
        .arg(ms / 3600000, 2, 10, QLatin1Char('0'))
        .arg(ms / 60000 % 60, 2, 10, QLatin1Char('0'))
        .arg(ms / 1000 % 60, 2, 10, QLatin1Char('0'))
        .arg(ms % 1000, 3, 10, QLatin1Char('0'));
}

LogLine LogLine::parse(QByteArrayView line)
{
    LogLine l;
    while (!line.isEmpty() && (line.back() == '\n' || line.back() == '\r'))
        line.chop(1);
    if (line.trimmed().isEmpty()) {
        l.type = Type::Blank;
        return l;
    }
    if (line.front() == '#') {
        // "# key: value"; the first line of a file has no key of that form.
        l.type = Type::Header;
        const QByteArrayView body = line.sliced(1).trimmed();
        const qsizetype colon = body.indexOf(':');
        const QByteArrayView key = colon > 0 ? body.first(colon) : QByteArrayView();
        const bool simple = !key.isEmpty() && !key.contains(' ');
        l.key = simple ? key.toByteArray() : QByteArrayLiteral("title");
        l.text = QString::fromUtf8(simple ? body.sliced(colon + 1).trimmed() : body);
        return l;
    }
    if (!parseStamp(line, &l.stamp))
        return l; // garbage
    // "  TX  kind  ...": the direction, then the kind.
    if (line.size() < 29 || line.sliced(23, 2) != "  " || line.sliced(27, 2) != "  ")
        return l;
    const QByteArrayView dir = line.sliced(25, 2);
    qsizetype at = 29;
    const qsizetype kindEnd = [&] {
        qsizetype e = at;
        while (e < line.size() && line.at(e) != ' ')
            ++e;
        return e;
    }();
    if (kindEnd == at)
        return l;
    l.kind = line.sliced(at, kindEnd - at).toByteArray();
    at = skipSpaces(line, kindEnd);
    if (dir == "--") {
        l.type = Type::Mark;
        l.text = QString::fromUtf8(line.sliced(at));
        return l;
    }
    if (dir != "TX" && dir != "RX")
        return l;
    // Hex bytes "01 03 00 ..." up to two spaces (or the end), then the summary.
    qsizetype end = line.indexOf("  ", at);
    if (end < 0)
        end = line.size();
    const QByteArrayView hex = line.sliced(at, end - at);
    if (hex.isEmpty() || (hex.size() + 1) % 3 != 0)
        return l;
    for (qsizetype i = 0; i < hex.size(); ++i) {
        const char c = hex.at(i);
        const bool isHex =
            (c >= '0' && c <= '9') || (c >= 'A' && c <= 'F') || (c >= 'a' && c <= 'f');
        if (i % 3 == 2 ? c != ' ' : !isHex)
            return l;
    }
    l.bytes = QByteArray::fromHex(hex.toByteArray());
    l.sent = dir == "TX";
    l.type = Type::Frame; // its summary is left out: the bytes say it all, and faster
    return l;
}

} // namespace stepcom
