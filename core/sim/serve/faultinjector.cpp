#include "sim/serve/faultinjector.h"

#include <QCoreApplication>

namespace stepcom {

FaultInjector::FaultInjector(const FaultOptions &options)
    : m_options(options)
    , m_random(options.seed)
{}

FaultInjector::Decision FaultInjector::next()
{
    const double dropRoll = m_random.generateDouble();
    const double corruptRoll = m_random.generateDouble();
    const double lateRoll = m_random.generateDouble();
    const double exceptionRoll = m_random.generateDouble();
    Decision d;
    d.exceptionCode = exceptionRoll < m_options.exception ? m_options.exceptionCode : 0;
    d.drop = dropRoll < m_options.drop;
    d.corruptCrc = !d.drop && corruptRoll < m_options.corruptCrc;
    d.extraDelayMs = lateRoll < m_options.late ? m_options.lateMs : 0;
    if (!d.drop && m_options.hangupAfter > 0 && ++m_answered >= m_options.hangupAfter) {
        m_answered = 0;
        d.hangUp = true;
    }
    return d;
}

std::optional<double> FaultInjector::parseShare(const QString &text, QString *error)
{
    QString t = text.trimmed();
    double divisor = 1;
    if (t.endsWith(QLatin1Char('%'))) {
        t.chop(1);
        divisor = 100;
    }
    bool ok = false;
    const double v = t.toDouble(&ok) / divisor;
    if (!ok || v < 0 || v > 1) {
        if (error)
            *error = QCoreApplication::translate("stepcom::FaultInjector",
                                                 "'%1' is not a share between 0 and 1 (or 0%-100%)")
                         .arg(text);
        return std::nullopt;
    }
    return v;
}

bool FaultInjector::parseShareAndValue(const QString &text, double *share, int *value,
                                       QString *error)
{
    const int colon = int(text.indexOf(QLatin1Char(':')));
    const auto s = parseShare(colon < 0 ? text : text.left(colon), error);
    if (!s)
        return false;
    bool ok = colon >= 0;
    const int v = ok ? text.mid(colon + 1).toInt(&ok) : 0;
    if (!ok || v < 0) {
        if (error)
            *error = QCoreApplication::translate("stepcom::FaultInjector",
                                                 "'%1': expected SHARE:NUMBER, e.g. 0.1:500")
                         .arg(text);
        return false;
    }
    *share = *s;
    *value = v;
    return true;
}

} // namespace stepcom
