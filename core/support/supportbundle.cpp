#include "support/supportbundle.h"

#include "commissioning/checklistfile.h"

#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <QSerialPortInfo>
#include <QStandardPaths>
#include <QSysInfo>
#include <QTemporaryFile>

#include <quazip.h>
#include <quazipfile.h>

#include <filesystem>

namespace stepcom {

namespace {

constexpr qint64 kChunk = 256 * 1024;

bool copyInto(QIODevice &from, QIODevice &to)
{
    QByteArray buffer;
    while (!from.atEnd()) {
        buffer = from.read(kChunk);
        if (buffer.isEmpty() || to.write(buffer) != buffer.size())
            return false;
    }
    return true;
}

} // namespace

QString SupportBundle::defaultLogDirectory()
{
    return QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation) +
           QStringLiteral("/StepCom/stepcom/logs");
}

QStringList SupportBundle::defaultSettingsFiles()
{
    const QDir dir(QStandardPaths::writableLocation(QStandardPaths::GenericConfigLocation) +
                   QStringLiteral("/StepCom"));
    QStringList files;
    for (const QFileInfo &info : dir.entryInfoList({QStringLiteral("*.conf")}, QDir::Files))
        files << info.absoluteFilePath();
    return files;
}

QFileInfoList SupportBundle::logsFor(const BundleInput &input)
{
    const QDateTime since = input.now.addDays(-std::max(0, input.days));
    QFileInfoList out;
    const QDir dir(input.logDirectory);
    for (const QFileInfo &info :
         dir.entryInfoList({QStringLiteral("*.log")}, QDir::Files, QDir::Name)) {
        if (info.lastModified() >= since)
            out << info;
    }
    return out;
}

QString SupportBundle::systemText(const BundleInput &input)
{
    QString text = QStringLiteral("StepCom: %1\nQt: %2 (built with %3)\nOS: %4 (%5 %6, %7)\n")
                       .arg(QStringLiteral(STEPCOM_VERSION), QLatin1String(qVersion()),
                            QLatin1String(QT_VERSION_STR), QSysInfo::prettyProductName(),
                            QSysInfo::kernelType(), QSysInfo::kernelVersion(),
                            QSysInfo::currentCpuArchitecture());
    text += QStringLiteral("Created: %1\n\nSerial adapters seen (%2):\n")
                .arg(input.now.toString(Qt::ISODate), input.serialByIdDirectory);
    const QDir byId(input.serialByIdDirectory);
    const QFileInfoList links =
        byId.entryInfoList(QDir::Files | QDir::System | QDir::NoDotAndDotDot);
    for (const QFileInfo &link : links)
        text += QStringLiteral("  %1 -> %2\n").arg(link.fileName(), link.symLinkTarget());
    if (links.isEmpty())
        text += QStringLiteral("  (none)\n");
    text += QStringLiteral("\nSerial ports listed by Qt:\n");
    const QList<QSerialPortInfo> ports = QSerialPortInfo::availablePorts();
    for (const QSerialPortInfo &p : ports)
        text += QStringLiteral("  %1  %2  %3  serial %4\n")
                    .arg(p.systemLocation(), p.description(), p.manufacturer(), p.serialNumber());
    if (ports.isEmpty())
        text += QStringLiteral("  (none)\n");
    return text;
}

