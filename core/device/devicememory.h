#pragma once

#include "device/parameterstore.h"

#include <QHash>

namespace stepcom {

// What the session knows of each controller of the line while another one is in view: the
// store's entries (values read, edits typed, failed writes, unsaved to flash) are put aside
// when the view moves away and put back, with the background poll's newer status on top, when
// it returns. The store stays the one object the pages are bound to; only what it holds moves.
class DeviceMemory
{
public:
    void putAside(int id, const ParameterStore &store);
    // Puts back what was put aside for `id` (nothing: every value unknown), `newer` on top.
    void bringBack(int id, ParameterStore &store, const QHash<QString, qint64> &newer);
    // The device values known of a device not in view, `newer` on top.
    QHash<QString, qint64> values(int id, const QHash<QString, qint64> &newer) const;
    // What device `id` holds now (read again after a restart); its edits stay.
    void setDeviceValues(int id, const QHash<QString, qint64> &values);
    bool holds(int id) const { return m_aside.contains(id); }
    // The link is gone: no device's values are known any more (edits stay).
    void forgetDeviceValues();

private:
    QHash<int, ParameterStore::Snapshot> m_aside;
};

} // namespace stepcom
