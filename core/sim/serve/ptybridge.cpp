#include "sim/serve/ptybridge.h"

#include <QPointer>
#include <QSocketNotifier>
#include <QTimer>

#ifdef Q_OS_UNIX
#include <QFile>
#include <QFileInfo>
#include <QLoggingCategory>

#include <cerrno>
#include <climits>
#include <fcntl.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>
#include <utility>
#if __has_include(<pty.h>)
#include <pty.h>
#elif __has_include(<util.h>)
#include <util.h>
#else
#include <libutil.h>
#endif
#endif

namespace stepcom {

#ifdef Q_OS_UNIX

namespace {

Q_LOGGING_CATEGORY(lcPty, "stepcom.sim.pty", QtInfoMsg)

// Bounds memory when a side stops reading; a real wire would have lost the bytes long before.
constexpr qsizetype kMaxPending = 1024 * 1024;
constexpr int kReadChunk = 4096;

PtyBridge::Side otherSide(PtyBridge::Side side)
{
    return side == PtyBridge::Side::A ? PtyBridge::Side::B : PtyBridge::Side::A;
}

QString sideName(PtyBridge::Side side)
{
    return side == PtyBridge::Side::A ? QStringLiteral("A") : QStringLiteral("B");
}

void setError(QString *error, const QString &message)
{
    if (error)
        *error = message;
}

QString systemError(const QString &what, int errorCode)
{
    return QStringLiteral("%1: %2").arg(what, qt_error_string(errorCode));
}

void closeFd(int &fd)
{
    if (fd >= 0)
        ::close(fd);
    fd = -1;
}

bool isWouldBlock(int errorCode)
{
    return errorCode == EAGAIN || errorCode == EWOULDBLOCK;
}

// Writes what the master takes now; -1 on a hard error (errno set).
qsizetype writeSome(int fd, const char *data, qsizetype size)
{
    qsizetype done = 0;
    while (done < size) {
        const ssize_t n = ::write(fd, data + done, static_cast<size_t>(size - done));
        if (n > 0) {
            done += n;
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0 && isWouldBlock(errno))
            break;
        return -1;
    }
    return done;
}

// termios speeds are opaque constants on Linux; some platforms lack the higher ones.
constexpr std::pair<speed_t, qint32> kSpeeds[] = {
    {B50, 50},         {B75, 75},         {B110, 110},       {B134, 134},         {B150, 150},
    {B200, 200},       {B300, 300},       {B600, 600},       {B1200, 1200},       {B1800, 1800},
    {B2400, 2400},     {B4800, 4800},     {B9600, 9600},     {B19200, 19200},     {B38400, 38400},
#ifdef B7200
    {B7200, 7200},     {B14400, 14400},   {B28800, 28800},   {B76800, 76800},
#endif
#ifdef B57600
    {B57600, 57600},   {B115200, 115200}, {B230400, 230400},
#endif
#ifdef B460800
    {B460800, 460800},
#endif
#ifdef B500000
    {B500000, 500000}, {B576000, 576000}, {B921600, 921600}, {B1000000, 1000000},
#endif
};

qint32 speedToBaud(speed_t speed)
{
    for (const auto &[constant, baud] : kSpeeds) {
        if (constant == speed)
            return baud;
    }
    return 0; // B0 (nobody set a speed) or a custom rate termios cannot express
}

} // namespace

PtyBridge::PtyBridge(QObject *parent)
    : QObject(parent)
{}

PtyBridge::~PtyBridge()
{
    teardown();
}

bool PtyBridge::open(QString *error)
{
    if (isOpen()) {
        setError(error, QStringLiteral("the pseudo-terminal bridge is already open"));
        return false;
    }
    ++m_generation;
    for (Port &p : m_ports) {
        if (!openPort(p, error)) {
            teardown();
            return false;
        }
    }
    for (const Side side : {Side::A, Side::B}) {
        Port &p = port(side);
        p.readNotifier = new QSocketNotifier(p.master, QSocketNotifier::Read, this);
        connect(p.readNotifier, &QSocketNotifier::activated, this,
                [this, side] { readMaster(side); });
        p.writeNotifier = new QSocketNotifier(p.master, QSocketNotifier::Write, this);
        p.writeNotifier->setEnabled(false); // only while bytes wait for room
        connect(p.writeNotifier, &QSocketNotifier::activated, this,
                [this, side] { flushPending(side); });
    }
    qCDebug(lcPty) << "bridge open:" << m_ports[0].path << "<->" << m_ports[1].path;
    return true;
}

bool PtyBridge::openPort(Port &p, QString *error)
{
    if (::openpty(&p.master, &p.slave, nullptr, nullptr, nullptr) != 0) {
        const int err = errno;
        p.master = p.slave = -1;
        setError(error, systemError(QStringLiteral("openpty failed"), err));
        return false;
    }
    // A simulator may spawn programs; they must not inherit the bridge's descriptors.
    ::fcntl(p.master, F_SETFD, FD_CLOEXEC);
    ::fcntl(p.slave, F_SETFD, FD_CLOEXEC);
    const int flags = ::fcntl(p.master, F_GETFL);
    if (flags < 0 || ::fcntl(p.master, F_SETFL, flags | O_NONBLOCK) < 0) {
        setError(error,
                 systemError(QStringLiteral("cannot make the pty master non-blocking"), errno));
        return false;
    }
    termios tio{};
    if (::tcgetattr(p.slave, &tio) != 0) {
        setError(error, systemError(QStringLiteral("tcgetattr on the pty slave failed"), errno));
        return false;
    }
    ::cfmakeraw(&tio);
    tio.c_cflag |= CLOCAL | CREAD;
    tio.c_cc[VMIN] = 1;
    tio.c_cc[VTIME] = 0;
    // B0 until a program sets its own speed, so clientBaud() can say "unknown" (a pty ignores it).
    ::cfsetispeed(&tio, B0);
    ::cfsetospeed(&tio, B0);
    if (::tcsetattr(p.slave, TCSANOW, &tio) != 0) {
        setError(error, systemError(QStringLiteral("tcsetattr on the pty slave failed"), errno));
        return false;
    }
    char name[PATH_MAX] = {};
    if (::ttyname_r(p.slave, name, sizeof name) != 0) {
        setError(error, systemError(QStringLiteral("cannot name the pty slave"), errno));
        return false;
    }
    p.path = QFile::decodeName(name);
    return true;
}

void PtyBridge::close()
{
    if (!isOpen())
        return;
    qCDebug(lcPty) << "hang-up:" << m_ports[0].path << "<->" << m_ports[1].path;
    teardown();
    Q_EMIT hungUp();
}

void PtyBridge::teardown()
{
    ++m_generation;
    removeLinks();
    for (Port &p : m_ports) {
        // Disabled before the fd closes; deleteLater because we may be inside their activated().
        for (QSocketNotifier **n : {&p.readNotifier, &p.writeNotifier}) {
            if (*n) {
                (*n)->setEnabled(false);
                (*n)->deleteLater();
                *n = nullptr;
            }
        }
        // Master first: its close hangs up the slave for every program that has it open.
        closeFd(p.master);
        closeFd(p.slave);
        p.path.clear();
        p.pending.clear();
        p.partial.clear();
        p.frames.clear();
        p.awaitingRead = false;
    }
}

bool PtyBridge::isOpen() const
{
    return m_ports[0].master >= 0;
}

QString PtyBridge::path(Side side) const
{
    return port(side).path;
}

void PtyBridge::setTap(Tap tap)
{
    m_tap = std::move(tap);
}

void PtyBridge::inject(Side to, const QByteArray &bytes)
{
    forward(to, bytes);
}

qint32 PtyBridge::clientBaud(Side side) const
{
    const Port &p = port(side);
    termios tio{};
    // On Linux termios ioctls on a master act on its slave, which is what the program configured.
    if (p.master < 0 || ::tcgetattr(p.master, &tio) != 0) {
        if (p.slave < 0 || ::tcgetattr(p.slave, &tio) != 0)
            return 0;
    }
    return speedToBaud(::cfgetospeed(&tio));
}

void PtyBridge::readMaster(Side from)
{
    Port &p = port(from);
    if (p.master < 0)
        return;
    char buffer[kReadChunk];
    ssize_t n = 0;
    do {
        n = ::read(p.master, buffer, sizeof buffer);
    } while (n < 0 && errno == EINTR);
    if (n < 0 && isWouldBlock(errno))
        return;
    if (n <= 0) {
        // EIO/EOF: the slave lost every opener (our kept fd prevents that on Linux); a notifier
        // on such a master would fire forever, so stop listening to this side.
        qCWarning(lcPty).noquote()
            << "side" << sideName(from)
            << "stopped:" << (n < 0 ? qt_error_string(errno) : QStringLiteral("EOF"));
        p.readNotifier->setEnabled(false);
        return;
    }
    const QByteArray bytes(buffer, static_cast<qsizetype>(n));
    const quint64 generation = m_generation;
    const QPointer<PtyBridge> self(this);
    Q_EMIT bytesSeen(from, bytes);
    if (!self || generation != m_generation)
        return;
    if (!p.framer) {
        passOn(from, bytes);
        return;
    }
    p.partial.append(bytes);
    while (!p.partial.isEmpty()) {
        const int length = p.framer(p.partial);
        if (length <= 0 || length > p.partial.size())
            break;
        p.frames.append(p.partial.left(length));
        p.partial.remove(0, length);
    }
    deliverFrames(from);
}

void PtyBridge::passOn(Side from, const QByteArray &bytes)
{
    const quint64 generation = m_generation;
    const QPointer<PtyBridge> self(this);
    QByteArray out = bytes;
    if (m_tap) {
        const Tap tap = m_tap; // a copy, so the tap may replace itself with setTap()
        out = tap(from, bytes);
        if (!self || generation != m_generation)
            return;
    }
    if (!out.isEmpty())
        forward(otherSide(from), out);
}

bool PtyBridge::otherSideHasRead(Side from)
{
    Port &to = port(otherSide(from));
    if (!to.pending.isEmpty())
        return false;
    if (!to.awaitingRead)
        return true;
    int queued = 0;
    // The slave's input queue is the tty's, shared by every opener: our kept fd sees it.
    if (to.slave < 0 || ::ioctl(to.slave, FIONREAD, &queued) != 0)
        return true;
    if (queued > 0)
        to.seenQueued = true;
    else if (to.seenQueued || to.handedAt.elapsed() >= kUntoldMs)
        to.awaitingRead = false;
    return !to.awaitingRead;
}

void PtyBridge::frameRead(Side side)
{
    Port &p = port(side);
    p.awaitingRead = false;
    const Port &from = port(otherSide(side));
    if (m_frameTimer && (!from.frames.isEmpty() || !from.partial.isEmpty()))
        m_frameTimer->start(0);
}

void PtyBridge::deliverFrames(Side from)
{
    Port &p = port(from);
    const quint64 generation = m_generation;
    const QPointer<PtyBridge> self(this);
    while (!p.frames.isEmpty() && otherSideHasRead(from)) {
        Port &to = port(otherSide(from));
        to.awaitingRead = true;
        to.seenQueued = false;
        to.handedAt.start();
        passOn(from, p.frames.takeFirst());
        if (!self || generation != m_generation)
            return;
    }
    if (!p.frames.isEmpty()) {
        m_frameTimer->start(1); // the other side reads the one before first
        return;
    }
    if (!p.partial.isEmpty())
        m_frameTimer->start(kFrameSilenceMs); // a silence: what came is all there is
}

void PtyBridge::setFramer(Side from, Framer framer)
{
    port(from).framer = std::move(framer);
    if (m_frameTimer)
        return;
    m_frameTimer = new QTimer(this);
    m_frameTimer->setSingleShot(true);
    connect(m_frameTimer, &QTimer::timeout, this, [this] {
        for (const Side side : {Side::A, Side::B}) {
            Port &p = port(side);
            if (!p.framer)
                continue;
            // Waited out a silence with an incomplete frame and nothing held: noise, or a
            // frame this framer cannot size; it goes on as it came.
            if (p.frames.isEmpty() && !p.partial.isEmpty() && otherSideHasRead(side))
                p.frames.append(std::exchange(p.partial, {}));
            deliverFrames(side);
        }
    });
}

void PtyBridge::forward(Side to, const QByteArray &bytes)
{
    Port &p = port(to);
    if (p.master < 0 || bytes.isEmpty())
        return;
    if (p.pending.isEmpty()) {
        const qsizetype done = writeSome(p.master, bytes.constData(), bytes.size());
        if (done < 0) {
            qCWarning(lcPty).noquote() << "dropped" << bytes.size() << "bytes to side"
                                       << sideName(to) << ":" << qt_error_string(errno);
            return;
        }
        if (done == bytes.size())
            return;
        p.pending = bytes.mid(done);
        p.writeNotifier->setEnabled(true);
        return;
    }
    if (p.pending.size() + bytes.size() > kMaxPending) {
        qCWarning(lcPty) << "side" << sideName(to) << "is not reading; dropped" << bytes.size()
                         << "bytes";
        return;
    }
    p.pending.append(bytes);
}

void PtyBridge::flushPending(Side to)
{
    Port &p = port(to);
    if (p.master < 0)
        return;
    const qsizetype done = writeSome(p.master, p.pending.constData(), p.pending.size());
    if (done < 0) {
        qCWarning(lcPty).noquote() << "dropped" << p.pending.size() << "bytes to side"
                                   << sideName(to) << ":" << qt_error_string(errno);
        p.pending.clear();
    } else {
        p.pending.remove(0, done);
    }
    if (p.pending.isEmpty())
        p.writeNotifier->setEnabled(false);
}

bool PtyBridge::createLink(Side side, const QString &linkPath, QString *error)
{
    if (!isOpen()) {
        setError(error, QStringLiteral("the pseudo-terminal bridge is not open"));
        return false;
    }
    if (linkPath.isEmpty()) {
        setError(error, QStringLiteral("empty link path"));
        return false;
    }
    const QFileInfo info(linkPath);
    if (!info.isSymLink() && info.exists()) {
        setError(error,
                 QStringLiteral("refusing to replace %1: it is not a symbolic link").arg(linkPath));
        return false;
    }
    const QByteArray target = QFile::encodeName(path(side));
    const QByteArray link = QFile::encodeName(linkPath);
    // symlink() then rename() swaps an old link atomically: a client never sees no link at all.
    const QByteArray temporary = link + ".stepcom-" + QByteArray::number(::getpid());
    ::unlink(temporary.constData());
    if (::symlink(target.constData(), temporary.constData()) != 0) {
        setError(error, systemError(QStringLiteral("cannot create %1").arg(linkPath), errno));
        return false;
    }
    if (::rename(temporary.constData(), link.constData()) != 0) {
        const int err = errno;
        ::unlink(temporary.constData());
        setError(error, systemError(QStringLiteral("cannot create %1").arg(linkPath), err));
        return false;
    }
    m_links.removeIf([&linkPath](const Link &l) { return l.path == linkPath; });
    m_links.append({side, linkPath});
    return true;
}

void PtyBridge::removeLinks()
{
    for (const Link &l : std::as_const(m_links)) {
        const QByteArray link = QFile::encodeName(l.path);
        const QByteArray target = QFile::encodeName(path(l.side));
        char current[PATH_MAX];
        const ssize_t n = ::readlink(link.constData(), current, sizeof current);
        // Someone may have pointed the link elsewhere since; only remove what is still ours.
        if (n >= 0 && QByteArray(current, static_cast<qsizetype>(n)) == target)
            ::unlink(link.constData());
    }
    m_links.clear();
}

#else // !Q_OS_UNIX

PtyBridge::PtyBridge(QObject *parent)
    : QObject(parent)
{}

PtyBridge::~PtyBridge() = default;

bool PtyBridge::open(QString *error)
{
    if (error)
        *error = QStringLiteral("pseudo-terminals are Unix only; use Modbus TCP (--tcp)");
    return false;
}

void PtyBridge::close() {}

bool PtyBridge::isOpen() const
{
    return false;
}

QString PtyBridge::path(Side side) const
{
    Q_UNUSED(side)
    return {};
}

void PtyBridge::setTap(Tap tap)
{
    m_tap = std::move(tap);
}

void PtyBridge::setFramer(Side from, Framer framer)
{
    Q_UNUSED(from)
    Q_UNUSED(framer)
}

void PtyBridge::frameRead(Side side)
{
    Q_UNUSED(side)
}

void PtyBridge::inject(Side to, const QByteArray &bytes)
{
    Q_UNUSED(to)
    Q_UNUSED(bytes)
}

qint32 PtyBridge::clientBaud(Side side) const
{
    Q_UNUSED(side)
    return 0;
}

bool PtyBridge::createLink(Side side, const QString &linkPath, QString *error)
{
    Q_UNUSED(side)
    Q_UNUSED(linkPath)
    if (error)
        *error = QStringLiteral("pseudo-terminals are Unix only; use Modbus TCP (--tcp)");
    return false;
}

#endif // Q_OS_UNIX

} // namespace stepcom
