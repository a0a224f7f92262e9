// stepcom-svg2png: renders the application icon's SVG into the hicolor PNG sizes at build time,
// with Qt Svg (which StepCom needs anyway): no network and no other tool.
//   stepcom-svg2png ICON.svg OUTDIR NAME SIZE...   writes OUTDIR/<SIZE>x<SIZE>/apps/NAME.png
#include <QCoreApplication>
#include <QDir>
#include <QImage>
#include <QPainter>
#include <QSvgRenderer>
#include <QTextStream>

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QTextStream err(stderr);
    const QStringList args = QCoreApplication::arguments().mid(1);
    if (args.size() < 4) {
        err << "usage: stepcom-svg2png ICON.svg OUTDIR NAME SIZE..." << Qt::endl;
        return 2;
    }
    QSvgRenderer renderer(args.at(0));
    if (!renderer.isValid()) {
        err << "stepcom-svg2png: " << args.at(0) << ": not a valid SVG file" << Qt::endl;
        return 1;
    }
    for (const QString &sizeText : args.mid(3)) {
        bool ok = false;
        const int size = sizeText.toInt(&ok);
        if (!ok || size < 8 || size > 1024) {
            err << "stepcom-svg2png: '" << sizeText << "' is not a size from 8 to 1024" << Qt::endl;
            return 2;
        }
        QImage image(size, size, QImage::Format_ARGB32_Premultiplied);
        image.fill(Qt::transparent);
        QPainter painter(&image);
        painter.setRenderHint(QPainter::Antialiasing);
        renderer.render(&painter, QRectF(0, 0, size, size));
        painter.end();
        const QString dir = QStringLiteral("%1/%2x%2/apps").arg(args.at(1)).arg(size);
        const QString file = QStringLiteral("%1/%2.png").arg(dir, args.at(2));
        if (!QDir().mkpath(dir) || !image.save(file, "PNG")) {
            err << "stepcom-svg2png: cannot write " << file << Qt::endl;
            return 1;
        }
    }
    return 0;
}
