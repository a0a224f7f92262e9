#pragma once

#include "line/busscanner.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTextStream>

namespace stepcom {

class RegisterMap;

// `stepcomctl scan`: runs the BusScanner the window's scan dialog runs and prints every
// controller that answered (a table, or JSON with --json) on standard output, the progress on
// standard error. Exit codes: 0 found at least one, 1 none, 3 the line could not be used.
class CtlScan : public QObject
{
    Q_OBJECT
public:
    enum Exit { Found = 0, NoneFound = 1, LinkError = 3 };

    // What it found goes to `out`, why it stopped to `problems` (the runner's, kept for
    // --json's object); the progress to standard error.
    CtlScan(const BusScanner::Plan &plan, const RegisterMap &map, bool json, QTextStream &out,
            QTextStream &problems, QObject *parent = nullptr);
    void start();

Q_SIGNALS:
    void finished(int exitCode);

private:
    void onProgress(int done, int total, int baud, int deviceId);
    void onFinished(bool cancelled, const QString &error);
    void printTable() const;
    void printJson() const;

    BusScanner::Plan m_plan;
    BusScanner m_scanner;
    bool m_json;
    bool m_network;
    QElapsedTimer m_clock;
    QTextStream &m_out;
    QTextStream &m_problems;
    mutable QTextStream m_err;
};

} // namespace stepcom
