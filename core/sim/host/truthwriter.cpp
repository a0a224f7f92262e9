#include "sim/host/truthwriter.h"

#include "sim/model/simdevice.h"

#include <QCoreApplication>
#include <QJsonDocument>
#include <QSaveFile>

namespace stepcom {

TruthWriter::TruthWriter(SimDevice *device, const QString &path, QObject *parent)
    : QObject(parent)
    , m_device(device)
    , m_path(path)
{
    m_timer.setInterval(kIntervalMs);
    connect(&m_timer, &QTimer::timeout, this, &TruthWriter::poll);
}

bool TruthWriter::start(QString *error)
{
    if (!flush(error))
        return false;
    m_timer.start();
    return true;
}

void TruthWriter::poll()
{
    QString why;
    if (!flush(&why) && !m_failedOnce) {
        m_failedOnce = true; // said once, not every 50 ms
        Q_EMIT failed(why);
    }
}

bool TruthWriter::flush(QString *error)
{
    QJsonObject truth = m_device->truthJson();
    QJsonObject withoutTime = truth;
    withoutTime.remove(QStringLiteral("time_ms"));
    if (m_hasWritten && withoutTime == m_written)
        return true;
    if (!write(truth, error))
        return false;
    m_written = withoutTime;
    m_hasWritten = true;
    return true;
}

bool TruthWriter::write(const QJsonObject &truth, QString *error)
{
    QSaveFile file(m_path);
    if (file.open(QIODevice::WriteOnly) &&
        file.write(QJsonDocument(truth).toJson(QJsonDocument::Indented)) >= 0 && file.commit())
        return true;
    if (error)
        *error = QCoreApplication::translate("stepcom::TruthWriter", "--truth-out: %1: %2")
                     .arg(m_path, file.errorString());
    return false;
}

} // namespace stepcom
