#pragma once

// The layout checks of the window's suites (tst_layoutfit: pages, strip and status bar;
// tst_dialogfit: the dialogs): every visible widget's text whole, inside its parent, nothing
// scrolling sideways, a dialog inside the screen. Problems are collected, then reported at once.

#include <QString>
#include <QStringList>

class QWidget;

namespace stepcom::test {

// The path of object names (or class names) from the window down to `w`.
QString describe(const QWidget *w);
// How many pixels the text `w` shows is wider than its room (0 or less: it fits; 0 for a widget
// whose text cannot be cut), and the text in `what`.
int overflow(const QWidget *w, QString *what);

class LayoutChecks
{
protected:
    QStringList m_problems;

    void problem(const QString &where, const QString &what);
    // The problems found, a line each, for QVERIFY2.
    QString report() const;
    // Every visible widget of `top`: its text fits, it lies inside its parent, nothing
    // scrolls sideways.
    void checkTree(QWidget *top, const QString &context);
    // A dialog or tool window shown over the window: inside the screen, and its tree as above.
    void checkDialog(QWidget *dialog, const QString &name);
    // A page shown for the first time lays itself out in rounds of posted layout requests
    // (its minimum grows, then its parents' layouts follow): judge the result, not a round.
    static void settle();
};

} // namespace stepcom::test
