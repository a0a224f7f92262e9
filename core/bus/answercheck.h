#pragma once

#include <QModbusPdu>
#include <QString>

namespace stepcom {

// Can this answer be the answer to that request? Qt's RTU client matched by unit and function
// only, so a late answer to another request was taken; these are the checks the content
// allows: a write's answer repeats its address and value (FC05/06) or count (FC10) exactly, a
// read's carries the requested count, an exception answers the same function.
class AnswerCheck
{
public:
    // Empty when the answer (its function code byte as on the wire, exception bit included,
    // and its data) fits `request`; otherwise why not, in words. The raw byte, because
    // QModbusPdu::functionCode() drops the exception bit and isException() trips UBSan on 6.4.
    static QString mismatch(const QModbusRequest &request, int answerFunctionCode,
                            const QByteArray &answerData);
    // The exception code of an exception answer, 0 for a normal one.
    static int exceptionCode(int answerFunctionCode, const QByteArray &answerData);
};

} // namespace stepcom
