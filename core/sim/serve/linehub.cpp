#include "sim/serve/linehub.h"

#include <QFile>
#include <QFileInfo>
#include <QSocketNotifier>

#ifdef Q_OS_UNIX
#include <cerrno>
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>
#if __has_include(<pty.h>)
#include <pty.h>
#else
#include <util.h>
#endif
#endif

namespace stepcom {

namespace {

// Bounds memory when a party stops reading; a real wire would have lost the bytes long before.
constexpr qsizetype kMaxPending = 1024 * 1024;

#ifdef Q_OS_UNIX
bool makeRaw(int fd)
{
    termios t{};
    if (::tcgetattr(fd, &t) != 0)
        return false;
    ::cfmakeraw(&t);
    if (::cfgetospeed(&t) == B0)
        ::cfsetspeed(&t, B9600);
    return ::tcsetattr(fd, TCSANOW, &t) == 0;
}

bool nonBlocking(int fd)
{
    const int flags = ::fcntl(fd, F_GETFL);
    return flags >= 0 && ::fcntl(fd, F_SETFL, flags | O_NONBLOCK) == 0;
}
#endif

} // namespace

LineHub::LineHub(QObject *parent)
    : QObject(parent)
{}

LineHub::~LineHub()
{
    close();
}

bool LineHub::open(int parties, QString *error)
{
#ifdef Q_OS_UNIX
    if (isOpen() || parties < 1) {
        *error = isOpen() ? tr("the line is already open")
                          : tr("a line needs at least one party, not %1").arg(parties);
        return false;
    }
    for (int i = 0; i < parties; ++i) {
        auto *p = new Party;
        m_parties << p;
        char name[256] = {};
        if (::openpty(&p->fd, &p->slave, name, nullptr, nullptr) != 0 || !makeRaw(p->slave) ||
            !nonBlocking(p->fd)) {
            *error = tr("cannot make a pseudo-terminal: %1").arg(qt_error_string(errno));
            close();
            return false;
        }
        p->path = QString::fromLocal8Bit(name);
        p->reader = new QSocketNotifier(p->fd, QSocketNotifier::Read, this);
        connect(p->reader, &QSocketNotifier::activated, this, [this, i] { readParty(i); });
    }
    return true;
#else
    Q_UNUSED(parties)
    *error = tr("a line of pseudo-terminals needs Unix");
    return false;
#endif
}

bool LineHub::attach(const QString &path, QString *error)
{
#ifdef Q_OS_UNIX
    const int fd = ::open(QFile::encodeName(path).constData(), O_RDWR | O_NOCTTY | O_NONBLOCK);
    if (fd < 0 || !makeRaw(fd)) {
        *error = tr("cannot open %1: %2").arg(path, qt_error_string(errno));
        if (fd >= 0)
            ::close(fd);
        return false;
    }
    auto *p = new Party;
    p->fd = fd;
    p->path = path;
    p->attached = true;
    const int index = int(m_parties.size());
    m_parties << p;
    p->reader = new QSocketNotifier(fd, QSocketNotifier::Read, this);
    connect(p->reader, &QSocketNotifier::activated, this, [this, index] { readParty(index); });
    return true;
#else
    *error = tr("a line of pseudo-terminals needs Unix");
    Q_UNUSED(path)
    return false;
#endif
}

bool LineHub::reattach(const QString &path, QString *error)
{
    for (qsizetype i = m_parties.size() - 1; i >= 0; --i) {
        if (m_parties.at(i)->attached)
            closeParty(m_parties.takeAt(i));
    }
    return attach(path, error);
}

void LineHub::closeParty(Party *p)
{
    delete p->reader;
    delete p->writer;
#ifdef Q_OS_UNIX
    if (p->fd >= 0)
        ::close(p->fd);
    if (p->slave >= 0)
        ::close(p->slave);
#endif
    delete p;
}

void LineHub::close()
{
    for (const QString &link : std::as_const(m_links))
        QFile::remove(link);
    m_links.clear();
    for (Party *p : std::as_const(m_parties))
        closeParty(p);
    m_parties.clear();
}

QStringList LineHub::paths() const
{
    QStringList out;
    for (const Party *p : m_parties)
        if (!p->attached)
            out << p->path;
    return out;
}

qint64 LineHub::bytesSent(int index) const
{
    return index >= 0 && index < m_parties.size() ? m_parties.at(index)->sent : 0;
}

void LineHub::setEcho(int index, bool echo)
{
    if (index >= 0 && index < m_parties.size())
        m_parties.at(index)->echo = echo;
}

bool LineHub::createLink(int index, const QString &linkPath, QString *error)
{
    if (index < 0 || index >= m_parties.size()) {
        *error = tr("no party %1 on the line").arg(index + 1);
        return false;
    }
    const QFileInfo info(linkPath);
    if (info.exists() && !info.isSymLink()) {
        *error = tr("%1 exists and is not a symlink: not replaced").arg(linkPath);
        return false;
    }
    QFile::remove(linkPath);
    if (!QFile::link(m_parties.at(index)->path, linkPath)) {
        *error = tr("cannot make the symlink %1").arg(linkPath);
        return false;
    }
    m_links << linkPath;
    return true;
}

void LineHub::readParty(int index)
{
#ifdef Q_OS_UNIX
    Party *p = m_parties.at(index);
    char buffer[4096];
    const ssize_t n = ::read(p->fd, buffer, sizeof buffer);
    if (n <= 0) {
        if (n < 0 && (errno == EAGAIN || errno == EINTR))
            return;
        // EIO from an attached terminal whose other end went: nothing more comes from it.
        p->reader->setEnabled(false);
        return;
    }
    const QByteArray bytes(buffer, int(n));
    p->sent += n;
    Q_EMIT bytesSeen(index, bytes);
    followBaud(index);
    if (p->echo)
        writeTo(index, bytes);
    for (int i = 0; i < m_parties.size(); ++i)
        if (i != index)
            writeTo(i, bytes);
#else
    Q_UNUSED(index)
#endif
}

void LineHub::followBaud(int from)
{
#ifdef Q_OS_UNIX
    const Party *source = m_parties.at(from);
    if (source->slave < 0)
        return;
    termios sender{};
    if (::tcgetattr(source->slave, &sender) != 0)
        return;
    const speed_t speed = ::cfgetospeed(&sender);
    for (const Party *p : std::as_const(m_parties)) {
        termios t{};
        if (!p->attached || ::tcgetattr(p->fd, &t) != 0 || ::cfgetospeed(&t) == speed)
            continue;
        ::cfsetspeed(&t, speed);
        ::tcsetattr(p->fd, TCSANOW, &t);
    }
#else
    Q_UNUSED(from)
#endif
}

void LineHub::writeTo(int index, const QByteArray &bytes)
{
    Party *p = m_parties.at(index);
    if (p->pending.size() + bytes.size() > kMaxPending)
        return; // nobody reads that end: the bytes are lost, as on a wire
    p->pending.append(bytes);
    flush(index);
}

void LineHub::flush(int index)
{
#ifdef Q_OS_UNIX
    Party *p = m_parties.at(index);
    while (!p->pending.isEmpty()) {
        const ssize_t n = ::write(p->fd, p->pending.constData(), size_t(p->pending.size()));
        if (n > 0) {
            p->pending.remove(0, n);
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK)
            p->pending.clear(); // that end is gone
        break;
    }
    if (!p->pending.isEmpty() && !p->writer) {
        p->writer = new QSocketNotifier(p->fd, QSocketNotifier::Write, this);
        connect(p->writer, &QSocketNotifier::activated, this, [this, index] { flush(index); });
    }
    if (p->writer)
        p->writer->setEnabled(!p->pending.isEmpty());
#else
    Q_UNUSED(index)
#endif
}

} // namespace stepcom
