#include "support/supportbundle.h"

#include "commissioning/checklistfile.h"

#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <QSerialPortInfo>
#include <QStandardPaths>
#include <QSysInfo>

#include <quazip.h>
#include <quazipfile.h>

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

bool SupportBundle::create(const QString &zipPath, const BundleInput &input, QStringList *contents,
                           QString *error)
{
    // name inside → file outside (or text), in the order the README lists them
    struct Item
    {
        QString name;
        QString source;
        QByteArray text;
        QString what;
    };
    QList<Item> items;
    items << Item{QStringLiteral("system.txt"),
                  {},
                  systemText(input).toUtf8(),
                  QStringLiteral("StepCom's and Qt's versions, the OS, the serial adapters seen")};
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
    QString readme =
        QStringLiteral("StepCom support bundle, made %1 by StepCom %2.\n\n"
                       "Session logs of the last %3 day(s); replay them with `stepcomctl replay "
                       "THIS.zip --events` or in the window (File > Open session log).\n\n")
            .arg(input.now.toString(Qt::ISODate), QStringLiteral(STEPCOM_VERSION))
            .arg(input.days);
    for (const Item &item : std::as_const(items))
        readme += QStringLiteral("%1\n    %2\n").arg(item.name, item.what);
    items.prepend(Item{QStringLiteral("README.txt"), {}, readme.toUtf8(), {}});

    QuaZip zip(zipPath);
    if (!zip.open(QuaZip::mdCreate)) {
        *error = tr("cannot create %1 (zip error %2)").arg(zipPath).arg(zip.getZipError());
        return false;
    }
    for (const Item &item : std::as_const(items)) {
        QuaZipFile out(&zip);
        QuaZipNewInfo info(item.name);
        if (!item.source.isEmpty())
            info = QuaZipNewInfo(item.name, item.source);
        if (!out.open(QIODevice::WriteOnly, info)) {
            *error = tr("cannot write %1 into %2").arg(item.name, zipPath);
            return false;
        }
        bool ok = true;
        if (item.source.isEmpty()) {
            ok = out.write(item.text) == item.text.size();
        } else {
            QFile in(item.source);
            ok = in.open(QIODevice::ReadOnly) && copyInto(in, out);
        }
        out.close();
        if (!ok || out.getZipError() != 0) {
            *error = tr("cannot write %1 into %2").arg(item.name, zipPath);
            return false;
        }
        if (contents)
            *contents << item.name;
    }
    zip.close();
    if (zip.getZipError() != 0) {
        *error = tr("cannot finish %1 (zip error %2)").arg(zipPath).arg(zip.getZipError());
        return false;
    }
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
