#include "report/reportfile.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QFileInfo>
#include <QImage>
#include <QPageLayout>
#include <QPdfWriter>
#include <QSaveFile>
#include <QTextDocument>

namespace stepcom::ReportFile {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("stepcom::ReportFile", text);
}

QString cannotWrite(const QString &path, const QSaveFile &file)
{
    return tr("cannot write %1: %2").arg(path, file.errorString());
}

} // namespace

QString write(const QString &path, const QString &title,
              const std::function<std::unique_ptr<QTextDocument>()> &document,
              const std::function<QString()> &html)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    const bool pdf = suffix == QLatin1String("pdf");
    if (!pdf && suffix != QLatin1String("html") && suffix != QLatin1String("htm"))
        return tr("%1: the report is written as .pdf or .html, not .%2").arg(path, suffix);
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return cannotWrite(path, file);
    if (pdf) {
        QPdfWriter writer(&file);
        writer.setPageSize(QPageSize(QPageSize::A4));
        writer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
        writer.setResolution(300);
        writer.setTitle(title);
        writer.setCreator(QStringLiteral("StepCom %1").arg(QStringLiteral(STEPCOM_VERSION)));
        document()->print(&writer);
    } else {
        const QByteArray bytes = html().toUtf8();
        if (file.write(bytes) != bytes.size())
            return cannotWrite(path, file);
    }
    if (file.error() != QFileDevice::NoError || !file.commit())
        return cannotWrite(path, file);
    return {};
}

QString pngDataUrl(const QImage &image)
{
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    image.save(&buffer, "PNG");
    return QStringLiteral("data:image/png;base64,") + QString::fromLatin1(png.toBase64());
}

} // namespace stepcom::ReportFile
