#pragma once

#include <QJsonObject>
#include <QObject>
#include <QString>
#include <QTimer>

namespace stepcom {

class SimDevice;

// Keeps SimDevice::truthJson() in a file for people and for tests in other processes: written
// atomically (QSaveFile) whenever it changed, at most every 50 ms, and by flush() at exit.
class TruthWriter : public QObject
{
    Q_OBJECT
public:
    static constexpr int kIntervalMs = 50;

    TruthWriter(SimDevice *device, const QString &path, QObject *parent = nullptr);

    // Writes the first file now; false and why when it cannot be written.
    bool start(QString *error);
    // Writes the truth now if it changed since the last write.
    bool flush(QString *error = nullptr);
    QString path() const { return m_path; }

Q_SIGNALS:
    void failed(const QString &why);

private:
    void poll();
    bool write(const QJsonObject &truth, QString *error);

    SimDevice *m_device;
    QString m_path;
    QTimer m_timer;
    QJsonObject m_written; // without its time: a change of the time alone is no change
    bool m_hasWritten = false;
    bool m_failedOnce = false;
};

} // namespace stepcom
