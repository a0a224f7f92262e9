#pragma once

#include "sim/model/simdevice.h"

#include <QTest>

// Shorthands for tests that drive a SimDevice by hand: a register by key, a checked write and
// a checked command (the QTest failure names what the device refused).
namespace stepcom::test {

inline qint64 value(const SimDevice &d, const char *key)
{
    return d.value(QLatin1String(key)).value_or(-999999);
}

inline void set(SimDevice &d, const char *key, qint64 raw)
{
    QString error;
    QVERIFY2(d.setValue(QLatin1String(key), raw, &error), qPrintable(error));
}

inline void cmd(SimDevice &d, const char *key)
{
    QString error;
    QVERIFY2(d.command(QLatin1String(key), &error), qPrintable(error));
}

} // namespace stepcom::test
