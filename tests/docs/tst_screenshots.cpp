#include "base/language.h"
#include "laptopscenes.h"
#include "scenes.h"
#include "session/devicesession.h"
#include "shooter.h"
#include "window/mainwindow.h"
#include "window/windowprobe.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <memory>
#include <vector>

using namespace stepcom;

// stepcom-shots, run into a scratch directory: a picture of every page of the window and of
// every scene, in both languages, none of them blank; the committed pictures are the same set
// (regenerate with scripts/screenshots.sh when a page or scene is added); every picture the
// guides and the README show exists.
class TestScreenshots : public QObject
{
    Q_OBJECT
    QTemporaryDir out;
    QStringList expected; // file names, the same in every language

    static QDir source() { return QDir(QStringLiteral(STEPCOM_SOURCE_DIR)); }
    static QSet<QString> pngs(const QDir &dir)
    {
        const QStringList list = dir.entryList({QStringLiteral("*.png")}, QDir::Files);
        return {list.begin(), list.end()};
    }
    // Not blank: many colours, and no colour covering nearly all of it.
    static QString blankness(const QImage &image)
    {
        QHash<QRgb, int> counts;
        int samples = 0;
        for (int y = 0; y < image.height(); y += 7) {
            for (int x = 0; x < image.width(); x += 7) {
                ++counts[image.pixel(x, y)];
                ++samples;
            }
        }
        int top = 0;
        for (int n : std::as_const(counts))
            top = std::max(top, n);
        if (counts.size() < 16)
            return QStringLiteral("only %1 colours").arg(counts.size());
        if (top > samples * 97 / 100)
            return QStringLiteral("one colour covers %1% of it").arg(top * 100 / samples);
        return {};
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(QStringLiteral("StepComTest"));
        QVERIFY(out.isValid());
        // What the window has, counted here and not by the generator.
        Language::instance().setLanguage(QStringLiteral("en"));
        DeviceSession session;
        MainWindow window(&session);
        QVERIFY(WindowProbe(window).pages().size() >= 2);
        for (int i = 0; i < WindowProbe(window).pages().size(); ++i)
            expected << Shooter::pageFileName(WindowProbe(window).pages(), i);
        QCOMPARE(QSet<QString>(expected.begin(), expected.end()).size(), expected.size());
        // One generator per language, side by side: they mostly wait for the simulated motors.
        std::vector<std::unique_ptr<QProcess>> runs;
        for (const QString &language : Language::available()) {
            auto &p = runs.emplace_back(std::make_unique<QProcess>());
            p->setProcessChannelMode(QProcess::ForwardedErrorChannel);
            p->start(QStringLiteral(STEPCOM_SHOTS),
                     {QStringLiteral("--out"), out.path(), QStringLiteral("--lang"), language});
        }
        for (auto &p : runs) {
            QTRY_VERIFY_WITH_TIMEOUT(p->state() == QProcess::NotRunning, 270000);
            QCOMPARE(p->exitStatus(), QProcess::NormalExit);
            QCOMPARE(p->exitCode(), 0);
            const QString written = QString::fromUtf8(p->readAllStandardOutput());
            for (const QString &line : written.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
                const QString name = QFileInfo(line).fileName();
                if (name.startsWith(QLatin1String("scene-")) && !expected.contains(name))
                    expected << name;
            }
        }
        QVERIFY2(expected.size() > WindowProbe(window).pages().size(), "no scene was shot");
    }

    void everyPageAndSceneInEveryLanguage_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QString>("file");
        for (const QString &language : Language::available()) {
            for (const QString &file : std::as_const(expected))
                QTest::addRow("%s/%s", qPrintable(language), qPrintable(file)) << language << file;
        }
    }
    void everyPageAndSceneInEveryLanguage()
    {
        QFETCH(QString, language);
        QFETCH(QString, file);
        const QString path = QDir(out.path()).filePath(language + QLatin1Char('/') + file);
        QVERIFY2(QFile::exists(path), qPrintable(path + QStringLiteral(" was not written")));
        QImage image(path);
        QVERIFY2(!image.isNull(), qPrintable(path + QStringLiteral(" is not a PNG")));
        // Dialogs are drawn over the window: every picture is the window's size, but for the
        // ones of small laptop screens.
        const QSize laptop = laptopscenes::pictureSize(file);
        QCOMPARE(image.size(), laptop.isEmpty() ? QSize(1280, 800) : laptop);
        const QString blank = blankness(image);
        QVERIFY2(blank.isEmpty(), qPrintable(path + QStringLiteral(" looks blank: ") + blank));
    }

    void theLanguagesDiffer()
    {
        for (const QString &file : std::as_const(expected)) {
            QFile en(QDir(out.path()).filePath(QStringLiteral("en/") + file));
            QFile zh(QDir(out.path()).filePath(QStringLiteral("zh_CN/") + file));
            QVERIFY(en.open(QIODevice::ReadOnly) && zh.open(QIODevice::ReadOnly));
            QVERIFY2(en.readAll() != zh.readAll(),
                     qPrintable(file + QStringLiteral(" is the same in both languages")));
        }
    }

    void theCommittedPicturesAreCurrent()
    {
        for (const QString &language : Language::available()) {
            const QSet<QString> made = pngs(QDir(out.path()).filePath(language));
            const QSet<QString> committed =
                pngs(source().filePath(QStringLiteral("docs/images/") + language));
            QStringList missing = (made - committed).values();
            QStringList stale = (committed - made).values();
            missing.sort();
            stale.sort();
            QVERIFY2(missing.isEmpty() && stale.isEmpty(),
                     qPrintable(QStringLiteral(
                                    "docs/images/%1 is out of date (run scripts/screenshots.sh): "
                                    "missing %2; no longer made %3")
                                    .arg(language, missing.join(QLatin1String(", ")),
                                         stale.join(QLatin1String(", ")))));
        }
    }

    void everyPictureTheDocsShowExists_data()
    {
        QTest::addColumn<QString>("doc");
        for (const char *doc : {"README.md", "docs/guide.md", "docs/guide.zh_CN.md"})
            QTest::newRow(doc) << QString::fromLatin1(doc);
    }
    void everyPictureTheDocsShowExists()
    {
        QFETCH(QString, doc);
        QFile file(source().filePath(doc));
        QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(doc + QStringLiteral(" is missing")));
        const QString text = QString::fromUtf8(file.readAll());
        // ![alt](path) and <img src="path">
        static const QRegularExpression image(
            QStringLiteral("!\\[[^\\]]*\\]\\(([^)\\s]+)\\)|<img[^>]*\\bsrc=\"([^\"]+)\""));
        const QDir base = QFileInfo(file).dir();
        int count = 0;
        for (const QRegularExpressionMatch &m : image.globalMatch(text)) {
            const QString target = m.captured(1).isEmpty() ? m.captured(2) : m.captured(1);
            ++count;
            QVERIFY2(
                QFile::exists(base.filePath(target)),
                qPrintable(QStringLiteral("%1 shows %2, which does not exist").arg(doc, target)));
        }
        QVERIFY2(count > 0, qPrintable(doc + QStringLiteral(" shows no picture")));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestScreenshots, Gui)
#include "tst_screenshots.moc"
