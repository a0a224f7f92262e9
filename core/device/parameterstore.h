#pragma once

#include "device/deviceclient.h"
#include "map/registermap.h"

#include <QHash>
#include <QObject>
#include <QSet>

#include <optional>

namespace stepcom {

// What StepCom knows about each parameter: the value the device holds (as last read), the
// value the user typed but has not written, and the state between them. Views show this;
// nothing here ever writes to the device.
class ParameterStore : public QObject
{
    Q_OBJECT
public:
    enum class State { Unknown, InSync, Edited, WriteFailed, Unsupported };
    Q_ENUM(State)

    struct Entry
    {
        std::optional<qint64> device;
        std::optional<qint64> edited;
        State state = State::Unknown;
        QString error;            // why the last write failed
        bool unsupported = false; // this controller does not have it (refused a read of it)
    };

    // Everything held for one controller: put aside when another device of the line is shown,
    // put back when it is shown again (DeviceMemory).
    struct Snapshot
    {
        QHash<QString, Entry> entries;
        bool unsaved = false;
    };

    explicit ParameterStore(const RegisterMap &map, QObject *parent = nullptr);

    const RegisterMap &map() const { return m_map; }
    Entry entry(const QString &key) const { return m_entries.value(key); }
    std::optional<qint64> deviceValue(const QString &key) const
    {
        return m_entries.value(key).device;
    }
    // The edit when there is one, else what the device holds.
    std::optional<qint64> shownValue(const QString &key) const;
    State state(const QString &key) const { return m_entries.value(key).state; }

    // Values read from the device. A pending edit is kept: a poll never overwrites typing.
    void setDeviceValues(const QHash<QString, qint64> &values);
    // The link is gone: what the device holds is unknown again (edits stay). A file (openFile)
    // keeps its values.
    void forgetDeviceValues();
    // The parameters the connected controller does not have ("not supported by this
    // controller"); every other key is supported again.
    void setUnsupported(const QSet<QString> &keys);
    bool isUnsupported(const QString &key) const { return m_entries.value(key).unsupported; }

    Snapshot snapshot() const { return {m_entries, m_unsaved}; }
    // Holds what `snapshot` held (keys it lacks become unknown); views hear of every change.
    void restore(const Snapshot &snapshot);

    // Validates against the map; returns the problem, or empty when the edit is held.
    // Editing back to the device's value drops the edit.
    QString edit(const QString &key, qint64 raw);
    void revert(const QString &key);
    void revertAll();
    bool hasEdits() const { return !editedKeys().isEmpty(); }
    QStringList editedKeys() const;
    QList<ParameterWrite> pendingWrites() const;
    // After a write: verified values are in sync and their edits gone; failed ones keep the
    // edit, marked WriteFailed with the reason.
    void applyWriteOutcome(const QList<ParameterWrite> &writes, const WriteOutcome &outcome);

    // Editing a profile file without a controller: the file's values stand where the
    // controller's would (views bind to them unchanged), edits are the user's changes to the
    // file. Replaces everything held; `name` names the file for views that word it.
    void openFile(const QString &name, const QHash<QString, qint64> &values);
    // Back to a controller: the file's values and every edit are forgotten.
    void closeFile();
    bool isFile() const { return m_file; }
    QString fileName() const { return m_fileName; }

    // Replaying a session log: what the log says the controller held at a moment
    // stands where the controller's values would, as a read would have put it (views show it
    // unchanged, the link's state aside). Replaces everything held, edits included; each moment
    // shown calls it again. closeReplay() forgets it all.
    void showReplay(const QString &name, const QHash<QString, qint64> &values);
    void closeReplay();
    bool isReplay() const { return m_replay; }
    QString replayName() const { return m_replayName; }

    // Set after any successful write until "save to flash" succeeds.
    bool unsavedToFlash() const { return m_unsaved; }
    void setUnsavedToFlash(bool unsaved);

Q_SIGNALS:
    void valueChanged(const QString &key);
    void editsChanged();
    void unsavedChanged(bool unsaved);
    // revertAll(): every field drops what it shows that is not held (a rejected typed value).
    void reverted();
    // A file was opened or closed (openFile, closeFile), a replay begun or ended.
    void originChanged();

private:
    void update(const QString &key, const Entry &entry);
    // Holds `values` as the device's and nothing else: every other value unknown, no edits.
    void holdOnly(const QHash<QString, qint64> &values);
    static State stateOf(const Entry &e);

    RegisterMap m_map;
    QHash<QString, Entry> m_entries;
    bool m_unsaved = false;
    bool m_file = false;
    QString m_fileName;
    bool m_replay = false;
    QString m_replayName;
};

} // namespace stepcom
