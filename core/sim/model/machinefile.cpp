#include "sim/model/machinefile.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>

#include <cmath>

namespace stepcom {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("stepcom::MachineFile", text);
}

// Reads one object's keys, remembering the first problem with its key path.
class Reader
{
public:
    Reader(const QJsonObject &object, const QString &path, QString *problem)
        : m_object(object)
        , m_path(path)
        , m_problem(problem)
    {}

    QString keyPath(const QString &key) const
    {
        return m_path.isEmpty() ? key : m_path + QLatin1Char('.') + key;
    }
    bool fail(const QString &key, const QString &why)
    {
        if (m_problem->isEmpty())
            *m_problem = QStringLiteral("%1: %2").arg(keyPath(key), why);
        return false;
    }
    bool known(const QStringList &keys)
    {
        for (auto it = m_object.begin(); it != m_object.end(); ++it) {
            if (!keys.contains(it.key()))
                return fail(it.key(), tr("unknown key"));
        }
        return true;
    }
    // A number from `min` to `max` into `out`; absent leaves `out` as it is.
    bool number(const QString &key, double min, double max, double *out)
    {
        const QJsonValue v = m_object.value(key);
        if (v.isUndefined())
            return true;
        if (!v.isDouble() || !std::isfinite(v.toDouble()))
            return fail(key, tr("must be a number"));
        const double d = v.toDouble();
        if (d < min || d > max)
            return fail(key,
                        tr("%1 is out of range (%2 to %3)")
                            .arg(QString::number(d), QString::number(min), QString::number(max)));
        *out = d;
        return true;
    }
    bool optionalNumber(const QString &key, double min, double max, std::optional<double> *out)
    {
        if (m_object.value(key).isUndefined())
            return true;
        double d = 0;
        if (!number(key, min, max, &d))
            return false;
        *out = d;
        return true;
    }
    bool whole(const QString &key, double min, double max, double *out)
    {
        const QJsonValue v = m_object.value(key);
        if (!v.isUndefined() && v.isDouble() && v.toDouble() != std::floor(v.toDouble()))
            return fail(key, tr("must be a whole number"));
        return number(key, min, max, out);
    }
    bool boolean(const QString &key, bool *out)
    {
        const QJsonValue v = m_object.value(key);
        if (v.isUndefined())
            return true;
        if (!v.isBool())
            return fail(key, tr("must be true or false"));
        *out = v.toBool();
        return true;
    }
    bool object(const QString &key, QJsonObject *out)
    {
        const QJsonValue v = m_object.value(key);
        if (v.isUndefined())
            return true;
        if (!v.isObject())
            return fail(key, tr("must be an object"));
        *out = v.toObject();
        return true;
    }

private:
    QJsonObject m_object;
    QString m_path;
    QString *m_problem;
};

constexpr double kMaxRpm = 100000;
constexpr double kMaxMm = 100000;

bool readWiring(const QJsonObject &o, const QString &path, QString *problem, AxisPhysics::Wiring *w)
{
    Reader r(o, path, problem);
    double negative = 0;
    double positive = 0;
    double home = 0;
    if (!r.known(
            {QStringLiteral("negative"), QStringLiteral("positive"), QStringLiteral("home")}) ||
        !r.whole(QStringLiteral("negative"), 0, 4, &negative) ||
        !r.whole(QStringLiteral("positive"), 0, 4, &positive) ||
        !r.whole(QStringLiteral("home"), 0, 4, &home))
        return false;
    *w = {int(negative), int(positive), int(home)};
    return true;
}

