#include "bus/answercheck.h"

#include "bus/bigendian.h"

#include <QCoreApplication>

namespace stepcom {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("stepcom::AnswerCheck", text);
}

int fcOf(const QModbusPdu &pdu)
{
    return quint8(pdu.functionCode()); // Qt 6.4 stores it sign-extended
}

// -1 where the frame is too short to hold the word.
int checkedWord(const QByteArray &data, int at)
{
    return data.size() < at + 2 ? -1 : bigendian::wordAt(data, at);
}

QString hex4(int value)
{
    return QString::number(value, 16).rightJustified(4, QLatin1Char('0')).toUpper();
}

} // namespace

int AnswerCheck::exceptionCode(int answerFunctionCode, const QByteArray &answerData)
{
    if (!(answerFunctionCode & 0x80) || answerData.size() != 1)
        return 0;
    return quint8(answerData.at(0));
}

QString AnswerCheck::mismatch(const QModbusRequest &request, int answerFunctionCode,
                              const QByteArray &answerData)
{
    const int fc = fcOf(request);
    const int afc = answerFunctionCode & 0xFF;
    const QByteArray q = request.data();
    const QByteArray &a = answerData;
    if ((afc & 0x7F) != fc)
        return tr("function %1 answered a request of function %2")
            .arg(afc & 0x7F, 2, 16, QLatin1Char('0'))
            .arg(fc, 2, 16, QLatin1Char('0'));
    if (afc & 0x80) {
        if (a.size() != 1)
            return tr("exception answer of %1 bytes").arg(a.size());
        return {};
    }
    switch (fc) {
    case 0x03: {
        const int asked = checkedWord(q, 2);
        const int carried = a.isEmpty() ? 0 : quint8(a.at(0)) / 2;
        if (a.isEmpty() || quint8(a.at(0)) != asked * 2 || a.size() != 1 + asked * 2)
            return tr("FC03 answer carried %1 registers, %2 were asked for")
                .arg(carried)
                .arg(asked);
        return {};
    }
    case 0x05:
    case 0x06:
        if (a != q)
            return tr("FC%1 answer for 0x%2 = 0x%3, the request wrote 0x%4 = 0x%5")
                .arg(fc, 2, 16, QLatin1Char('0'))
                .arg(hex4(checkedWord(a, 0)), hex4(checkedWord(a, 2)), hex4(checkedWord(q, 0)),
                     hex4(checkedWord(q, 2)));
        return {};
    case 0x10:
        if (a != q.left(4))
            return tr("FC10 answer for %1 registers at 0x%2, the request wrote %3 at 0x%4")
                .arg(checkedWord(a, 2))
                .arg(hex4(checkedWord(a, 0)))
                .arg(checkedWord(q, 2))
                .arg(hex4(checkedWord(q, 0)));
        return {};
    default:
        return {};
    }
}

} // namespace stepcom
