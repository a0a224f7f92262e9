#pragma once

#include "benchtypes.h"

#include <QList>
#include <QString>

namespace stepcom::bench {

// One line of the results table: a target, what was measured, what it is held against.
struct Verdict
{
    QString baud;
    QString target;
    QString measured;
    QString bound;
    QString ratio;
    // Error: it could not be measured at all (fails smoke runs too).
    enum class Result { Pass, Fail, Info, Error } result = Result::Info;
};

QList<Verdict> verdicts(const BaudResult &r);
QList<Verdict> builtinWindowVerdicts(const WindowResult &w);
QList<Verdict> trafficVerdicts(const TrafficResult &t);
QList<Verdict> busVerdicts(const BusResult &b);
QList<Verdict> scanVerdicts(const ScanResult &s);
QList<Verdict> gapVerdicts(const GapResult &g);
// (k): (a) and (b) on a controller that answers sooner than the manual's 35 ms.
QList<Verdict> answerTimeVerdicts(const BaudResult &r);
QList<Verdict> firstStatusVerdicts(const FirstStatusResult &f);
// A Markdown table; with `judged` false (smoke runs) results read "not judged".
QString table(const QList<Verdict> &rows, bool judged);
// Date, CPU and Qt version: what the numbers were measured on.
QString machineLine();
// Replaces the text between "<!-- bench:begin -->" and "<!-- bench:end -->" in `path`.
bool replaceResults(const QString &path, const QString &block, QString *error);

} // namespace stepcom::bench