bool readAxis(const QJsonObject &o, const QString &path, QString *problem, AxisPhysics *a)
{
    Reader r(o, path, problem);
    const QStringList keys = {QStringLiteral("pull_out_rpm"),
                              QStringLiteral("pull_in_rpm"),
                              QStringLiteral("accel_limit_rpm_per_s"),
                              QStringLiteral("backlash_mm"),
                              QStringLiteral("travel_mm"),
                              QStringLiteral("start_mm"),
                              QStringLiteral("negative_switch_mm"),
                              QStringLiteral("positive_switch_mm"),
                              QStringLiteral("switch_jitter_mm"),
                              QStringLiteral("switch_hysteresis_mm"),
                              QStringLiteral("hard_stop_mm"),
                              QStringLiteral("wiring")};
    QJsonObject wiring;
    if (!r.known(keys) ||
        !r.number(QStringLiteral("pull_out_rpm"), 0.01, kMaxRpm, &a->pullOutRpm) ||
        !r.number(QStringLiteral("pull_in_rpm"), 0.01, kMaxRpm, &a->pullInRpm) ||
        !r.number(QStringLiteral("accel_limit_rpm_per_s"), 0.01, 1e9, &a->accelLimitRpmPerS) ||
        !r.number(QStringLiteral("backlash_mm"), 0, 100, &a->backlashMm) ||
        !r.optionalNumber(QStringLiteral("travel_mm"), 0.01, kMaxMm, &a->travelMm) ||
        !r.optionalNumber(QStringLiteral("start_mm"), -kMaxMm, kMaxMm, &a->startMm) ||
        !r.number(QStringLiteral("negative_switch_mm"), -kMaxMm, kMaxMm, &a->negativeSwitchMm) ||
        !r.optionalNumber(QStringLiteral("positive_switch_mm"), -kMaxMm, kMaxMm,
                          &a->positiveSwitchMm) ||
        !r.number(QStringLiteral("switch_jitter_mm"), 0, 10, &a->switchJitterMm) ||
        !r.number(QStringLiteral("switch_hysteresis_mm"), 0, 100, &a->switchHysteresisMm) ||
        !r.number(QStringLiteral("hard_stop_mm"), 0, kMaxMm, &a->hardStopMm) ||
        !r.object(QStringLiteral("wiring"), &wiring))
        return false;
    if (a->pullInRpm > a->pullOutRpm)
        return r.fail(QStringLiteral("pull_in_rpm"),
                      tr("%1 is above pull_out_rpm (%2): a motor cannot start faster than it runs")
                          .arg(a->pullInRpm)
                          .arg(a->pullOutRpm));
    const double positive = a->positiveSwitchMm.value_or(a->travelMm.value_or(200));
    if (a->positiveSwitchMm && positive <= a->negativeSwitchMm)
        return r.fail(
            QStringLiteral("positive_switch_mm"),
            tr("%1 is not above negative_switch_mm (%2)").arg(positive).arg(a->negativeSwitchMm));
    const bool knowsPositive = a->travelMm || a->positiveSwitchMm;
    if (a->startMm && (*a->startMm < a->negativeSwitchMm - a->hardStopMm ||
                       (knowsPositive && *a->startMm > positive + a->hardStopMm)))
        return r.fail(QStringLiteral("start_mm"),
                      tr("%1 is beyond the hard stops").arg(*a->startMm));
    if (o.contains(QStringLiteral("wiring"))) {
        AxisPhysics::Wiring w;
        if (!readWiring(wiring, r.keyPath(QStringLiteral("wiring")), problem, &w))
            return false;
        a->wiring = w;
    }
    return true;
}

} // namespace

std::optional<MachineSettings> MachineFile::load(const QString &path, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        if (error)
            *error = tr("%1: cannot read the machine file: %2").arg(path, file.errorString());
        return std::nullopt;
    }
    return parse(file.readAll(), path, error);
}

std::optional<MachineSettings> MachineFile::parse(const QByteArray &json, const QString &name,
                                                  QString *error)
{
    auto refuse = [&](const QString &why) -> std::optional<MachineSettings> {
        if (error)
            *error = tr("%1: %2").arg(name, why);
        return std::nullopt;
    };
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return refuse(
            tr("not JSON (%1 at offset %2)").arg(parseError.errorString()).arg(parseError.offset));
    if (!doc.isObject())
        return refuse(tr("not a JSON object"));
    const QJsonObject root = doc.object();
    if (root.value(QStringLiteral("format")).toString() != QLatin1String("stepcom-sim-machine"))
        return refuse(tr("format: must be \"stepcom-sim-machine\""));
    if (root.value(QStringLiteral("version")) != QJsonValue(1))
        return refuse(tr("version: must be 1"));
    QString problem;
    Reader r(root, QString(), &problem);
    MachineSettings m;
    m.source = name;
    double seed = m.seed;
    QJsonObject axes;
    if (!r.known({QStringLiteral("format"), QStringLiteral("version"),
                  QStringLiteral("homing_zeroes_count"), QStringLiteral("seed"),
                  QStringLiteral("axes")}) ||
        !r.boolean(QStringLiteral("homing_zeroes_count"), &m.homingZeroesCount) ||
        !r.whole(QStringLiteral("seed"), 0, 4294967295.0, &seed) ||
        !r.object(QStringLiteral("axes"), &axes))
        return refuse(problem);
    m.seed = quint32(seed);
    static const QRegularExpression motorKey(QStringLiteral("^motor([1-9])$"));
    for (auto it = axes.begin(); it != axes.end(); ++it) {
        const QString path = QStringLiteral("axes.") + it.key();
        const auto match = motorKey.match(it.key());
        if (!match.hasMatch())
            return refuse(tr("%1: unknown key (the axes are motor1, motor2, ...)").arg(path));
        if (!it.value().isObject())
            return refuse(tr("%1: must be an object").arg(path));
        AxisPhysics a;
        if (!readAxis(it.value().toObject(), path, &problem, &a))
            return refuse(problem);
        m.axes.insert(match.captured(1).toInt(), a);
    }
    return m;
}

} // namespace stepcom