namespace {

// name inside → file outside (or text), in the order the README lists them
struct Item
{
    QString name;
    QString source;
    QByteArray text;
    QString what;
    qint64 size() const { return source.isEmpty() ? text.size() : QFileInfo(source).size(); }
};

// Puts the items into the zip at `path`; false and why not, or false when cancelled.
bool writeZip(const QString &path, const QList<Item> &items, QStringList *contents,
              const SupportBundle::Callbacks &callbacks, QString *error)
{
    qint64 total = 0;
    for (const Item &item : items)
        total += item.size();
    qint64 done = 0;
    const auto advance = [&](qint64 bytes) {
        done = std::min(total, done + bytes);
        if (callbacks.progress)
            callbacks.progress(done, total);
    };
    const auto cancelled = [&] { return callbacks.cancelled && callbacks.cancelled(); };
    QuaZip zip(path);
    if (!zip.open(QuaZip::mdCreate)) {
        *error =
            SupportBundle::tr("cannot create the zip file (zip error %1)").arg(zip.getZipError());
        return false;
    }
    for (const Item &item : items) {
        QuaZipFile out(&zip);
        QuaZipNewInfo info(item.name);
        if (!item.source.isEmpty())
            info = QuaZipNewInfo(item.name, item.source);
        if (!out.open(QIODevice::WriteOnly, info)) {
            *error = SupportBundle::tr("cannot write %1 into the bundle").arg(item.name);
            return false;
        }
        bool ok = true;
        if (item.source.isEmpty()) {
            ok = out.write(item.text) == item.text.size();
            advance(item.text.size());
        } else {
            QFile in(item.source);
            ok = in.open(QIODevice::ReadOnly);
            QByteArray buffer;
            while (ok && !in.atEnd() && !cancelled()) {
                buffer = in.read(kChunk);
                ok = !buffer.isEmpty() && out.write(buffer) == buffer.size();
                advance(buffer.size());
            }
        }
        out.close();
        if (cancelled())
            return false;
        if (!ok || out.getZipError() != 0) {
            *error = SupportBundle::tr("cannot write %1 into the bundle").arg(item.name);
            return false;
        }
        if (contents)
            *contents << item.name;
    }
    zip.close();
    if (zip.getZipError() != 0) {
        *error =
            SupportBundle::tr("cannot finish the zip file (zip error %1)").arg(zip.getZipError());
        return false;
    }
    advance(total - done); // a file that shrank meanwhile: the end is the end
    return true;
}

} // namespace

