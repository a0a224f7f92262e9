#pragma once

#include "map/registermap.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QHash>

#include <memory>

class QTextDocument;

namespace stepcom {

// Everything the commissioning sheet shows; raw values as read from the controller.
struct ReportInput
{
    RegisterMap map;
    QHash<QString, qint64> values;
    QString link; // LinkSettings::describe()
    int deviceId = 0;
    QString title; // e.g. the machine's name
    QString notes;
    QDateTime date;
    QString locale; // "zh_CN" for the map's Chinese labels, else English
};

// The sheet that goes into the machine's documentation: controller and link, every parameter
// with unit and register, input wiring, homing order, the arc and line setup with an XY picture,
// the mode, date and notes. Rendered with QTextDocument; text follows the active translator.
class CommissioningReport
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::CommissioningReport)
public:
    explicit CommissioningReport(ReportInput input);

    // HTML body; the XY picture is referenced as `imageSource`.
    QString html(const QString &imageSource) const;
    // A document with the picture as a resource, ready to print.
    std::unique_ptr<QTextDocument> document() const;
    QImage picture() const;

    // By the file's suffix (.pdf, .html/.htm); atomic; empty on success, else why not.
    QString write(const QString &path) const;
    QString writePdf(const QString &path) const;
    QString writeHtml(const QString &path) const;

private:
    QString text(const char *key) const; // value with unit or enum label, "—" when unknown
    QString label(const Parameter &p) const;
    QString controllerSection() const;
    QString parameterSection() const;
    QString wiringSection() const;
    QString interpolationSection(const QString &imageSource) const;

    ReportInput m_in;
};

} // namespace stepcom
