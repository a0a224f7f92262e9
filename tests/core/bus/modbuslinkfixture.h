#pragma once

// What the ModbusLink suites share: a scripted device on a pty, a link to it, and a callback
// that keeps a request's result.
#include "bus/modbuslink.h"
#include "scripteddevice.h"

#include <QObject>
#include <QSignalSpy>
#include <QTest>

#include <memory>

namespace stepcom::test {

struct LinkOutcome
{
    bool done = false;
    Result result;
};

inline ResultCallback into(LinkOutcome *o)
{
    return [o](const Result &r) {
        o->done = true;
        o->result = r;
    };
}

class LinkFixture : public QObject
{
protected:
    std::unique_ptr<ScriptedDevice> device;
    std::unique_ptr<ModbusLink> link;

    void initLink()
    {
        device = std::make_unique<ScriptedDevice>();
        QString error;
        QVERIFY2(device->open(&error), qPrintable(error));
        link = std::make_unique<ModbusLink>();
    }
    void cleanupLink()
    {
        link.reset();
        device.reset();
    }
    void openLink(int timeoutMs = 300, int retries = 0)
    {
        LinkSettings s;
        s.portName = device->clientPath();
        s.timeoutMs = timeoutMs;
        s.retries = retries;
        QSignalSpy opened(link.get(), &ModbusLink::opened);
        link->open(s);
        QTRY_COMPARE(opened.size(), 1);
        QVERIFY2(opened.at(0).at(0).toBool(), qPrintable(opened.at(0).at(1).toString()));
        link->setQuietTimeMs(50);
    }
};

} // namespace stepcom::test
