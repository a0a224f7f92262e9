#pragma once

#include <QElapsedTimer>
#include <QFile>
#include <QHash>
#include <QObject>
#include <QStringList>
#include <QVector>

#include <deque>
#include <functional>
#include <optional>

namespace stepcom {

class ParameterStore;
class Poller;
class RegisterMap;

// One look at the controller's status after a completed poll cycle. Unknown values are NaN
// (positions) or -1 (flags), so a gap in the link stays visible instead of repeating old data.
struct StatusSample
{
    qint64 epochMs = 0;        // wall clock, advanced by a monotonic clock: never goes back
    qint64 elapsedMs = 0;      // since the recorder was created
    QVector<double> positions; // per motor, engineering units (the map's unit, e.g. mm)
    QVector<qint8> running;    // per motor: 1, 0, or -1 unknown
    QVector<qint8> inputs;     // IN1.., same encoding
    QVector<qint8> outputs;    // output 1.., same encoding
};

// The status columns of a map, in CSV order: each motor's position (and its scale, decimals,
// unit) and running flag, the inputs (io.in1..), the outputs (io.out1..). The recorder samples
// them; a replay's track of a whole log (ReplayTrack) keeps the same.
struct StatusColumns
{
    explicit StatusColumns(const RegisterMap &map);
    int motors() const { return int(positionKeys.size()); }

    QStringList positionKeys;
    QStringList runningKeys; // one per motor; empty when the map has no running flag for it
    QStringList inputKeys;
    QStringList outputKeys;
    QVector<int> positionScale;
    QVector<int> positionDecimals;
    QString unit;
};

// Samples the status values (positions, running flags, inputs, outputs) once per completed
// poll cycle into a bounded in-memory history, and records them to CSV on request. No widgets:
// the plots, the CLI and the tests share it. A cycle that read only the positions (a motor
// runs) carries the last known inputs and outputs; unknown stays unknown.
//
// CSV: one header line ("time,ms,motor1.position [mm],...,io.out3"), then one row per sample:
// ISO 8601 local time with milliseconds and UTC offset, ms since the first row, positions with
// the map's decimals, flags as 0/1; an unknown value is an empty field.
//
// CSV recording writes the header at start and flushes every row as it goes (no QSaveFile):
// a recording that ends with a crash or a pulled plug keeps everything up to the last sample.
// Exports of a finished set of samples (writeCsv) are atomic instead.
class StatusRecorder : public QObject
{
    Q_OBJECT
public:
    StatusRecorder(const RegisterMap &map, ParameterStore *store, QObject *parent = nullptr);
    ~StatusRecorder() override;

    // Take a sample after each successful cycle of `poller` (failed cycles are skipped: their
    // values are old). Pass nullptr to detach.
    void attach(Poller *poller);
    // Sample the store now (what attach() does after each cycle).
    void takeSample();
    // A sample of `values` (raw, by key; a key missing is unknown) at a moment of another clock:
    // a replayed log's. Kept and recorded as any other sample.
    void addSample(const QHash<QString, qint64> &values, qint64 elapsedMs, qint64 epochMs);
    // Samples made elsewhere (a replay's, in time order), kept and recorded as any other; one
    // sampleAdded() for all of them.
    void addSamples(const QList<StatusSample> &samples);

    // The history keeps at most this many samples and drops those older than maxAgeMs.
    void setCapacity(int samples);
    int capacity() const { return m_capacity; }
    void setMaxAgeMs(qint64 ms);
    qint64 maxAgeMs() const { return m_maxAgeMs; }
    void clear();

    int size() const { return int(m_history.size()); }
    bool isEmpty() const { return m_history.empty(); }
    const StatusSample &at(int i) const { return m_history[size_t(i)]; }
    const StatusSample &last() const { return m_history.back(); }
    // Index of the first sample with elapsedMs >= ms (size() when there is none).
    int indexAtOrAfter(qint64 elapsedMs) const;
    QList<StatusSample> samples(int from = 0, int to = -1) const;

    // Columns of the status, in CSV order: motorN.position, motorN.running, io.inN, io.outN.
    int motorCount() const { return m_motors; }
    int inputCount() const { return int(m_inputKeys.size()); }
    int outputCount() const { return int(m_outputKeys.size()); }
    QStringList keys() const;
    QString positionUnit() const { return m_unit; }

    // One header line and one line per sample; the second column is ms since the first sample.
    QString csvHeader() const;
    QString csvRow(const StatusSample &sample, qint64 originMs) const;
    // Writes samples atomically (QSaveFile); on failure false and an error naming the path.
    bool writeCsv(const QString &path, const QList<StatusSample> &samples, QString *error) const;

    // Start writing every new sample to `path` (replaced if it exists).
    bool startRecording(const QString &path, QString *error);
    void stopRecording();
    bool isRecording() const { return m_file.isOpen(); }
    QString recordingPath() const { return m_file.fileName(); }
    int recordedRows() const { return m_rows; }

Q_SIGNALS:
    void sampleAdded();
    void cleared();
    void recordingChanged(bool recording);
    // Writing failed part-way (disk full, removed drive): the recording has stopped.
    void recordingFailed(const QString &error);

private:
    void trim();
    void append(const StatusSample &sample);
    void keep(const StatusSample &sample); // into the history and the recording
    StatusSample sampleOf(const std::function<std::optional<qint64>(const QString &)> &valueOf,
                          qint64 elapsedMs, qint64 epochMs) const;

    ParameterStore *m_store;
    int m_motors = 0;
    QStringList m_positionKeys;
    QStringList m_runningKeys;
    QStringList m_inputKeys;
    QStringList m_outputKeys;
    QVector<int> m_positionScale;
    QVector<int> m_positionDecimals;
    QString m_unit;
    std::deque<StatusSample> m_history;
    int m_capacity = 36000; // 30 minutes at 20 cycles a second
    qint64 m_maxAgeMs = 30 * 60 * 1000;
    QElapsedTimer m_clock;
    qint64 m_epochAtStart = 0;
    QMetaObject::Connection m_pollerConnection;
    QFile m_file;
    qint64 m_recordingOrigin = -1;
    int m_rows = 0;
};

} // namespace stepcom
