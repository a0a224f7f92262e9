#include "report/certificatesection.h"

#include "profile/settingsfingerprint.h"

#include "report/reporthtml.h"

#include <QLocale>

namespace stepcom {

namespace {

using namespace reporthtml;

} // namespace

CertificateSection::CertificateSection(const ReportInput &input)
    : m_in(input)
{}

QString CertificateSection::measurements(const ChecklistAttempt &attempt) const
{
    QStringList parts;
    for (const ChecklistMeasurement &m : attempt.measurements) {
        const QString value = m.unit.isEmpty() ? m.value : m.value + QLatin1Char(' ') + m.unit;
        parts << tr("%1: %2").arg(ChecklistStep::measurementLabel(m.key), value);
    }
    return parts.isEmpty() ? QStringLiteral("—") : parts.join(QLatin1String("; "));
}

QString CertificateSection::checklist() const
{
    QString h = QStringLiteral("<h2>%1</h2>\n").arg(esc(tr("Commissioning checklist")));
    if (!m_in.checklist) {
        return h + QStringLiteral("<p>%1</p>\n")
                       .arg(esc(tr("No commissioning checklist was recorded for this machine: "
                                   "this report shows settings, not tests.")));
    }
    const Checklist &c = *m_in.checklist;
    h += QStringLiteral("<p><b>%1</b> %2</p>\n")
             .arg(esc(Checklist::verdictText(c.verdict())), esc(c.summary()));
    if (!m_in.checklistFile.isEmpty())
        h += QStringLiteral("<p>%1</p>\n")
                 .arg(esc(tr("Checklist file: %1").arg(m_in.checklistFile)));
    // The checklist remembers the settings it ran against; other settings make it stale.
    const QString now =
        SettingsFingerprint::shortHash(m_in.map, SettingsFingerprint::ordered(m_in.values));
    if (!c.settingsFingerprint.isEmpty() && c.settingsFingerprint != now)
        h += QStringLiteral("<p><b>%1</b></p>\n")
                 .arg(esc(tr("The checklist was last run with other settings (fingerprint %1); "
                             "this report's settings have the fingerprint %2.")
                              .arg(c.settingsFingerprint, now)));
    const QLocale locale = m_in.locale.isEmpty() ? QLocale() : QLocale(m_in.locale);
    h += QLatin1String(kTable);
    // Widths for the header cells: the measurements need the room, the time needs little.
    h += QStringLiteral("<thead><tr><th width=\"22%\">%1</th><th width=\"13%\">%2</th>"
                        "<th width=\"35%\">%3</th><th width=\"12%\">%4</th>"
                        "<th width=\"18%\">%5</th></tr></thead>\n")
             .arg(esc(tr("Step")), esc(tr("Result")), esc(tr("Measured")), esc(tr("Time")),
                  esc(tr("Note")));
    for (const ChecklistStep &s : c.steps()) {
        const ChecklistAttempt *a = s.latest();
        if (!a) {
            h += row({esc(s.title()), esc(ChecklistStep::resultLabel(StepResult::Pending)),
                      QStringLiteral("—"), QStringLiteral("—"), QString()});
            continue;
        }
        QString result = ChecklistStep::resultLabel(a->result);
        if (a->number > 1)
            result = tr("%1 (attempt %2)").arg(result).arg(a->number);
        h += row({esc(s.title()), esc(result), esc(measurements(*a)),
                  esc(locale.toString(a->time.toLocalTime(), QLocale::ShortFormat)), esc(a->note)});
    }
    return h + QStringLiteral("</table>\n");
}

QString CertificateSection::travelLimits() const
{
    if (m_in.travelLimits.isEmpty())
        return {};
    QString h = QStringLiteral("<h2>%1</h2>\n<p>%2</p>\n")
                    .arg(esc(tr("Software travel limits")),
                         esc(tr("StepCom's own limits for steps, moves to a position and jogs; "
                                "not controller registers. The limit switches stay the machine's "
                                "protection.")));
    h += QLatin1String(kTable);
    h += row({esc(tr("Motor")), esc(tr("Min")), esc(tr("Max"))}, true);
    const auto &axes = m_in.travelLimits.axes();
    for (auto it = axes.cbegin(); it != axes.cend(); ++it) {
        const Parameter *p = TravelLimits::positionParameter(m_in.map, it.key());
        auto end = [&](const std::optional<qint64> &raw) {
            if (!raw || !p)
                return tr("open");
            return p->formatRaw(*raw) + QLatin1Char(' ') + p->unit;
        };
        h += row({esc(tr("Motor %1").arg(it.key())), esc(end(it->min)), esc(end(it->max))});
    }
    return h + QStringLiteral("</table>\n");
}

QString CertificateSection::signatures() const
{
    QString h = QStringLiteral("<h2>%1</h2>\n").arg(esc(tr("Signatures")));
    // Where a certificate is signed, a simulator's must not pass for a machine's.
    if (m_in.simulator)
        h += QStringLiteral("<p><b>%1</b></p>\n")
                 .arg(esc(tr("Read from StepCom's built-in simulator, not from a machine: "
                             "nothing here can be signed for a machine.")));
    h += QLatin1String(kTable);
    h += row({esc(tr("Role")), esc(tr("Name")), esc(tr("Signature")), esc(tr("Date"))}, true);
    const QString blank = QStringLiteral("&nbsp;<br>&nbsp;");
    for (const QString &role : {tr("Commissioned by"), tr("Accepted by (customer)")})
        h += row({esc(role), blank, blank, blank});
    return h + QStringLiteral("</table>\n");
}

} // namespace stepcom
