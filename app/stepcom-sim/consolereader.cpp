#include "consolereader.h"

#include <QSocketNotifier>

#ifdef Q_OS_UNIX
#include <unistd.h>
#else
#include <QMetaObject>
#include <io.h>
#include <iostream>
#include <string>
#include <thread>
#endif

namespace stepcom {

ConsoleReader::ConsoleReader(QObject *parent)
    : QObject(parent)
{
#ifdef Q_OS_UNIX
    m_notifier = new QSocketNotifier(STDIN_FILENO, QSocketNotifier::Read, this);
    connect(m_notifier, &QSocketNotifier::activated, this, &ConsoleReader::readAvailable);
#else
    // No notifier for a console handle: a reader thread hands each line to the event loop.
    std::thread([this] {
        std::string line;
        while (std::getline(std::cin, line)) {
            const QString text = QString::fromLocal8Bit(line.c_str());
            QMetaObject::invokeMethod(this, [this, text] { Q_EMIT lineRead(text); });
        }
        QMetaObject::invokeMethod(this, [this] { Q_EMIT endOfInput(); });
    }).detach();
#endif
}

ConsoleReader::~ConsoleReader() = default;

bool ConsoleReader::stdinIsTerminal()
{
#ifdef Q_OS_UNIX
    return ::isatty(STDIN_FILENO) == 1;
#else
    return _isatty(_fileno(stdin)) != 0;
#endif
}

void ConsoleReader::readAvailable()
{
#ifdef Q_OS_UNIX
    char chunk[1024];
    const ssize_t n = ::read(STDIN_FILENO, chunk, sizeof chunk);
    if (n <= 0) {
        m_notifier->setEnabled(false);
        if (!m_buffer.isEmpty()) {
            m_buffer.append('\n');
            emitLines();
        }
        Q_EMIT endOfInput();
        return;
    }
    m_buffer.append(chunk, n);
    emitLines();
#endif
}

void ConsoleReader::emitLines()
{
    qsizetype end = 0;
    while ((end = m_buffer.indexOf('\n')) >= 0) {
        const QByteArray line = m_buffer.left(end);
        m_buffer.remove(0, end + 1);
        Q_EMIT lineRead(QString::fromLocal8Bit(line).trimmed());
    }
}

} // namespace stepcom
