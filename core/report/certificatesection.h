#pragma once

#include "report/reportinput.h"

#include <QCoreApplication>

namespace stepcom {

// The parts of the commissioning report that make it a certificate: the checklist with every
// result and measurement, the software travel limits, and the places for names and signatures.
// HTML fragments in the report's table style; text follows the active translator.
class CertificateSection
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::CertificateSection)
public:
    explicit CertificateSection(const ReportInput &input);

    QString checklist() const;
    QString travelLimits() const;
    QString signatures() const;

private:
    QString measurements(const ChecklistAttempt &attempt) const;

    const ReportInput &m_in;
};

} // namespace stepcom
