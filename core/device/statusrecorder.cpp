#include "device/statusrecorder.h"

#include "device/parameterstore.h"
#include "device/poller.h"
#include "map/registermap.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QSaveFile>

#include <cmath>
#include <limits>

namespace stepcom {

namespace {

qint8 flagOf(const std::optional<qint64> &v)
{
    return v ? qint8(*v != 0) : qint8(-1);
}

QString flagText(qint8 flag)
{
    return flag < 0 ? QString() : QString::number(flag);
}

// ISO 8601 local time with milliseconds and the UTC offset, so files from different machines
// (or either side of a DST change) still line up.
QString isoTime(qint64 epochMs)
{
    const QDateTime local = QDateTime::fromMSecsSinceEpoch(epochMs);
    return local.toOffsetFromUtc(local.offsetFromUtc()).toString(Qt::ISODateWithMs);
}

QString describePath(const QString &path)
{
    return QDir::toNativeSeparators(QFileInfo(path).absoluteFilePath());
}

} // namespace

StatusColumns::StatusColumns(const RegisterMap &map)
{
    for (int n = 1; n <= map.blockCount(kMotorBlock); ++n) {
        const Parameter *pos = map.blockParameter(kMotorBlock, n, QStringLiteral("position"));
        const Parameter *run = map.blockParameter(kMotorBlock, n, QStringLiteral("running"));
        if (!pos)
            break;
        positionKeys << pos->key;
        positionScale << pos->scale;
        positionDecimals << pos->decimals();
        runningKeys << (run ? run->key : QString());
        if (unit.isEmpty())
            unit = pos->unit;
    }
    for (int n = 1; map.find(QStringLiteral("io.in%1").arg(n)); ++n)
        inputKeys << QStringLiteral("io.in%1").arg(n);
    for (int n = 1; map.find(QStringLiteral("io.out%1").arg(n)); ++n)
        outputKeys << QStringLiteral("io.out%1").arg(n);
}

StatusRecorder::StatusRecorder(const RegisterMap &map, ParameterStore *store, QObject *parent)
    : QObject(parent)
    , m_store(store)
{
    const StatusColumns columns(map);
    m_motors = columns.motors();
    m_positionKeys = columns.positionKeys;
    m_positionScale = columns.positionScale;
    m_positionDecimals = columns.positionDecimals;
    m_runningKeys = columns.runningKeys;
    m_unit = columns.unit;
    m_inputKeys = columns.inputKeys;
    m_outputKeys = columns.outputKeys;
    m_clock.start();
    m_epochAtStart = QDateTime::currentMSecsSinceEpoch();
}

StatusRecorder::~StatusRecorder()
{
    if (m_file.isOpen())
        m_file.close();
}

void StatusRecorder::attach(Poller *poller)
{
    disconnect(m_pollerConnection);
    if (poller)
        m_pollerConnection = connect(poller, &Poller::cycleFinished, this, [this](bool ok, qint64) {
            if (ok)
                takeSample();
        });
}

void StatusRecorder::takeSample()
{
    const qint64 elapsed = m_clock.elapsed();
    append(sampleOf([this](const QString &key) { return m_store->deviceValue(key); }, elapsed,
                    m_epochAtStart + elapsed));
}

void StatusRecorder::addSample(const QHash<QString, qint64> &values, qint64 elapsedMs,
                               qint64 epochMs)
{
    append(sampleOf(
        [&values](const QString &key) {
            const auto it = values.constFind(key);
            return it == values.cend() ? std::nullopt : std::optional<qint64>(*it);
        },
        elapsedMs, epochMs));
}

StatusSample
StatusRecorder::sampleOf(const std::function<std::optional<qint64>(const QString &)> &valueOf,
                         qint64 elapsedMs, qint64 epochMs) const
{
    StatusSample s;
    s.elapsedMs = elapsedMs;
    s.epochMs = epochMs;
    s.positions.reserve(m_motors);
    s.running.reserve(m_motors);
    for (int m = 0; m < m_motors; ++m) {
        const auto raw = valueOf(m_positionKeys.at(m));
        s.positions << (raw ? double(*raw) / m_positionScale.at(m)
                            : std::numeric_limits<double>::quiet_NaN());
        s.running << flagOf(m_runningKeys.at(m).isEmpty() ? std::nullopt
                                                          : valueOf(m_runningKeys.at(m)));
    }
    for (const QString &k : std::as_const(m_inputKeys))
        s.inputs << flagOf(valueOf(k));
    for (const QString &k : std::as_const(m_outputKeys))
        s.outputs << flagOf(valueOf(k));
    return s;
}

void StatusRecorder::append(const StatusSample &s)
{
    keep(s);
    trim();
    Q_EMIT sampleAdded();
}

void StatusRecorder::addSamples(const QList<StatusSample> &samples)
{
    if (samples.isEmpty())
        return;
    for (const StatusSample &s : samples)
        keep(s);
    trim();
    Q_EMIT sampleAdded();
}

void StatusRecorder::keep(const StatusSample &s)
{
    m_history.push_back(s);
    if (!m_file.isOpen())
        return;
    if (m_recordingOrigin < 0)
        m_recordingOrigin = s.elapsedMs;
    const QByteArray line = (csvRow(s, m_recordingOrigin) + QLatin1Char('\n')).toUtf8();
    if (m_file.write(line) != line.size() || !m_file.flush()) {
        const QString error = tr("Recording to “%1” stopped: %2")
                                  .arg(describePath(m_file.fileName()), m_file.errorString());
        stopRecording();
        Q_EMIT recordingFailed(error);
    } else {
        ++m_rows;
    }
}

void StatusRecorder::setCapacity(int samples)
{
    m_capacity = std::max(1, samples);
    trim();
}

void StatusRecorder::setMaxAgeMs(qint64 ms)
{
    m_maxAgeMs = std::max<qint64>(1, ms);
    trim();
}

void StatusRecorder::trim()
{
    while (int(m_history.size()) > m_capacity)
        m_history.pop_front();
    if (m_history.empty())
        return;
    const qint64 oldest = m_history.back().elapsedMs - m_maxAgeMs;
    while (!m_history.empty() && m_history.front().elapsedMs < oldest)
        m_history.pop_front();
}

void StatusRecorder::clear()
{
    m_history.clear();
    Q_EMIT cleared();
}

int StatusRecorder::indexAtOrAfter(qint64 elapsedMs) const
{
    const auto it =
        std::lower_bound(m_history.cbegin(), m_history.cend(), elapsedMs,
                         [](const StatusSample &s, qint64 ms) { return s.elapsedMs < ms; });
    return int(it - m_history.cbegin());
}

QList<StatusSample> StatusRecorder::samples(int from, int to) const
{
    if (to < 0 || to > size())
        to = size();
    QList<StatusSample> out;
    for (int i = std::max(0, from); i < to; ++i)
        out << m_history[size_t(i)];
    return out;
}

QStringList StatusRecorder::keys() const
{
    return m_positionKeys + m_runningKeys + m_inputKeys + m_outputKeys;
}

QString StatusRecorder::csvHeader() const
{
    QStringList cols{QStringLiteral("time"), QStringLiteral("ms")};
    for (const QString &k : m_positionKeys)
        cols << (m_unit.isEmpty() ? k : QStringLiteral("%1 [%2]").arg(k, m_unit));
    cols << m_runningKeys << m_inputKeys << m_outputKeys;
    return cols.join(QLatin1Char(','));
}

QString StatusRecorder::csvRow(const StatusSample &sample, qint64 originMs) const
{
    QStringList cols{isoTime(sample.epochMs), QString::number(sample.elapsedMs - originMs)};
    for (int m = 0; m < m_motors; ++m) {
        const double v = sample.positions.value(m, std::numeric_limits<double>::quiet_NaN());
        cols << (std::isnan(v) ? QString() : QString::number(v, 'f', m_positionDecimals.at(m)));
    }
    for (int m = 0; m < m_motors; ++m)
        cols << flagText(sample.running.value(m, -1));
    for (int n = 0; n < inputCount(); ++n)
        cols << flagText(sample.inputs.value(n, -1));
    for (int n = 0; n < outputCount(); ++n)
        cols << flagText(sample.outputs.value(n, -1));
    return cols.join(QLatin1Char(','));
}

bool StatusRecorder::writeCsv(const QString &path, const QList<StatusSample> &samples,
                              QString *error) const
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        if (error)
            *error = tr("Cannot write “%1”: %2").arg(describePath(path), file.errorString());
        return false;
    }
    const qint64 origin = samples.isEmpty() ? 0 : samples.first().elapsedMs;
    QByteArray text = (csvHeader() + QLatin1Char('\n')).toUtf8();
    for (const StatusSample &s : samples)
        text += (csvRow(s, origin) + QLatin1Char('\n')).toUtf8();
    if (file.write(text) != text.size() || !file.commit()) {
        if (error)
            *error = tr("Cannot write “%1”: %2").arg(describePath(path), file.errorString());
        return false;
    }
    return true;
}

bool StatusRecorder::startRecording(const QString &path, QString *error)
{
    stopRecording();
    if (path.isEmpty()) {
        if (error)
            *error = tr("Cannot record: no file name given");
        return false;
    }
    m_file.setFileName(path);
    const QByteArray header = (csvHeader() + QLatin1Char('\n')).toUtf8();
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text) ||
        m_file.write(header) != header.size() || !m_file.flush()) {
        if (error)
            *error = tr("Cannot record to “%1”: %2").arg(describePath(path), m_file.errorString());
        m_file.close();
        return false;
    }
    m_recordingOrigin = -1;
    m_rows = 0;
    Q_EMIT recordingChanged(true);
    return true;
}

void StatusRecorder::stopRecording()
{
    if (!m_file.isOpen())
        return;
    m_file.close();
    Q_EMIT recordingChanged(false);
}

} // namespace stepcom
