#pragma once

#include <QByteArray>
#include <QObject>

QT_BEGIN_NAMESPACE
class QSocketNotifier;
QT_END_NAMESPACE

namespace stepcom {

// Reads standard input line by line without blocking the event loop.
class ConsoleReader : public QObject
{
    Q_OBJECT
public:
    explicit ConsoleReader(QObject *parent = nullptr);
    ~ConsoleReader() override;
    // Whether standard input is a terminal (then the console is on by default).
    static bool stdinIsTerminal();

Q_SIGNALS:
    void lineRead(const QString &line);
    void endOfInput();

private:
    void readAvailable();
    void emitLines();

    QSocketNotifier *m_notifier = nullptr;
    QByteArray m_buffer;
};

} // namespace stepcom
