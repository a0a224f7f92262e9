#pragma once

#include <QString>
#include <QStringList>
#include <QTextBlock>

class QTextDocument;

namespace stepcom {

// Where the user guide is and which of its sections answers F1 on each page. The guide is the
// Markdown of docs/ (guide.md, guide.zh_CN.md and their images): installed with the program
// under share/stepcom/guide, or the source tree's copy when the program runs from its build.
class UserGuide
{
public:
    // Directories that may hold the guide, in the order they are tried.
    static QStringList searchDirectories();
    // "guide.md" or "guide.zh_CN.md".
    static QString fileName(const QString &language);
    // The guide in this language (English when it has none); empty when none is found.
    static QString file(const QString &language);

    // The topics F1 knows: a page's class name ("stepcom::ConnectionPage") or a dialog's topic.
    static QStringList topics();
    // The heading F1 on `topic` opens, as the guide in `language` spells it; the guide's title
    // for a topic it does not know.
    static QString heading(const QString &topic, const QString &language);
    static QString title(const QString &language);

    // The block of the heading whose text is `heading` (invalid when there is none).
    static QTextBlock findHeading(const QTextDocument &document, const QString &heading);
    // The heading a GitHub-style anchor ("#the-connection-page") names; invalid when none.
    static QTextBlock findAnchor(const QTextDocument &document, const QString &anchor);
    // GitHub's anchor of a heading: lower case, punctuation dropped, spaces to dashes.
    static QString anchor(const QString &heading);
};

} // namespace stepcom
