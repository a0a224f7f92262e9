#include "report/machinereport.h"

#include "profile/settingsfingerprint.h"
#include "report/commissioningreport.h"
#include "report/reportfile.h"
#include "report/reporthtml.h"

#include <QImage>
#include <QTextDocument>
#include <QUrl>

#include <algorithm>

namespace stepcom {

namespace {

using namespace reporthtml;

QString imageName(int index)
{
    return QStringLiteral("stepcom-xy-%1.png").arg(index + 1);
}

} // namespace

MachineReport::MachineReport(QList<ReportInput> devices, const QString &title, const QString &notes,
                             const QString &locale)
    : m_devices(std::move(devices))
    , m_title(title)
    , m_notes(notes)
    , m_locale(locale)
    , m_date(QDateTime::currentDateTime())
{
    for (ReportInput &d : m_devices) {
        d.locale = locale;
        if (!d.date.isValid())
            d.date = m_date;
    }
}

QString MachineReport::title() const
{
    const QString title =
        tr("Commissioning report of a machine: %n controller(s)", nullptr, int(m_devices.size()));
    const bool simulated = std::any_of(m_devices.cbegin(), m_devices.cend(),
                                       [](const ReportInput &d) { return d.simulator; });
    return simulated ? tr("%1 -- simulator, not a machine").arg(title) : title;
}

QString MachineReport::heading(const ReportInput &device) const
{
    return device.title.isEmpty()
               ? tr("Controller id %1").arg(device.deviceId)
               : tr("Controller id %1: %2").arg(device.deviceId).arg(device.title);
}

QString MachineReport::summary() const
{
    QString h = QStringLiteral("<h2>%1</h2>\n").arg(esc(tr("Controllers on the line")));
    h += QLatin1String(kTable);
    h += row(
        {esc(tr("Device id")), esc(tr("Name")), esc(tr("Link")), esc(tr("Settings fingerprint"))},
        true);
    for (const ReportInput &d : m_devices) {
        h += row({QString::number(d.deviceId),
                  esc(d.title.isEmpty() ? QStringLiteral("—") : d.title),
                  esc(d.simulator        ? tr("built-in simulator -- not a machine")
                      : d.link.isEmpty() ? QStringLiteral("—")
                                         : d.link),
                  esc(SettingsFingerprint::line(d.map, SettingsFingerprint::ordered(d.values)))});
    }
    h += QStringLiteral("</table>\n");
    const QLocale locale = m_locale.isEmpty() ? QLocale() : QLocale(m_locale);
    h += QStringLiteral("<p>%1</p>\n")
             .arg(esc(tr("Date: %1").arg(locale.toString(m_date, QLocale::LongFormat))));
    h += QStringLiteral("<h2>%1</h2>\n<p>%2</p>\n")
             .arg(esc(tr("Notes")),
                  m_notes.isEmpty()
                      ? QStringLiteral("—")
                      : esc(m_notes).replace(QLatin1Char('\n'), QLatin1String("<br>")));
    return h;
}

QString MachineReport::html(const QStringList &imageSources) const
{
    const QString title = this->title();
    QString h = QStringLiteral("<html><head><meta charset=\"utf-8\"><title>%1</title></head>"
                               "<body>\n")
                    .arg(esc(title));
    h += QStringLiteral("<h1>%1</h1>\n").arg(esc(title));
    if (!m_title.isEmpty())
        h += QStringLiteral("<p><b>%1</b></p>\n").arg(esc(m_title));
    h += summary();
    for (qsizetype i = 0; i < m_devices.size(); ++i) {
        const ReportInput &d = m_devices.at(i);
        // Each controller's sheet on its own pages.
        h += QStringLiteral("<h1 style=\"page-break-before: always\">%1</h1>\n")
                 .arg(esc(heading(d)));
        ReportInput sheet = d;
        sheet.title.clear(); // the heading names it
        h += CommissioningReport(sheet).body(imageSources.value(i));
    }
    return h + QStringLiteral("</body></html>\n");
}

std::unique_ptr<QTextDocument> MachineReport::document() const
{
    // The single report's document brings the fonts (Chinese included) and the line height.
    ReportInput first = m_devices.value(0);
    first.locale = m_locale;
    auto doc = CommissioningReport(first).document();
    QStringList names;
    for (qsizetype i = 0; i < m_devices.size(); ++i)
        names << imageName(int(i));
    doc->setHtml(html(names));
    for (qsizetype i = 0; i < m_devices.size(); ++i)
        doc->addResource(QTextDocument::ImageResource, QUrl(names.at(i)),
                         CommissioningReport(m_devices.at(i)).picture());
    return doc;
}

QString MachineReport::write(const QString &path) const
{
    if (m_devices.isEmpty())
        return tr("%1: no controller to report on").arg(path);
    return ReportFile::write(
        path, title(), [this] { return document(); }, [this] { return selfContainedHtml(); });
}

QString MachineReport::selfContainedHtml() const
{
    QStringList sources;
    for (const ReportInput &d : m_devices)
        sources << ReportFile::pngDataUrl(CommissioningReport(d).picture());
    return html(sources);
}

QStringList MachineReport::sheetLines() const
{
    QStringList lines;
    for (const ReportInput &d : m_devices) {
        QString line = QStringLiteral("id %1").arg(d.deviceId);
        if (!d.title.isEmpty())
            line += QStringLiteral(" \"%1\"").arg(d.title);
        if (d.fromFile())
            line += QStringLiteral(": made from the profile file %1 (no controller read)")
                        .arg(d.sourceFile);
        else
            line += QStringLiteral(": %1, values as read%2")
                        .arg(d.link.isEmpty() ? QStringLiteral("controller") : d.link,
                             d.lastRead.isValid()
                                 ? QStringLiteral(" at ") + d.lastRead.toString(Qt::ISODate)
                                 : QString());
        if (d.simulator)
            line += QStringLiteral(" -- the built-in simulator, not a machine");
        lines << line;
    }
    return lines;
}

} // namespace stepcom
