#pragma once

#include <QString>

#include <functional>
#include <memory>

class QImage;
class QTextDocument;

namespace stepcom::ReportFile {

// Writes a report to `path` by its suffix: .pdf prints `document()` on A4, .html/.htm writes
// `html()` as one self-contained file. Through QSaveFile: nothing half-written. Empty when
// written, else what went wrong, naming the path.
QString write(const QString &path, const QString &title,
              const std::function<std::unique_ptr<QTextDocument>()> &document,
              const std::function<QString()> &html);

// A picture that travels inside an HTML file ("data:image/png;base64,...").
QString pngDataUrl(const QImage &image);

} // namespace stepcom::ReportFile
