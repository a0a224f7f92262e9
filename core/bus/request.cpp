#include "bus/request.h"

#include <QCoreApplication>

namespace stepcom {

Request Request::read(quint16 address, quint16 count, Priority p)
{
    Request r;
    r.type = Type::ReadHolding;
    r.address = address;
    r.count = count;
    r.priority = p;
    return r;
}

Request Request::write(quint16 address, QVector<quint16> values, Priority p)
{
    Request r;
    r.type = Type::WriteHolding;
    r.address = address;
    r.values = std::move(values);
    r.priority = p;
    return r;
}

Request Request::coil(quint16 address, bool on, Priority p)
{
    Request r;
    r.type = Type::WriteCoil;
    r.address = address;
    r.coilOn = on;
    r.priority = p;
    return r;
}

int Request::functionCode() const
{
    switch (type) {
    case Type::ReadHolding:
        return 0x03;
    case Type::WriteHolding:
        return values.size() == 1 ? 0x06 : 0x10;
    case Type::WriteCoil:
        return 0x05;
    }
    return 0;
}

QString exceptionText(int code)
{
    const char *text = nullptr;
    switch (code) {
    case 1:
        text = QT_TRANSLATE_NOOP("stepcom::Modbus", "illegal function");
        break;
    case 2:
        text = QT_TRANSLATE_NOOP("stepcom::Modbus", "illegal data address");
        break;
    case 3:
        text = QT_TRANSLATE_NOOP("stepcom::Modbus", "illegal data value");
        break;
    case 4:
        text = QT_TRANSLATE_NOOP("stepcom::Modbus", "server device failure");
        break;
    case 5:
        text = QT_TRANSLATE_NOOP("stepcom::Modbus", "acknowledge");
        break;
    case 6:
        text = QT_TRANSLATE_NOOP("stepcom::Modbus", "server device busy");
        break;
    default:
        return QCoreApplication::translate("stepcom::Modbus", "exception %1").arg(code);
    }
    return QCoreApplication::translate("stepcom::Modbus", text) +
           QStringLiteral(" (%1)").arg(code, 2, 10, QLatin1Char('0'));
}

} // namespace stepcom
