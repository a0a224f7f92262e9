#include "ctlrunner.h"

#include "ctlmonitor.h"
#include "ctlmotionwait.h"

#include "bus/modbuslink.h"
#include "bus/trafficlog.h"
#include "device/motionjudge.h"
#include "sim/simhost.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

#include <cstdio>

namespace stepcom {

namespace {

QString accessName(const Parameter &p)
{
    switch (p.access) {
    case Access::ReadOnly:
        return QStringLiteral("r");
    case Access::ReadWrite:
        return QStringLiteral("rw");
    case Access::Command:
        return QStringLiteral("w");
    }
    return {};
}

QString commandName(CommandClass c)
{
    switch (c) {
    case CommandClass::Emergency:
        return QStringLiteral("emergency");
    case CommandClass::Motion:
        return QStringLiteral("motion");
    case CommandClass::Output:
        return QStringLiteral("output");
    case CommandClass::Setting:
        return QStringLiteral("setting");
    case CommandClass::Destructive:
        return QStringLiteral("destructive");
    case CommandClass::None:
        break;
    }
    return {};
}

QJsonValue engineering(const Parameter &p, qint64 raw)
{
    if (p.scale == 1)
        return QJsonValue(double(raw));
    return QJsonValue(p.formatRaw(raw).toDouble());
}

} // namespace

CtlRunner::CtlRunner(const CtlOptions &options, const RegisterMap &map, QObject *parent)
    : QObject(parent)
    , m_options(options)
    , m_map(map)
    , m_out(stdout)
    , m_err(stderr)
{}

void CtlRunner::start()
{
    const QString &c = m_options.command;
    if (c == QLatin1String("params"))
        runParams();
    else if (c == QLatin1String("read"))
        runRead();
    else if (c == QLatin1String("write"))
        runWrite();
    else if (c == QLatin1String("command"))
        runCommand();
    else if (c == QLatin1String("monitor"))
        runMonitor();
    else if (c == QLatin1String("dump"))
        runDump();
    else if (c == QLatin1String("diff"))
        runDiff();
    else if (c == QLatin1String("apply"))
        runApply();
    else if (c == QLatin1String("report"))
        runReport();
    else
        fail(UsageError, tr("unknown command '%1' (params, read, write, command, monitor, dump, "
                            "diff, apply, report)")
                             .arg(c));
}

void CtlRunner::fail(int code, const QString &message)
{
    m_err << QStringLiteral("stepcomctl: ") << message << Qt::endl;
    finish(code);
}

void CtlRunner::finish(int code)
{
    if (m_finished)
        return;
    m_finished = true;
    m_out.flush();
    m_err.flush();
    if (m_link)
        m_link->close(tr("done"));
    QTimer::singleShot(0, this, [this, code] { Q_EMIT finished(code); });
}

QString CtlRunner::valueText(const Parameter &p, qint64 raw) const
{
    QString text = p.formatRaw(raw);
    if (!p.values.isEmpty()) {
        const QString label = p.displayRaw(raw);
        if (label != text)
            text += QStringLiteral(" (%1)").arg(label);
    } else if (!p.unit.isEmpty()) {
        text += QLatin1Char(' ') + p.unit;
    }
    return text;
}

void CtlRunner::connectThen(std::function<void()> next)
{
    if (m_options.target == CtlOptions::Target::None) {
        fail(UsageError, tr("no controller given: use --port PATH, --tcp HOST[:PORT] or --sim"));
        return;
    }
    if (m_options.target == CtlOptions::Target::Sim && !startSimulator())
        return;
    m_link = new ModbusLink(this);
    m_link->traffic()->setMap(&m_map);
    if (m_options.verbose) {
        connect(m_link->traffic(), &TrafficLog::entryAdded, this,
                [this](const TrafficEntry &e) { m_err << TrafficLog::format(e) << Qt::endl; });
    }
    m_device = new DeviceClient(m_link, m_map, this);
    // Only the first opening runs the command: a write of device.baud reopens the link at the
    // new baud, and that must not start the command a second time.
    connect(
        m_link, &ModbusLink::opened, this,
        [this, next](bool ok, const QString &reason) {
            if (!ok) {
                fail(m_linkError,
                     tr("cannot connect to %1: %2").arg(m_options.link.describe(), reason));
                return;
            }
            next();
        },
        Qt::SingleShotConnection);
    m_link->open(m_options.link);
}

bool CtlRunner::startSimulator()
{
    // The built-in controller runs in this process; on Unix it is reached over a
    // pseudo-terminal, so --sim takes the same RTU path as a real adapter.
    m_sim = new SimHost(this);
    SimOptions sim;
    sim.map = m_map;
#ifdef Q_OS_UNIX
    sim.rtu = true;
#else
    sim.tcp = true;
#endif
    QString error;
    if (!m_sim->start(sim, &error)) {
        fail(m_linkError, tr("cannot start the built-in simulator: %1").arg(error));
        return false;
    }
    if (sim.rtu) {
        m_options.link.transport = LinkSettings::Transport::Rtu;
        m_options.link.portName = m_sim->rtuPath();
    } else {
        m_options.link.transport = LinkSettings::Transport::Tcp;
        m_options.link.host = m_sim->tcpAddress().toString();
        m_options.link.tcpPort = m_sim->tcpPort();
    }
    return true;
}

void CtlRunner::runParams()
{
    if (m_options.json) {
        QJsonArray array;
        for (const Parameter &p : m_map.parameters()) {
            QJsonObject o{{QStringLiteral("key"), p.key},
                          {QStringLiteral("kind"),
                           p.isHolding() ? QStringLiteral("holding") : QStringLiteral("coil")},
                          {QStringLiteral("plc"), p.plc},
                          {QStringLiteral("address"), p.address},
                          {QStringLiteral("words"), p.isHolding() ? p.words : 1},
                          {QStringLiteral("signed"), p.isSigned},
                          {QStringLiteral("scale"), p.scale},
                          {QStringLiteral("unit"), p.unit},
                          {QStringLiteral("access"), accessName(p)},
                          {QStringLiteral("group"), p.group},
                          {QStringLiteral("label"), p.label.en},
                          {QStringLiteral("label_zh_CN"), p.label.zh},
                          {QStringLiteral("help"), p.help.en}};
            if (p.isHolding()) {
                o.insert(QStringLiteral("min"), engineering(p, p.rawMin));
                o.insert(QStringLiteral("max"), engineering(p, p.rawMax));
                if (!p.values.isEmpty()) {
                    QJsonArray values;
                    for (const EnumValue &v : p.values)
                        values.append(QJsonObject{{QStringLiteral("value"), double(v.value)},
                                                  {QStringLiteral("label"), v.label.en}});
                    o.insert(QStringLiteral("values"), values);
                }
            } else {
                o.insert(QStringLiteral("min"), QJsonValue());
                o.insert(QStringLiteral("max"), QJsonValue());
                o.insert(QStringLiteral("command"), commandName(p.command));
            }
            array.append(o);
        }
        m_out << QString::fromUtf8(QJsonDocument(array).toJson(QJsonDocument::Indented));
    } else {
        for (const Parameter &p : m_map.parameters()) {
            const QString range = p.isHolding() ? p.rangeText() : commandName(p.command);
            m_out << QStringLiteral("%1  %2  %3  %4  %5")
                         .arg(p.key, -26)
                         .arg(p.registerName(), -15)
                         .arg(accessName(p), -2)
                         .arg(p.label.en, -32)
                         .arg(range)
                  << Qt::endl;
        }
    }
    finish(Ok);
}

void CtlRunner::runRead()
{
    QList<const Parameter *> params;
    for (const QString &key : std::as_const(m_options.arguments)) {
        const Parameter *p = m_map.find(key);
        if (!p) {
            fail(UsageError, tr("unknown parameter '%1' (see: stepcomctl params)").arg(key));
            return;
        }
        if (!p->readable()) {
            fail(UsageError, tr("%1 is a command and cannot be read").arg(key));
            return;
        }
        params << p;
    }
    if (params.isEmpty())
        params = m_map.holdings();
    connectThen([this, params] {
        m_device->read(params, Priority::Read, [this, params](const ReadOutcome &r) {
            if (m_options.json) {
                QJsonObject o;
                for (const Parameter *p : params) {
                    if (r.values.contains(p->key))
                        o.insert(p->key, engineering(*p, r.values.value(p->key)));
                }
                m_out << QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Indented));
            } else {
                for (const Parameter *p : params) {
                    if (r.values.contains(p->key))
                        m_out << p->key << QStringLiteral(" = ")
                              << valueText(*p, r.values.value(p->key)) << Qt::endl;
                }
            }
            if (!r.ok) {
                for (const QString &e : r.errors)
                    m_err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
                finish(DeviceError);
                return;
            }
            finish(Ok);
        });
    });
}

