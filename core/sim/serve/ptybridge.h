#pragma once

#include <QByteArray>
#include <QElapsedTimer>
#include <QList>
#include <QObject>
#include <QString>

#include <array>
#include <functional>

QT_BEGIN_NAMESPACE
class QSocketNotifier;
class QTimer;
QT_END_NAMESPACE

namespace stepcom {

// Two pseudo-terminals joined back to back in-process: what a program writes to the slave of
// side A comes out of the slave of side B and vice versa, and every chunk can be watched or
// rewritten on the way. The simulator serves RTU through it; tests sit on it like a wire tap.
// Bytes sent to a side no program has open wait in its pty, like a UART FIFO, and reach the next
// program that opens it: clients should QSerialPort::clear() after opening.
class PtyBridge : public QObject
{
    Q_OBJECT
public:
    enum class Side { A, B };
    Q_ENUM(Side)
    // Called for every chunk read from a side's master before it is forwarded to the other side.
    // Return what to forward (possibly modified; an empty array drops it).
    using Tap = std::function<QByteArray(Side from, const QByteArray &bytes)>;

    // How many bytes the frame at the start of `bytes` takes: > 0 a complete frame's length,
    // 0 when more bytes are needed.
    using Framer = std::function<int(const QByteArray &bytes)>;

    explicit PtyBridge(QObject *parent = nullptr);
    ~PtyBridge() override;

    // Two openpty() pairs set raw; our own slave fds stay open so a program closing its side
    // never makes the master read EIO. Fails if already open.
    bool open(QString *error);
    // Hang-up: closes masters and kept slave fds; programs with a slave open see the port vanish.
    void close();
    bool isOpen() const;
    // The slave path (e.g. /dev/pts/5) a program opens; empty when closed.
    QString path(Side side) const;
    void setTap(Tap tap);
    // What `from` sends is cut into frames and handed on one frame at a time, each once the
    // program on the other side has read the one before, the tap called per frame: a program
    // that reads a burst as one frame (Qt's RTU server) never gets two requests glued
    // together when it was too busy to read between them, as a device on a wire hears the
    // silence between frames. Bytes that make no complete frame go on after kFrameSilenceMs.
    // A frame has been read once it was seen waiting on the other side and then gone (a pty
    // hands bytes on asynchronously: an empty queue right after a write says nothing), or once
    // frameRead() says so -- or, from a program that never tells, after kUntoldMs.
    void setFramer(Side from, Framer framer);
    // The program on `side` has read what was handed to it: the next frame may go.
    void frameRead(Side side);
    static constexpr int kFrameSilenceMs = 20;
    static constexpr int kUntoldMs = 100;
    // Write bytes out of `to`'s slave as if the other side had sent them (bypasses the tap).
    void inject(Side to, const QByteArray &bytes);
    // The baud rate the program on `side` set on its slave; 0 if unknown (nobody set one, the
    // bridge is closed, or a non-standard rate).
    qint32 clientBaud(Side side) const;
    // Symlink at `linkPath` to path(side), replacing a symlink but never another kind of file;
    // removed on close()/destruction if it still points at our slave.
    bool createLink(Side side, const QString &linkPath, QString *error);

Q_SIGNALS:
    // Every chunk as read, before the tap.
    void bytesSeen(stepcom::PtyBridge::Side from, const QByteArray &bytes);
    // Emitted once by close() of an open bridge (never by the destructor).
    void hungUp();

private:
    struct Port
    {
        int master = -1;
        int slave = -1;
        QString path;
        QSocketNotifier *readNotifier = nullptr;
        QSocketNotifier *writeNotifier = nullptr;
        QByteArray pending;        // bytes the master could not take yet
        Framer framer;             // what this side sends is handed on frame by frame
        QByteArray partial;        // bytes read from this side, not yet a whole frame
        QList<QByteArray> frames;  // whole frames read from this side, not yet handed on
        bool awaitingRead = false; // a frame was handed to this side's program, not yet read
        bool seenQueued = false;   // ... and was seen waiting in its queue
        QElapsedTimer handedAt;
    };
    struct Link
    {
        Side side;
        QString path;
    };

    Port &port(Side side) { return m_ports[static_cast<int>(side)]; }
    const Port &port(Side side) const { return m_ports[static_cast<int>(side)]; }
    bool openPort(Port &p, QString *error);
    void teardown();
    void readMaster(Side from);
    void forward(Side to, const QByteArray &bytes);
    void flushPending(Side to);
    // Hands on the frames `from` sent while the other side's program has read all before.
    void deliverFrames(Side from);
    void passOn(Side from, const QByteArray &bytes);
    bool otherSideHasRead(Side from);
    void removeLinks();

    std::array<Port, 2> m_ports;
    QList<Link> m_links;
    Tap m_tap;
    QTimer *m_frameTimer = nullptr; // looks again whether a held frame may go on
    quint64 m_generation = 0; // tells a handler that close()/open() ran inside a signal or tap
};

} // namespace stepcom
