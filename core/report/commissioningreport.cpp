#include "report/commissioningreport.h"

#include "device/wiringcheck.h"
#include "profile/settingsfingerprint.h"
#include "report/certificatesection.h"
#include "report/reportfile.h"
#include "report/reporthtml.h"
#include "report/xypicture.h"

#include <QFont>
#include <QFontInfo>
#include <QFontMetricsF>
#include <QTextDocument>
#include <QUrl>

namespace stepcom {

namespace {

const QString kImageName = QStringLiteral("stepcom-xy.png");
const QSize kImageSize(900, 900);

using namespace reporthtml;

} // namespace

CommissioningReport::CommissioningReport(ReportInput input)
    : m_in(std::move(input))
{
    if (!m_in.date.isValid())
        m_in.date = QDateTime::currentDateTime();
}

QString CommissioningReport::label(const Parameter &p) const
{
    return p.label.text(m_in.locale);
}

QString CommissioningReport::text(const char *key) const
{
    const Parameter *p = m_in.map.find(QLatin1String(key));
    if (!p || !m_in.values.contains(p->key))
        return QStringLiteral("—");
    return p->displayRaw(m_in.values.value(p->key), m_in.locale);
}

QString CommissioningReport::controllerSection() const
{
    QString h = QStringLiteral("<h2>%1</h2>\n")
                    .arg(esc(m_in.fromFile() ? tr("Controller (as the profile records it)")
                                             : tr("Controller")));
    h += QLatin1String(kTable);
    auto line = [&](const QString &what, const QString &value) {
        h += row({esc(what), esc(value)});
    };
    line(tr("Device id"), m_in.deviceId > 0 ? QString::number(m_in.deviceId) : text("device.id"));
    if (m_in.simulator)
        line(tr("Controller"), tr("StepCom's built-in simulator -- not a machine"));
    if (m_in.fromFile())
        line(tr("Link"), tr("none: made from a file, not read from a controller"));
    else
        line(tr("Link"), m_in.link.isEmpty() ? QStringLiteral("—") : m_in.link);
    if (!m_in.fromFile() && !m_in.line.isEmpty())
        line(tr("Link, as measured"), m_in.line);
    QString baud = text("device.baud");
    if (baud == QStringLiteral("—") && m_in.fileBaud > 0)
        baud = QString::number(m_in.fileBaud);
    line(m_in.fromFile() ? tr("Baud rate") : tr("Baud rate (register)"), baud);
    QString map =
        QStringLiteral("%1 (%2)").arg(m_in.map.name().text(m_in.locale), m_in.map.identity());
    if (!m_in.fileMap.isEmpty())
        map += QStringLiteral("; ") + tr("the profile was made with %1").arg(m_in.fileMap);
    line(tr("Register map"), map);
    QString mode = text("mode.system");
    if (m_in.values.value(QStringLiteral("mode.system")) == 1)
        mode += QStringLiteral(", ") + tr("round trips: %1").arg(text("mode.round_trips"));
    line(tr("System mode"), mode);
    line(tr("Homing order"),
         tr("first: %1, then: %2").arg(text("homing.first"), text("homing.second")));
    const QLocale locale = m_in.locale.isEmpty() ? QLocale() : QLocale(m_in.locale);
    if (m_in.fromFile()) {
        line(tr("Profile file"), m_in.sourceFile);
        if (m_in.fileCreated.isValid())
            line(tr("Profile saved"),
                 tr("%1 by StepCom %2")
                     .arg(locale.toString(m_in.fileCreated.toLocalTime(), QLocale::LongFormat),
                          m_in.fileStepcomVersion.isEmpty() ? QStringLiteral("—")
                                                            : m_in.fileStepcomVersion));
    }
    line(m_in.fromFile() ? tr("Report date") : tr("Date"),
         locale.toString(m_in.date, QLocale::LongFormat));
    if (!m_in.fromFile()) {
        line(tr("Values read"), m_in.lastRead.isValid()
                                    ? locale.toString(m_in.lastRead, QLocale::LongFormat)
                                    : QStringLiteral("—"));
        line(tr("Flash"),
             !m_in.savedToFlash ? tr("unknown: this program did not follow the writes")
             : *m_in.savedToFlash
                 ? tr("saved: nothing written since connecting or since the last save to flash")
                 : tr("NOT saved: values were written since the last save to flash and are lost "
                      "at power-off"));
    }
    line(tr("StepCom version"), QStringLiteral(STEPCOM_VERSION));
    // One line to compare two machines by: the same settings give the same line.
    line(tr("Settings fingerprint"),
         SettingsFingerprint::line(m_in.map, SettingsFingerprint::ordered(m_in.values)));
    return h + QStringLiteral("</table>\n");
}

QString CommissioningReport::fileSection() const
{
    if (!m_in.fromFile() || m_in.notFromFile.isEmpty())
        return {};
    QString h = QStringLiteral("<h2>%1</h2>\n<ul>\n")
                    .arg(esc(tr("What of the profile this register map cannot show")));
    for (const QString &line : m_in.notFromFile)
        h += QStringLiteral("<li>%1</li>\n").arg(esc(line));
    return h + QStringLiteral("</ul>\n");
}

QString CommissioningReport::parameterSection() const
{
    QString h = QStringLiteral("<h2>%1</h2>\n").arg(esc(tr("Parameters")));
    for (const ParameterGroup &g : m_in.map.groups()) {
        QList<const Parameter *> params;
        for (const Parameter *p : m_in.map.inGroup(g.id)) {
            if (p->writable())
                params << p;
        }
        if (params.isEmpty())
            continue;
        // A block group ("Motor {n}") holds every instance: split it per instance.
        QList<int> instances;
        for (const Parameter *p : std::as_const(params)) {
            if (!instances.contains(p->instance))
                instances << p->instance;
        }
        for (int instance : std::as_const(instances)) {
            // The map fills a group label's {n} with 0 (the group is shared by the instances).
            QString title = g.label.text(m_in.locale);
            if (instance > 0)
                title = params.first()->block == QLatin1String("motor")
                            ? tr("Motor %1").arg(instance)
                            : QStringLiteral("%1 (%2)").arg(title).arg(instance);
            h += QStringLiteral("<h3>%1</h3>\n").arg(esc(title));
            h += QLatin1String(kTable);
            h += row({esc(tr("Parameter")), esc(tr("Value")), esc(tr("Unit")), esc(tr("Key")),
                      esc(tr("Register"))},
                     true);
            for (const Parameter *p : std::as_const(params)) {
                if (p->instance != instance)
                    continue;
                QString value = QStringLiteral("—");
                if (m_in.unsupported.contains(p->key)) {
                    value = tr("not supported by this controller");
                } else if (m_in.values.contains(p->key)) {
                    const qint64 raw = m_in.values.value(p->key);
                    value = p->formatRaw(raw);
                    const QString shown = p->displayRaw(raw, m_in.locale);
                    if (!p->values.isEmpty() && shown != value)
                        value += QStringLiteral(" (%1)").arg(shown);
                }
                h += row({esc(label(*p)), esc(value), esc(p->unit), esc(p->key),
                          esc(p->registerName())});
            }
            h += QStringLiteral("</table>\n");
        }
    }
    return h;
}

QString CommissioningReport::wiringSection() const
{
    QString h = QStringLiteral("<h2>%1</h2>\n").arg(esc(tr("Input wiring")));
    h += QLatin1String(kTable);
    h += row({esc(tr("Motor")), esc(tr("Positive limit")), esc(tr("Negative limit")),
              esc(tr("Home input"))},
             true);
    QList<MotorWiring> motors;
    const int count = m_in.map.blockCount(QStringLiteral("motor"));
    auto input = [&](int n, const char *local) -> std::optional<int> {
        const Parameter *p =
            m_in.map.blockParameter(QStringLiteral("motor"), n, QLatin1String(local));
        if (!p || !m_in.values.contains(p->key))
            return std::nullopt;
        return int(m_in.values.value(p->key));
    };
    auto name = [](std::optional<int> v) { return v ? inputName(*v) : QStringLiteral("—"); };
    for (int n = 1; n <= count; ++n) {
        MotorWiring w{n, input(n, "limit_positive"), input(n, "limit_negative"),
                      input(n, "home_input")};
        motors << w;
        h += row({esc(tr("Motor %1").arg(n)), name(w.positive), name(w.negative), name(w.home)});
    }
    h += QStringLiteral("</table>\n");
    std::optional<int> mode;
    if (m_in.values.contains(QStringLiteral("mode.system")))
        mode = int(m_in.values.value(QStringLiteral("mode.system")));
    const QList<WiringWarning> warnings = checkWiring(motors, mode);
    if (warnings.isEmpty()) {
        h += QStringLiteral("<p>%1</p>\n").arg(esc(tr("No suspicious wiring found.")));
    } else {
        h += QStringLiteral("<ul>\n");
        for (const WiringWarning &w : warnings)
            h += QStringLiteral("<li>%1</li>\n").arg(esc(w.message));
        h += QStringLiteral("</ul>\n");
    }
    return h;
}

QString CommissioningReport::interpolationSection(const QString &imageSource) const
{
    QString h = QStringLiteral("<h2>%1</h2>\n").arg(esc(tr("Arc and line interpolation")));
    h += QLatin1String(kTable);
    auto pair = [&](const char *x, const char *y) {
        return QStringLiteral("(%1, %2)").arg(text(x), text(y));
    };
    h += row({esc(tr("Arc")), esc(text("arc.enabled"))});
    h += row({esc(tr("Arc mode")), esc(text("arc.mode"))});
    h += row({esc(tr("Arc start")), esc(pair("arc.start_x", "arc.start_y"))});
    h += row({esc(tr("Arc end")), esc(pair("arc.end_x", "arc.end_y"))});
    if (m_in.values.value(QStringLiteral("arc.mode")) == 0)
        h += row({esc(tr("Arc centre")), esc(pair("arc.center_x", "arc.center_y"))});
    else
        h += row({esc(tr("Arc middle point")), esc(pair("arc.middle_x", "arc.middle_y"))});
    h += row({esc(tr("Arc direction")), esc(text("arc.direction"))});
    h += row({esc(tr("Arc speed")), esc(text("arc.speed"))});
    h += row({esc(tr("Line")), esc(text("line.enabled"))});
    h += row({esc(tr("Line start")), esc(pair("line.start_x", "line.start_y"))});
    h += row({esc(tr("Line end")), esc(pair("line.end_x", "line.end_y"))});
    h += row({esc(tr("Line speed")), esc(text("line.speed"))});
    h += QStringLiteral("</table>\n");
    const XyPicture picture(m_in.map, m_in.values);
    if (!picture.arcProblem().isEmpty())
        h += QStringLiteral("<p>%1</p>\n")
                 .arg(esc(tr("The arc cannot be drawn: %1").arg(picture.arcProblem())));
    h += QStringLiteral("<p><img src=\"%1\" width=\"400\" height=\"400\" alt=\"%2\"></p>\n")
             .arg(imageSource, esc(tr("XY picture of the arc and the line")));
    return h;
}

QString CommissioningReport::title() const
{
    const QString title = m_in.fromFile() ? tr("Commissioning report (from a profile file)")
                                          : tr("Commissioning report");
    return m_in.simulator ? tr("%1 -- simulator, not a machine").arg(title) : title;
}

QString CommissioningReport::html(const QString &imageSource) const
{
    const QString title = this->title();
    QString h = QStringLiteral("<html><head><meta charset=\"utf-8\"><title>%1</title></head>"
                               "<body>\n")
                    .arg(esc(title));
    h += QStringLiteral("<h1>%1</h1>\n").arg(esc(title));
    return h + body(imageSource) + QStringLiteral("</body></html>\n");
}

QString CommissioningReport::body(const QString &imageSource) const
{
    QString h;
    if (!m_in.title.isEmpty())
        h += QStringLiteral("<p><b>%1</b></p>\n").arg(esc(m_in.title));
    if (m_in.simulator)
        h += QStringLiteral("<p><b>%1</b></p>\n")
                 .arg(esc(tr("SIMULATOR -- NOT A MACHINE: these values were read from StepCom's "
                             "built-in simulator. This sheet certifies no machine.")));
    if (m_in.fromFile())
        h += QStringLiteral("<p><b>%1</b></p>\n")
                 .arg(esc(tr("Made from the profile file %1, not read from a controller: these "
                             "are the values the file holds; a controller may hold others.")
                              .arg(m_in.sourceFile)));
    const CertificateSection certificate(m_in);
    h += controllerSection();
    h += certificate.checklist();
    h += wiringSection();
    // The long tables run from the first page on; the picture, which cannot be split, comes
    // after them so it never leaves a half-empty first page behind.
    h += parameterSection();
    if (!m_in.unsupported.isEmpty())
        h += QStringLiteral("<p>%1</p>\n")
                 .arg(esc(tr("Not supported by this controller (it refuses to read them, a "
                             "firmware variant): %1")
                              .arg(m_in.unsupported.join(QLatin1String(", ")))));
    h += certificate.travelLimits();
    h += interpolationSection(imageSource);
    h += fileSection();
    h += QStringLiteral("<h2>%1</h2>\n").arg(esc(tr("Notes")));
    h += QStringLiteral("<p>%1</p>\n")
             .arg(m_in.notes.isEmpty()
                      ? QStringLiteral("—")
                      : esc(m_in.notes).replace(QLatin1Char('\n'), QLatin1String("<br>")));
    h += certificate.signatures();
    return h;
}

QImage CommissioningReport::picture() const
{
    return XyPicture(m_in.map, m_in.values).render(kImageSize);
}

std::unique_ptr<QTextDocument> CommissioningReport::document() const
{
    auto doc = std::make_unique<QTextDocument>();
    if (m_in.locale.startsWith(QLatin1String("zh"))) {
        // Han characters from a Simplified Chinese font (the system's fallback may pick the
        // Japanese glyph variants); Latin text and digits stay in the default font, whose
        // glyphs PDF readers map back to text reliably.
        QFont font = doc->defaultFont();
        font.setFamilies({QFontInfo(font).family(), QStringLiteral("Noto Sans CJK SC"),
                          QStringLiteral("Source Han Sans SC"),
                          QStringLiteral("WenQuanYi Micro Hei"), QStringLiteral("Microsoft YaHei"),
                          QStringLiteral("PingFang SC")});
        doc->setDefaultFont(font);
        // Latin and Han lines differ in height; one fixed line height keeps every cell of a row
        // equal, so a row is never split across two pages.
        doc->setDefaultStyleSheet(QStringLiteral("td, th { line-height: %1px; }")
                                      .arg(qRound(QFontMetricsF(font).height() * 1.25)));
    }
    doc->addResource(QTextDocument::ImageResource, QUrl(kImageName), picture());
    doc->setHtml(html(kImageName));
    return doc;
}

QString CommissioningReport::write(const QString &path) const
{
    // HTML: one self-contained file, the picture travels inside it as a data URL.
    return ReportFile::write(
        path, title(), [this] { return document(); },
        [this] { return html(ReportFile::pngDataUrl(picture())); });
}

} // namespace stepcom