void CtlRunner::runWrite()
{
    if (m_options.arguments.isEmpty()) {
        fail(UsageError, tr("write needs KEY=VALUE arguments"));
        return;
    }
    QList<ParameterWrite> writes;
    QStringList problems;
    for (const QString &arg : std::as_const(m_options.arguments)) {
        const qsizetype eq = arg.indexOf(QLatin1Char('='));
        if (eq <= 0) {
            problems << tr("'%1' is not KEY=VALUE").arg(arg);
            continue;
        }
        const QString key = arg.left(eq).trimmed();
        const Parameter *p = m_map.find(key);
        if (!p) {
            problems << tr("unknown parameter '%1' (see: stepcomctl params)").arg(key);
            continue;
        }
        if (!p->writable()) {
            problems << (p->isCoil() ? tr("%1 is a command: use 'stepcomctl command %1'").arg(key)
                                     : tr("%1 is read-only").arg(key));
            continue;
        }
        QString error;
        const auto raw = p->parse(arg.mid(eq + 1), &error);
        if (!raw) {
            problems << error;
            continue;
        }
        writes.append({p, *raw});
    }
    if (problems.isEmpty())
        problems = DeviceClient::validate(writes); // duplicates, as the device client checks
    if (!problems.isEmpty()) {
        for (const QString &p : std::as_const(problems))
            m_err << QStringLiteral("stepcomctl: ") << p << Qt::endl;
        m_err << QStringLiteral("stepcomctl: ") << tr("nothing was written") << Qt::endl;
        finish(UsageError);
        return;
    }
    connectThen([this, writes] {
        m_device->write(writes, [this, writes](const WriteOutcome &w) {
            for (const ParameterWrite &pw : writes) {
                const bool verified = w.written.contains(pw.parameter->key) &&
                                      std::none_of(w.mismatches.cbegin(), w.mismatches.cend(),
                                                   [&](const WriteMismatch &m) {
                                                       return m.key == pw.parameter->key;
                                                   });
                if (verified)
                    m_out << pw.parameter->key << QStringLiteral(" = ")
                          << valueText(*pw.parameter, pw.raw) << QStringLiteral("  ")
                          << tr("(written, verified)") << Qt::endl;
            }
            for (const QString &e : w.errors)
                m_err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
            if (!w.notWritten.isEmpty())
                m_err << QStringLiteral("stepcomctl: ")
                      << tr("not written: %1").arg(w.notWritten.join(QLatin1String(", ")))
                      << Qt::endl;
            if (!w.ok) {
                finish(DeviceError);
                return;
            }
            if (!m_options.saveToFlash) {
                finish(Ok);
                return;
            }
            saveToFlashThenFinish();
        });
    });
}

