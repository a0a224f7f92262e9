#pragma once

#include "bus/linksettings.h" // LinkSettings
#include "bus/linkstats.h"    // what linkStats() hands out
#include "bus/trafficlog.h"   // what traffic() hands out

#include <QMap>
#include <QObject>

namespace stepcom {

class DeviceSession;
class LinkHealth;
class ReadLimits;
class Reconnector;

// The session's link to its line: connecting (to a port, a TCP address or the built-in
// simulator), its state and health, reconnecting after a loss, its traffic and statistics, and
// what each controller of the line refuses to read. Owned by the DeviceSession that hands it
// out (connection()); it works on the session's link, which stays the session's.
class SessionConnection : public QObject
{
    Q_OBJECT
public:
    enum class LinkState { Disconnected, Connecting, Connected };
    Q_ENUM(LinkState)

    explicit SessionConnection(DeviceSession *session);

    // Connect, then (live) read everything (reading never writes). `connected(ok, reason)`
    // follows.
    void connectTo(const LinkSettings &settings);
    // Start the built-in simulated controller in this process and connect to it.
    void connectSimulator();
    // Close the link; an empty reason says the user disconnected.
    void disconnectFrom(const QString &reason = QString());
    LinkState linkState() const;
    bool isConnected() const;
    bool isSimulator() const;
    LinkSettings settings() const;
    // Port closed / open but not answering / answering: "connected" means answering.
    LinkHealth *health() const;
    // Tries again on its own after a link loss (off until a front-end turns it on); while it
    // waits, an E-STOP is held and sent first when the link is back, then everything is read.
    Reconnector *reconnector() const;
    TrafficLog *traffic() const;
    const LinkStats &linkStats() const;
    void resetLinkStats();
    // Whether Qt's own qt.modbus messages reach stderr (stepcomctl --verbose); off by default.
    static void setLinkDiagnosticsShown(bool shown);
    // What the connected controller refuses to read (gaps, parameters it lacks), learnt from
    // its answers and remembered per line and id for this session's life.
    const ReadLimits &readLimits() const;
    // The line a controller is on (port, or host:port); read limits are kept per line and id.
    static QString lineKey(const LinkSettings &settings);
    // Every controller's known read limits as text by "line#id", for the saved connection
    // settings; taken back, the next connect need not learn them again (said once then).
    QMap<QString, QString> knownReadLimits() const;
    void setKnownReadLimits(const QMap<QString, QString> &known);

Q_SIGNALS:
    void connected(bool ok, const QString &reason);
    void disconnected(const QString &reason);
    // The link dropped on its own (after `disconnected`).
    void linkLost(const QString &reason);
    void linkStateChanged();
    void linkStatsChanged();
    // Answers began with the request's own bytes: the adapter echoes and the option is off.
    void echoSuspected();
    // Learnt what the controller refuses to read (said once, in words; also a message()).
    void readLimitsLearned(const QString &text);

private:
    DeviceSession *m_session;
};

} // namespace stepcom
