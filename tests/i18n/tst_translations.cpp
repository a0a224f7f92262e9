// Checks .ts files: every message translated, nothing unfinished, placeholders kept.
// Usage: tst_translations FILE.ts...   (exit 0 when all are complete)
#include <QCoreApplication>
#include <QFile>
#include <QRegularExpression>
#include <QSet>
#include <QTextStream>
#include <QXmlStreamReader>

namespace {

QSet<QString> placeholders(const QString &text)
{
    static const QRegularExpression pattern(QStringLiteral("%(n|[1-9])"));
    QSet<QString> found;
    for (auto it = pattern.globalMatch(text); it.hasNext();)
        found.insert(it.next().captured(0));
    return found;
}

int check(const QString &path, QTextStream &out)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        out << path << ": cannot open: " << file.errorString() << Qt::endl;
        return 1;
    }
    QXmlStreamReader xml(&file);
    int problems = 0;
    int messages = 0;
    QString context;
    QString source;
    QString translation;
    QStringList forms;
    QString type;
    bool numerus = false;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement()) {
            const auto name = xml.name();
            if (name == QLatin1String("name")) {
                context = xml.readElementText();
            } else if (name == QLatin1String("message")) {
                numerus = xml.attributes().value(QLatin1String("numerus")) == QLatin1String("yes");
                source.clear();
                translation.clear();
                forms.clear();
                type.clear();
            } else if (name == QLatin1String("source")) {
                source = xml.readElementText();
            } else if (name == QLatin1String("translation")) {
                type = xml.attributes().value(QLatin1String("type")).toString();
                if (!numerus)
                    translation = xml.readElementText();
            } else if (name == QLatin1String("numerusform")) {
                forms << xml.readElementText();
            }
        } else if (xml.isEndElement() && xml.name() == QLatin1String("message")) {
            ++messages;
            const QString where = QStringLiteral("%1: [%2] \"%3\"").arg(path, context, source);
            if (type == QLatin1String("unfinished") || type == QLatin1String("vanished") ||
                type == QLatin1String("obsolete")) {
                out << where << ": " << type << Qt::endl;
                ++problems;
                continue;
            }
            const QStringList texts = numerus ? forms : QStringList{translation};
            if (texts.isEmpty() || std::any_of(texts.cbegin(), texts.cend(), [](const QString &t) {
                    return t.trimmed().isEmpty();
                })) {
                out << where << ": no translation" << Qt::endl;
                ++problems;
                continue;
            }
            for (const QString &t : texts) {
                if (placeholders(t) != placeholders(source)) {
                    out << where << ": placeholders differ in \"" << t << "\"" << Qt::endl;
                    ++problems;
                }
            }
        }
    }
    if (xml.hasError()) {
        out << path << ": invalid XML at line " << xml.lineNumber() << ": " << xml.errorString()
            << Qt::endl;
        return 1;
    }
    if (messages == 0) {
        out << path << ": no messages at all" << Qt::endl;
        return 1;
    }
    out << path << ": " << messages << " messages, " << problems << " problems" << Qt::endl;
    return problems == 0 ? 0 : 1;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QTextStream out(stdout);
    int failed = 0;
    const QStringList files = app.arguments().mid(1);
    for (const QString &f : files)
        failed += check(f, out);
    out << (files.size() - failed) << " passed, " << failed << " failed" << Qt::endl;
    return failed == 0 && !files.isEmpty() ? 0 : 1;
}