void CtlRunner::runCommand()
{
    if (m_options.arguments.size() != 1) {
        fail(UsageError, tr("command needs exactly one command name (see: stepcomctl params)"));
        return;
    }
    const QString key = m_options.arguments.first();
    const Parameter *p = m_map.find(key);
    if (!p || !p->isCoil()) {
        fail(UsageError, p ? tr("%1 is a parameter, not a command: use read or write").arg(key)
                           : tr("unknown command '%1' (see: stepcomctl params)").arg(key));
        return;
    }
    if (p->command == CommandClass::Destructive && !m_options.yes) {
        fail(UsageError,
             tr("%1 destroys settings (%2); add --yes if you mean it").arg(key, p->help.en));
        return;
    }
    if (m_options.wait) {
        if (!MotionJudge::kindOf(m_map, key)) {
            fail(UsageError, tr("--wait: %1 has no end to wait for (single move, home, home in "
                                "order, return to data zero, arc and line have one)")
                                 .arg(key));
            return;
        }
        connectThen([this, p] {
            auto *wait = new CtlMotionWait(m_device, *p, m_options.json, this);
            connect(wait, &CtlMotionWait::finished, this, &CtlRunner::finish);
            wait->start();
        });
        return;
    }
    connectThen([this, p] {
        m_device->command(*p, [this, p](const Result &r) {
            if (!r.ok) {
                fail(DeviceError, r.errorText);
                return;
            }
            // A moving command is only acknowledged: its end is known with --wait.
            m_out << (p->command == CommandClass::Motion
                          ? tr("%1: sent (add --wait to wait for how it ends)").arg(p->key)
                          : tr("%1: done").arg(p->key))
                  << Qt::endl;
            finish(Ok);
        });
    });
}

void CtlRunner::runMonitor()
{
    if (!m_options.arguments.isEmpty()) {
        fail(UsageError, tr("monitor takes no arguments, only --count and --interval"));
        return;
    }
    connectThen([this] {
        auto *monitor = new CtlMonitor(m_device, m_options.count, m_options.intervalMs, this);
        connect(monitor, &CtlMonitor::finished, this, &CtlRunner::finish);
        monitor->start();
    });
}

} // namespace stepcom
