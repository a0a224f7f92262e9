#pragma once

#include "report/reportinput.h"

#include <QCoreApplication>

#include <memory>

class QTextDocument;

namespace stepcom {

// The sheet that goes into the machine's documentation: controller and link, every parameter
// with unit and register, input wiring, homing order, the arc and line setup with an XY picture,
// the mode, date and notes. Rendered with QTextDocument; text follows the active translator.
// Made from a profile file, it says so in its title, under it and in the controller section.
class CommissioningReport
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::CommissioningReport)
public:
    explicit CommissioningReport(ReportInput input);

    // HTML body; the XY picture is referenced as `imageSource`.
    QString html(const QString &imageSource) const;
    // The sections under the title, for a document of several devices (MachineReport).
    QString body(const QString &imageSource) const;
    // A document with the picture as a resource, ready to print.
    std::unique_ptr<QTextDocument> document() const;
    QImage picture() const;
    // "Commissioning report", or "... (from a profile file)".
    QString title() const;

    // By the file's suffix (.pdf, .html/.htm); atomic; empty on success, else why not.
    QString write(const QString &path) const;

private:
    QString text(const char *key) const; // value with unit or enum label, "—" when unknown
    QString label(const Parameter &p) const;
    QString controllerSection() const;
    QString parameterSection() const;
    QString wiringSection() const;
    QString interpolationSection(const QString &imageSource) const;
    QString fileSection() const; // made from a file: what of it this map cannot show

    ReportInput m_in;
};

} // namespace stepcom
