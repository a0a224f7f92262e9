// The application icon: the SVG the window shows (compiled in, drawn by Qt's SVG icon engine
// plugin) is readable at the smallest size, and the PNGs rendered at build time for the hicolor
// theme are that same drawing at their sizes.
#include <QDir>
#include <QGuiApplication>
#include <QIcon>
#include <QImage>
#include <QTest>

namespace {

bool near(QColor a, QColor b)
{
    return qAbs(a.red() - b.red()) < 40 && qAbs(a.green() - b.green()) < 40 &&
           qAbs(a.blue() - b.blue()) < 40;
}

const QColor tile(0x1d, 0x4e, 0x89);
const QColor shaft(0xf5, 0xa6, 0x23);

} // namespace

class TestIcon : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void windowIcon_data()
    {
        QTest::addColumn<int>("size");
        for (int size : {16, 32, 64})
            QTest::addRow("%d px", size) << size;
    }
    void windowIcon()
    {
        QFETCH(int, size);
        const QIcon icon(QStringLiteral(":/icons/stepcom.svg"));
        QVERIFY(!icon.isNull());
        const QImage image = icon.pixmap(size, size).toImage();
        QCOMPARE(image.size(), QSize(size, size));
        // Transparent outside the rounded tile, blue tile at the edge, white flange, orange shaft.
        QCOMPARE(qAlpha(image.pixel(0, 0)), 0);
        QVERIFY(near(image.pixelColor(size / 2, size / 32), tile));
        QVERIFY(near(image.pixelColor(size / 2, size * 3 / 16), Qt::white));
        QVERIFY(near(image.pixelColor(size / 2, size / 2), shaft));
    }

#ifdef STEPCOM_ICON_DIR
    void hicolorPngs_data()
    {
        QTest::addColumn<int>("size");
        for (int size : {16, 24, 32, 48, 64, 128, 256})
            QTest::addRow("%d px", size) << size;
    }
    void hicolorPngs()
    {
        QFETCH(int, size);
        const QString path = QStringLiteral(STEPCOM_ICON_DIR "/%1x%1/apps/stepcom.png").arg(size);
        QImage png(path);
        QVERIFY2(!png.isNull(), qPrintable(path));
        QCOMPARE(png.size(), QSize(size, size));
        const QImage svg = QIcon(QStringLiteral(":/icons/stepcom.svg"))
                               .pixmap(size, size)
                               .toImage()
                               .convertToFormat(QImage::Format_ARGB32);
        png = png.convertToFormat(QImage::Format_ARGB32);
        int differing = 0;
        for (int y = 0; y < size; ++y) {
            for (int x = 0; x < size; ++x) {
                const QRgb a = png.pixel(x, y);
                const QRgb b = svg.pixel(x, y);
                if (qAbs(qAlpha(a) - qAlpha(b)) > 8 || (qAlpha(a) > 0 && !near(a, b)))
                    ++differing;
            }
        }
        QVERIFY2(differing <= size * size / 100, qPrintable(QString::number(differing)));
    }
#endif
};

#include "testregistry.h"
STEPCOM_TEST(TestIcon, Gui)
#include "tst_icon.moc"
