#include "bus/portsetup.h"

#ifdef Q_OS_LINUX
#include <cerrno>
#include <cstring>
#include <linux/serial.h>
#include <sys/ioctl.h>
#include <termios.h>
#endif

namespace stepcom {

namespace {

QString driverText(const SerialAdapter &a)
{
    return a.driver.isEmpty() ? PortSetup::tr("its driver") : a.driver;
}

} // namespace

QString PortSetup::requestLowLatency(int fd)
{
#ifdef Q_OS_LINUX
    serial_struct ss{};
    if (::ioctl(fd, TIOCGSERIAL, &ss) != 0)
        return QString::fromLocal8Bit(std::strerror(errno));
    if (ss.flags & ASYNC_LOW_LATENCY)
        return {};
    ss.flags |= ASYNC_LOW_LATENCY;
    if (::ioctl(fd, TIOCSSERIAL, &ss) != 0)
        return QString::fromLocal8Bit(std::strerror(errno));
    return {};
#else
    Q_UNUSED(fd)
    return tr("not on this system");
#endif
}

QString PortSetup::applyRs485(int fd, const LinkSettings &s, const SerialAdapter &adapter)
{
    if (s.rs485 == LinkSettings::Rs485::Auto)
        return {};
#ifdef Q_OS_LINUX
    if (s.rs485 == LinkSettings::Rs485::Rts) {
        // Receiving until a request goes out.
        if (setRts(fd, false))
            return {};
        return tr("%1: the driver (%2) refused to switch RTS (%3); StepCom cannot drive the "
                  "RS-485 direction by RTS here: try --rs485 auto with an adapter that "
                  "switches by itself")
            .arg(s.portName, driverText(adapter), QString::fromLocal8Bit(std::strerror(errno)));
    }
    serial_rs485 rs{};
    rs.flags = SER_RS485_ENABLED | SER_RS485_RTS_ON_SEND;
    rs.delay_rts_before_send = quint32((s.rs485DelayBeforeUs + 999) / 1000); // the kernel's ms
    rs.delay_rts_after_send = quint32((s.rs485DelayAfterUs + 999) / 1000);
    if (::ioctl(fd, TIOCSRS485, &rs) == 0)
        return {};
    return tr("%1: the driver (%2) has no kernel RS-485 mode (%3): try --rs485 rts (StepCom "
              "switches RTS itself) or --rs485 auto (the adapter switches by itself)")
        .arg(s.portName, driverText(adapter), QString::fromLocal8Bit(std::strerror(errno)));
#else
    Q_UNUSED(fd)
    Q_UNUSED(adapter)
    return tr("%1: RS-485 direction modes need Linux: use --rs485 auto").arg(s.portName);
#endif
}

bool PortSetup::setRts(int fd, bool on)
{
#ifdef Q_OS_LINUX
    int bit = TIOCM_RTS;
    return ::ioctl(fd, on ? TIOCMBIS : TIOCMBIC, &bit) == 0;
#else
    Q_UNUSED(fd)
    Q_UNUSED(on)
    return false;
#endif
}

void PortSetup::endOfSend(int fd)
{
#ifdef Q_OS_LINUX
    ::tcdrain(fd);
    setRts(fd, false);
#else
    Q_UNUSED(fd)
#endif
}

} // namespace stepcom
