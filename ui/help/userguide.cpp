#include "help/userguide.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QTextDocument>

namespace stepcom {

namespace {

struct Section
{
    const char *topic;
    const char *english;
    const char *chinese;
};

// The headings of docs/guide.md and docs/guide.zh_CN.md that F1 opens; tst_userguide checks
// that every one exists in both guides.
const Section sections[] = {
    {"stepcom::ConnectionPage", "The Connection page", "连接页面"},
    {"stepcom::MotorPage", "Setting up a motor", "设定电机参数"},
    {"stepcom::MotionPage", "Jogging and homing", "点动与回零"},
    {"stepcom::PendantDialog", "A phone as the pendant", "手机作为手持器"},
    {"stepcom::InputsPage", "Limit and home inputs", "限位与原点信号"},
    {"stepcom::InterpolationPage", "Arc and line interpolation", "圆弧插补与直线插补"},
    {"stepcom::ModesPage", "Special modes", "特殊功能模式"},
    {"stepcom::DevicePage", "The device: id, baud, flash, factory settings",
     "设备：ID、波特率、数据保存、出厂设置"},
    {"stepcom::PlotPage", "Live monitoring and plots", "实时监视与曲线图"},
    {"stepcom::SequencePage", "Running a cycle", "运行工作循环"},
    {"stepcom::ChecklistPage", "Commissioning a machine step by step", "逐步调试一台机器"},
    {"stepcom::BusScanDialog", "Finding a forgotten id or baud rate", "忘记了设备 ID 或波特率"},
    {"stepcom::IdAssistantDialog", "Several controllers on one line", "一条总线上的多台控制器"},
    {"stepcom::ProfileCompareDialog", "Profiles and the commissioning report",
     "参数文件与调试报告"},
    {"stepcom::TrafficView", "The traffic log and the session log files", "通信记录与会话日志文件"},
    {"stepcom::SupportBundleDialog", "Help from afar: replay a session, send a support bundle",
     "远程支持：回放会话、发送支持包"},
};

} // namespace

QStringList UserGuide::searchDirectories()
{
    const QString appDir = QCoreApplication::applicationDirPath();
    QStringList dirs;
    // Installed: <prefix>/bin/stepcom and <prefix>/share/stepcom/guide.
    dirs << QDir::cleanPath(appDir + QStringLiteral("/../" STEPCOM_GUIDE_INSTALL_DIR));
    // Run from the build tree: the source tree's docs/, always the newest.
    if (QDir::cleanPath(appDir).startsWith(QDir::cleanPath(QStringLiteral(STEPCOM_BINARY_DIR))))
        dirs << QStringLiteral(STEPCOM_SOURCE_DIR "/docs");
    return dirs;
}

QString UserGuide::fileName(const QString &language)
{
    return language == QLatin1String("en") || language.isEmpty()
               ? QStringLiteral("guide.md")
               : QStringLiteral("guide.%1.md").arg(language);
}

QString UserGuide::file(const QString &language)
{
    for (const QString &name : {fileName(language), fileName(QStringLiteral("en"))}) {
        for (const QString &dir : searchDirectories()) {
            const QFileInfo info(QDir(dir).filePath(name));
            if (info.isFile() && info.isReadable())
                return info.absoluteFilePath();
        }
    }
    return {};
}

QStringList UserGuide::topics()
{
    QStringList out;
    for (const Section &s : sections)
        out << QString::fromLatin1(s.topic);
    return out;
}

QString UserGuide::title(const QString &language)
{
    return language == QLatin1String("zh_CN") ? QStringLiteral("StepCom 使用手册")
                                              : QStringLiteral("StepCom user guide");
}

QString UserGuide::heading(const QString &topic, const QString &language)
{
    for (const Section &s : sections) {
        if (topic == QLatin1String(s.topic))
            return language == QLatin1String("zh_CN") ? QString::fromUtf8(s.chinese)
                                                      : QString::fromUtf8(s.english);
    }
    return title(language);
}

QTextBlock UserGuide::findHeading(const QTextDocument &document, const QString &heading)
{
    for (QTextBlock b = document.begin(); b.isValid(); b = b.next()) {
        if (b.blockFormat().headingLevel() > 0 && b.text().trimmed() == heading)
            return b;
    }
    return {};
}

QTextBlock UserGuide::findAnchor(const QTextDocument &document, const QString &anchorName)
{
    for (QTextBlock b = document.begin(); b.isValid(); b = b.next()) {
        if (b.blockFormat().headingLevel() > 0 && anchor(b.text()) == anchorName)
            return b;
    }
    return {};
}

QString UserGuide::anchor(const QString &heading)
{
    QString out;
    for (const QChar c : heading.trimmed().toLower()) {
        if (c.isLetterOrNumber() || c == QLatin1Char('-') || c == QLatin1Char('_'))
            out += c;
        else if (c == QLatin1Char(' '))
            out += QLatin1Char('-');
    }
    return out;
}

} // namespace stepcom
