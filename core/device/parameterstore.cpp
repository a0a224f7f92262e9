#include "device/parameterstore.h"

#include <QCoreApplication>

namespace stepcom {

ParameterStore::ParameterStore(const RegisterMap &map, QObject *parent)
    : QObject(parent)
    , m_map(map)
{
    for (const Parameter *p : m_map.holdings())
        m_entries.insert(p->key, Entry());
}

std::optional<qint64> ParameterStore::shownValue(const QString &key) const
{
    const Entry e = m_entries.value(key);
    return e.edited ? e.edited : e.device;
}

ParameterStore::State ParameterStore::stateOf(const Entry &e)
{
    if (e.unsupported)
        return State::Unsupported;
    if (!e.error.isEmpty() && e.edited)
        return State::WriteFailed;
    if (e.edited)
        return State::Edited;
    return e.device ? State::InSync : State::Unknown;
}

void ParameterStore::update(const QString &key, const Entry &entry)
{
    Entry next = entry;
    next.state = stateOf(next);
    const Entry old = m_entries.value(key);
    if (old.device == next.device && old.edited == next.edited && old.state == next.state &&
        old.error == next.error && old.unsupported == next.unsupported)
        return;
    const bool editsMoved = old.edited.has_value() != next.edited.has_value();
    m_entries.insert(key, next);
    Q_EMIT valueChanged(key);
    if (editsMoved)
        Q_EMIT editsChanged();
}

void ParameterStore::setDeviceValues(const QHash<QString, qint64> &values)
{
    for (auto it = values.cbegin(); it != values.cend(); ++it) {
        if (!m_entries.contains(it.key()))
            continue;
        Entry e = m_entries.value(it.key());
        e.device = it.value();
        if (e.edited && *e.edited == it.value()) {
            e.edited.reset(); // the device already holds what was typed
            e.error.clear();
        }
        update(it.key(), e);
    }
}

void ParameterStore::forgetDeviceValues()
{
    if (m_file || m_replay)
        return;                                // a file's or a log's values: no link to lose
    const QStringList keys = m_entries.keys(); // update() may detach a hash a snapshot shares
    for (const QString &key : keys) {
        Entry e = m_entries.value(key);
        e.device.reset();
        update(key, e);
    }
}

void ParameterStore::restore(const Snapshot &snapshot)
{
    // By key list: the snapshot may share this hash's data, and update() detaches it.
    const QStringList keys = m_entries.keys();
    for (const QString &key : keys)
        update(key, snapshot.entries.value(key));
    setUnsavedToFlash(snapshot.unsaved);
}

void ParameterStore::setUnsupported(const QSet<QString> &keys)
{
    for (auto it = m_entries.cbegin(); it != m_entries.cend(); ++it) {
        Entry e = it.value();
        e.unsupported = keys.contains(it.key());
        if (e.unsupported) {
            e.device.reset();
            e.edited.reset();
            e.error.clear();
        }
        update(it.key(), e);
    }
}

QString ParameterStore::edit(const QString &key, qint64 raw)
{
    const Parameter *p = m_map.find(key);
    if (!p || !m_entries.contains(key))
        return QCoreApplication::translate("stepcom::ParameterStore", "unknown parameter %1")
            .arg(key);
    if (!p->writable())
        return QCoreApplication::translate("stepcom::ParameterStore", "%1 is read-only").arg(key);
    if (m_entries.value(key).unsupported)
        return QCoreApplication::translate("stepcom::ParameterStore",
                                           "%1 is not supported by this controller")
            .arg(key);
    if (const QString why = p->checkRaw(raw); !why.isEmpty())
        return why;
    Entry e = m_entries.value(key);
    e.error.clear();
    if (e.device && *e.device == raw)
        e.edited.reset();
    else
        e.edited = raw;
    update(key, e);
    return {};
}

void ParameterStore::revert(const QString &key)
{
    if (!m_entries.contains(key))
        return;
    Entry e = m_entries.value(key);
    e.edited.reset();
    e.error.clear();
    update(key, e);
}

void ParameterStore::revertAll()
{
    for (const QString &key : editedKeys())
        revert(key);
    Q_EMIT reverted();
}

QStringList ParameterStore::editedKeys() const
{
    QStringList keys;
    for (const Parameter *p : m_map.holdings()) {
        if (m_entries.value(p->key).edited)
            keys << p->key;
    }
    return keys;
}

QList<ParameterWrite> ParameterStore::pendingWrites() const
{
    QList<ParameterWrite> writes;
    for (const QString &key : editedKeys())
        writes.append({m_map.find(key), *m_entries.value(key).edited});
    return writes;
}

void ParameterStore::applyWriteOutcome(const QList<ParameterWrite> &writes,
                                       const WriteOutcome &outcome)
{
    bool anyWritten = false;
    for (const ParameterWrite &w : writes) {
        const QString &key = w.parameter->key;
        Entry e = m_entries.value(key);
        if (outcome.verified(key)) {
            anyWritten = true;
            e.device = w.raw;
            if (e.edited && *e.edited == w.raw)
                e.edited.reset();
            e.error.clear();
        } else {
            if (const WriteMismatch *m = outcome.mismatch(key)) {
                anyWritten = true; // something reached the device
                e.device = m->got;
                e.error = QCoreApplication::translate("stepcom::ParameterStore",
                                                      "the controller holds %1 instead")
                              .arg(m->got ? w.parameter->formatRaw(*m->got) : QStringLiteral("?"));
            } else if (outcome.notWritten.contains(key)) {
                e.error = QCoreApplication::translate("stepcom::ParameterStore",
                                                      "not written: an earlier write failed");
            } else {
                // Sent, but no good answer: a lost or late answer may well mean the controller
                // took the value. What it holds is unknown until read again (DeviceSession
                // reads it back), never the old value by assumption.
                e.device.reset();
                e.error = outcome.errors.isEmpty() ? QStringLiteral("write failed")
                                                   : outcome.errors.first();
            }
            e.edited = w.raw;
        }
        update(key, e);
    }
    if (anyWritten)
        setUnsavedToFlash(true);
}

void ParameterStore::holdOnly(const QHash<QString, qint64> &values)
{
    const QStringList keys = m_entries.keys(); // update() may detach a hash a snapshot shares
    for (const QString &key : keys)
        update(key,
               Entry{values.contains(key) ? std::optional<qint64>(values.value(key)) : std::nullopt,
                     std::nullopt, State::Unknown, QString()});
    setUnsavedToFlash(false);
}

void ParameterStore::openFile(const QString &name, const QHash<QString, qint64> &values)
{
    holdOnly(values);
    m_file = true;
    m_fileName = name;
    m_replay = false;
    m_replayName.clear();
    Q_EMIT originChanged();
}

void ParameterStore::closeFile()
{
    if (!m_file)
        return;
    holdOnly({});
    m_file = false;
    m_fileName.clear();
    Q_EMIT originChanged();
}

void ParameterStore::showReplay(const QString &name, const QHash<QString, qint64> &values)
{
    holdOnly(values);
    const bool began = !m_replay || m_replayName != name;
    m_replay = true;
    m_replayName = name;
    if (began)
        Q_EMIT originChanged();
}

void ParameterStore::closeReplay()
{
    if (!m_replay)
        return;
    holdOnly({});
    m_replay = false;
    m_replayName.clear();
    Q_EMIT originChanged();
}

void ParameterStore::setUnsavedToFlash(bool unsaved)
{
    if (m_unsaved == unsaved)
        return;
    m_unsaved = unsaved;
    Q_EMIT unsavedChanged(unsaved);
}

} // namespace stepcom
