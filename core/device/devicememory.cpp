#include "device/devicememory.h"

namespace stepcom {

void DeviceMemory::putAside(int id, const ParameterStore &store)
{
    m_aside.insert(id, store.snapshot());
}

void DeviceMemory::bringBack(int id, ParameterStore &store, const QHash<QString, qint64> &newer)
{
    store.restore(m_aside.take(id));
    store.setDeviceValues(newer); // keeps an edit, as a poll does
}

QHash<QString, qint64> DeviceMemory::values(int id, const QHash<QString, qint64> &newer) const
{
    QHash<QString, qint64> values;
    const ParameterStore::Snapshot aside = m_aside.value(id);
    for (auto it = aside.entries.cbegin(); it != aside.entries.cend(); ++it)
        if (it->device)
            values.insert(it.key(), *it->device);
    for (auto it = newer.cbegin(); it != newer.cend(); ++it)
        values.insert(it.key(), it.value());
    return values;
}

void DeviceMemory::setDeviceValues(int id, const QHash<QString, qint64> &values)
{
    ParameterStore::Snapshot &aside = m_aside[id];
    for (auto it = values.cbegin(); it != values.cend(); ++it)
        aside.entries[it.key()].device = it.value();
}

void DeviceMemory::forgetDeviceValues()
{
    for (ParameterStore::Snapshot &s : m_aside)
        for (ParameterStore::Entry &e : s.entries)
            e.device.reset();
}

} // namespace stepcom
