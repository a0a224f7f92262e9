#pragma once

#include <QString>
#include <QStringList>

// The HTML pieces every section of the commissioning report is built from.
namespace stepcom::reporthtml {

inline QString esc(const QString &s)
{
    return s.toHtmlEscaped();
}

inline QString row(const QStringList &cells, bool header = false)
{
    const QString tag = header ? QStringLiteral("th") : QStringLiteral("td");
    QString out = QStringLiteral("<tr>");
    for (const QString &c : cells)
        out += QStringLiteral("<%1>%2</%1>").arg(tag, c);
    out += QStringLiteral("</tr>");
    // A header row in <thead> is repeated at the top of every page the table runs onto.
    return header ? QStringLiteral("<thead>%1</thead>\n").arg(out) : out + QLatin1Char('\n');
}

inline constexpr const char *kTable =
    "<table border=\"1\" cellspacing=\"0\" cellpadding=\"3\" width=\"100%\">\n";

} // namespace stepcom::reporthtml
