#pragma once

#include "report/reportinput.h"

#include <QCoreApplication>

#include <memory>

class QTextDocument;

namespace stepcom {

// The commissioning report of a whole machine: every controller of its line in one document.
// A first page names the machine and lists the devices (id, name, link, settings fingerprint);
// then each device's sheet (CommissioningReport's sections, its own XY picture) starts on a
// new page under its id and name.
class MachineReport
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::MachineReport)
public:
    // One input per device, in the order of the line; `title` names the machine.
    MachineReport(QList<ReportInput> devices, const QString &title, const QString &notes,
                  const QString &locale);

    QString title() const;
    // The picture of device `index` is referenced as imageSources.at(index).
    QString html(const QStringList &imageSources) const;
    std::unique_ptr<QTextDocument> document() const;
    // The whole report as one file: each picture travels inside it as a data URL (what a .html
    // report holds, and report.html in a support bundle).
    QString selfContainedHtml() const;
    // One line per controller, in English, for a README: "id 1: /dev/ttyUSB0 · 9600 8N1 · id 1,
    // values as read" or "id 1 \"Machine A\": made from the profile file machine-a.json".
    QStringList sheetLines() const;
    bool isEmpty() const { return m_devices.isEmpty(); }
    // By the file's suffix (.pdf, .html/.htm); atomic; empty on success, else why not.
    QString write(const QString &path) const;

private:
    QString summary() const;
    QString heading(const ReportInput &device) const;

    QList<ReportInput> m_devices;
    QString m_title;
    QString m_notes;
    QString m_locale;
    QDateTime m_date;
};

} // namespace stepcom