bool SupportBundle::create(const QString &zipPath, const BundleInput &input, QStringList *contents,
                           QString *error, const Callbacks &callbacks)
{
    QList<Item> items;
    items << Item{QStringLiteral("system.txt"),
                  {},
                  systemText(input).toUtf8(),
                  QStringLiteral("StepCom's and Qt's versions, the OS, the serial adapters seen")};
    if (!input.reportHtml.isEmpty())
        items << Item{QStringLiteral("report.html"),
                      {},
                      input.reportHtml,
                      QStringLiteral("the commissioning report of the machine (open it in a web "
                                     "browser), %1 controller sheet(s):\n        %2")
                          .arg(input.reportSheets.size())
                          .arg(input.reportSheets.join(QStringLiteral("\n        ")))};
    for (const QFileInfo &log : logsFor(input))
        items << Item{QStringLiteral("logs/") + log.fileName(),
                      log.absoluteFilePath(),
                      {},
                      QStringLiteral("session log, %1 bytes, last written %2")
                          .arg(log.size())
                          .arg(log.lastModified().toString(Qt::ISODate))};
    if (!input.profilePath.isEmpty()) {
        if (!QFileInfo::exists(input.profilePath)) {
            *error = tr("the profile %1 does not exist").arg(input.profilePath);
            return false;
        }
        items << Item{QStringLiteral("profile/") + QFileInfo(input.profilePath).fileName(),
                      input.profilePath,
                      {},
                      QStringLiteral("the open profile")};
        const QString checklist = ChecklistFile::pathFor(input.profilePath);
        if (QFileInfo::exists(checklist))
            items << Item{QStringLiteral("profile/") + QFileInfo(checklist).fileName(),
                          checklist,
                          {},
                          QStringLiteral("the profile's commissioning checklist")};
    }
    for (const QString &settings : input.settingsFiles) {
        if (QFileInfo::exists(settings))
            items << Item{QStringLiteral("settings/") + QFileInfo(settings).fileName(),
                          settings,
                          {},
                          QStringLiteral("StepCom's settings (it keeps no passwords)")};
    }
    const bool logs = std::any_of(items.cbegin(), items.cend(), [](const Item &item) {
        return item.name.startsWith(QLatin1String("logs/"));
    });
    QString readme =
        QStringLiteral("StepCom support bundle, made %1 by StepCom %2.\n\n")
            .arg(input.now.toString(Qt::ISODate), QStringLiteral(STEPCOM_VERSION)) +
        (logs ? QStringLiteral("Session logs of the last %1 day(s); replay them with `stepcomctl "
                               "replay THIS.zip --events` or in the window (File > Open session "
                               "log).\n\n")
                    .arg(input.days)
              : QStringLiteral("No session log of the last %1 day(s) was found in %2.\n\n")
                    .arg(input.days)
                    .arg(QDir::toNativeSeparators(input.logDirectory)));
    for (const Item &item : std::as_const(items))
        readme += QStringLiteral("%1\n    %2\n").arg(item.name, item.what);
    if (input.reportHtml.isEmpty())
        readme +=
            QStringLiteral("\nNo commissioning report of the machine: %1.\n")
                .arg(input.noReport.isEmpty() ? QStringLiteral("none was made") : input.noReport);
    items.prepend(Item{QStringLiteral("README.txt"), {}, readme.toUtf8(), {}});

    // Written under another name beside it, renamed when whole: nothing half-written is left,
    // and a bundle of the same name stays as it was until the new one is complete.
    const QFileInfo target(zipPath);
    QTemporaryFile partial(target.absoluteDir().filePath(QLatin1Char('.') + target.fileName() +
                                                         QStringLiteral(".XXXXXX.part")));
    if (!partial.open()) {
        *error = tr("cannot create %1: %2").arg(zipPath, partial.errorString());
        return false;
    }
    partial.close(); // QuaZip writes it by its name; the object removes it unless renamed
    QStringList names;
    const bool written = writeZip(partial.fileName(), items, &names, callbacks, error);
    if (callbacks.cancelled && callbacks.cancelled()) {
        *error = tr("cancelled");
        return false;
    }
    if (!written) {
        *error = QStringLiteral("%1: %2").arg(zipPath, *error);
        return false;
    }
    std::error_code failed;
    std::filesystem::rename(std::filesystem::path(partial.fileName().toStdU16String()),
                            std::filesystem::path(zipPath.toStdU16String()), failed);
    if (failed) {
        *error = tr("cannot write %1: %2")
                     .arg(zipPath, QString::fromLocal8Bit(failed.message().c_str()));
        return false;
    }
    partial.setAutoRemove(false); // it is the bundle now
    if (contents)
        *contents << names;
    return true;
}

QStringList SupportBundle::logs(const QString &zipPath, QString *error)
{
    QuaZip zip(zipPath);
    if (!zip.open(QuaZip::mdUnzip)) {
        *error = tr("%1 is not a zip file (or cannot be read)").arg(zipPath);
        return {};
    }
    QStringList names =
        zip.getFileNameList().filter(QRegularExpression(QStringLiteral("^logs/.+\\.log$")));
    std::sort(names.begin(), names.end()); // names begin with their time
    if (names.isEmpty())
        *error = zip.getFileNameList().contains(QStringLiteral("README.txt"))
                     ? tr("the bundle %1 holds no session log").arg(zipPath)
                     : tr("%1 is not a StepCom support bundle").arg(zipPath);
    return names;
}

QString SupportBundle::extract(const QString &zipPath, const QString &entry,
                               const QString &directory, QString *error)
{
    QuaZip zip(zipPath);
    if (!zip.open(QuaZip::mdUnzip) || !zip.setCurrentFile(entry)) {
        *error = tr("%1 holds no %2").arg(zipPath, entry);
        return {};
    }
    QuaZipFile in(&zip);
    const QString path = QDir(directory).filePath(QFileInfo(entry).fileName());
    QFile out(path);
    if (!in.open(QIODevice::ReadOnly) || !out.open(QIODevice::WriteOnly) || !copyInto(in, out)) {
        *error = tr("cannot copy %1 out of %2 into %3").arg(entry, zipPath, directory);
        return {};
    }
    return path;
}

} // namespace stepcom
