#pragma once

#include <QCoreApplication>
#include <QDateTime>
#include <QFileInfoList>
#include <QString>
#include <QStringList>

#include <functional>

namespace stepcom {

// What goes into a support bundle.
struct BundleInput
{
    QString logDirectory; // the session logs (SupportBundle::defaultLogDirectory())
    int days = 7;         // logs changed within the last `days` days
    QString profilePath;  // the open profile (and its checklist beside it), if any
    QStringList settingsFiles;
    QString serialByIdDirectory = QStringLiteral("/dev/serial/by-id");
    QDateTime now = QDateTime::currentDateTime();
    // The commissioning report of the machine, made by the caller (MachineReport's
    // selfContainedHtml(), the core draws nothing): report.html inside, and `reportSheets`
    // (MachineReport::sheetLines()) say in the README what it covers. Without one, `noReport`
    // says in the README why there is none.
    QByteArray reportHtml;
    QStringList reportSheets;
    QString noReport;
};

// One .zip a technician sends to support: the session logs of the last days, the
// open profile and its checklist, the machine's commissioning report, the settings, StepCom's
// and Qt's versions, the OS and the serial adapters seen, and a README.txt saying what is
// inside. Read back, its logs open for replay (extract(), then ReplayLog). The window's Help →
// Create support bundle… and `stepcomctl bundle` make the same file.
class SupportBundle
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::SupportBundle)
public:
    // create() on a thread of its own (the window): how far it got, and a way to stop it.
    struct Callbacks
    {
        // Bytes put into the zip so far of all it takes; from create()'s thread, never less
        // than the last call, the last one done == total.
        std::function<void(qint64 done, qint64 total)> progress;
        std::function<bool()> cancelled; // asked between chunks; true stops it, nothing left
    };
    // Where the window writes its session logs and its settings, whichever program asks.
    static QString defaultLogDirectory();
    static QStringList defaultSettingsFiles();
    // The logs a bundle of `input` takes, oldest first (their sizes for the dialog).
    static QFileInfoList logsFor(const BundleInput &input);
    // "StepCom 0.1.0, Qt 6.4.2 (built with 6.4.2), Debian GNU/Linux 12 (bookworm), …" and the
    // adapters: the text of system.txt.
    static QString systemText(const BundleInput &input);

    // Writes the zip; false and why not ("cancelled" when the callbacks said so). `contents`
    // (optional) gets the names inside. Written beside zipPath under another name and renamed when
    // complete: a bundle that failed or was cancelled leaves no file, and a file of that name stays
    // as it was.
    static bool create(const QString &zipPath, const BundleInput &input, QStringList *contents,
                       QString *error, const Callbacks &callbacks = {});
    // The session logs inside a bundle ("logs/…"), oldest first; empty and why when it is not
    // a bundle.
    static QStringList logs(const QString &zipPath, QString *error);
    // Copies one entry out into `directory`; the path written, or empty and why not.
    static QString extract(const QString &zipPath, const QString &entry, const QString &directory,
                           QString *error);
};

} // namespace stepcom
