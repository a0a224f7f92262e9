#include "proof/proofresult.h"

#include <QJsonValue>

#include <cmath>

namespace stepcom {

QJsonValue proofJsonValue(std::optional<double> v, int decimals)
{
    if (!v)
        return QJsonValue::Null;
    const double f = std::pow(10.0, decimals);
    return std::round(*v * f) / f + 0.0; // + 0.0: no "-0" in the JSON
}

QString proofOutcomeWord(ProofOutcome outcome)
{
    switch (outcome) {
    case ProofOutcome::Done:
        return QStringLiteral("done");
    case ProofOutcome::Refused:
        return QStringLiteral("refused");
    case ProofOutcome::Stopped:
        return QStringLiteral("stopped");
    case ProofOutcome::EmergencyStop:
        return QStringLiteral("estop");
    case ProofOutcome::LinkLost:
        return QStringLiteral("link_lost");
    case ProofOutcome::Restarted:
        return QStringLiteral("restarted");
    case ProofOutcome::DeviceError:
        return QStringLiteral("device_error");
    }
    return {};
}

QString proofSentences(const QString &first, const QString &second)
{
    if (first.isEmpty() || second.isEmpty())
        return first + second;
    QString head = first;
    while (head.endsWith(QLatin1Char('.')) || head.endsWith(QChar(0x3002)))
        head.chop(1);
    return QCoreApplication::translate("stepcom::ProofResult", "%1. %2").arg(head, second);
}

double LostStepResult::lost() const
{
    const double out = lostOut.value_or(0);
    const double back = lostBack.value_or(0);
    return std::abs(out) >= std::abs(back) ? out : back;
}

double LostStepResult::lostSteps() const
{
    return chunk > 0 ? lost() / chunk * 4 : 0;
}

QString LostStepResult::verdictWord() const
{
    switch (verdict) {
    case Verdict::Kept:
        return QStringLiteral("kept");
    case Verdict::Lost:
        return QStringLiteral("lost");
    case Verdict::Unknown:
        break;
    }
    return QStringLiteral("unknown");
}

QString LostStepResult::verdictText() const
{
    switch (verdict) {
    case Verdict::Kept:
        return tr("kept its steps");
    case Verdict::Lost:
        return tr("lost steps");
    case Verdict::Unknown:
        break;
    }
    return tr("not known");
}

QJsonObject LostStepResult::toJson() const
{
    const bool measured = lostOut || lostBack;
    return {{QStringLiteral("motor"), motor},
            {QStringLiteral("cycles"), cycles},
            {QStringLiteral("distance_mm"), proofJsonValue(distance, 2)},
            {QStringLiteral("speed_rpm"), speedRpm},
            {QStringLiteral("accel"), accel},
            {QStringLiteral("lost_mm"), measured ? proofJsonValue(lost()) : QJsonValue::Null},
            {QStringLiteral("lost_out_mm"), proofJsonValue(lostOut)},
            {QStringLiteral("lost_back_mm"), proofJsonValue(lostBack)},
            {QStringLiteral("lost_steps"),
             measured ? proofJsonValue(lostSteps(), 1) : QJsonValue::Null},
            {QStringLiteral("resolution_mm"), proofJsonValue(resolution, 4)},
            {QStringLiteral("repeatability_mm"), proofJsonValue(repeatability, 4)},
            {QStringLiteral("verdict"), verdictWord()},
            {QStringLiteral("outcome"), proofOutcomeWord(outcome)},
            {QStringLiteral("simulator"), simulator},
            {QStringLiteral("restored"), restored},
            {QStringLiteral("message"), text}};
}

} // namespace stepcom
