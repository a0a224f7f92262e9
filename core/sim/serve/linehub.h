#pragma once

#include <QByteArray>
#include <QList>
#include <QObject>
#include <QString>
#include <QStringList>

QT_BEGIN_NAMESPACE
class QSocketNotifier;
QT_END_NAMESPACE

namespace stepcom {

// A line of several parties, as on RS-485: N pseudo-terminals where every byte one party sends
// reaches all the others (never itself). A test puts a master, a listener and the simulated
// controller on one line; attach() adds a party inside this process (the simulator's pty), and
// the bytes each party sent are counted, so a test can prove a listener sent nothing.
// Programs set the baud on their own end: bytes reach an attached party at the sender's baud.
class LineHub : public QObject
{
    Q_OBJECT
public:
    explicit LineHub(QObject *parent = nullptr);
    ~LineHub() override;

    // `parties` pseudo-terminals, raw; our own slave fds stay open so a program closing its
    // end never makes the master read EIO. Fails when already open or parties < 1.
    bool open(int parties, QString *error);
    void close();
    bool isOpen() const { return !m_parties.isEmpty(); }
    // The slave paths programs open, in order (party 0 first).
    QStringList paths() const;
    // A party of our own: the terminal at `path` (the simulator's end of its pty bridge),
    // opened raw. Its index is the last of paths()'s + 1.
    bool attach(const QString &path, QString *error);
    // The attached parties replaced by the terminal at `path` (the simulator's pty came back
    // under another name after a hang-up).
    bool reattach(const QString &path, QString *error);
    // Bytes party `index` has sent onto the line since open().
    qint64 bytesSent(int index) const;
    int parties() const { return int(m_parties.size()); }
    // Party `index` hears its own bytes back, before the others hear them: an adapter without
    // echo suppression (a half-duplex USB-RS485 one) on that party's end.
    void setEcho(int index, bool echo);
    // A symlink at `linkPath` to party `index`'s path, replacing a symlink but never another
    // kind of file; removed on close().
    bool createLink(int index, const QString &linkPath, QString *error);

Q_SIGNALS:
    // Every chunk one party sent, before it reaches the others.
    void bytesSeen(int party, const QByteArray &bytes);

private:
    struct Party
    {
        int fd = -1;    // the master (or the attached terminal)
        int slave = -1; // kept open (pseudo-terminals of our own)
        QString path;
        bool attached = false;
        QSocketNotifier *reader = nullptr;
        QSocketNotifier *writer = nullptr;
        QByteArray pending; // bytes the party could not take yet
        qint64 sent = 0;
        bool echo = false;
    };
    void readParty(int index);
    void writeTo(int index, const QByteArray &bytes);
    void flush(int index);
    // The baud party `from` set on its end, applied to the attached parties before its bytes.
    void followBaud(int from);
    static void closeParty(Party *p);

    QList<Party *> m_parties;
    QStringList m_links;
};

} // namespace stepcom
