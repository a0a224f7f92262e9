#pragma once

#include <QSerialPort>
#include <QString>

namespace stepcom {

// How to reach one controller. Defaults are the controller's factory settings.
struct LinkSettings
{
    // Rtu: a serial port; Tcp: Modbus TCP (MBAP); RtuTcp: RTU frames with CRC over a plain TCP
    // socket, as transparent RS-485/Ethernet converters pass them on.
    enum class Transport { Rtu, Tcp, RtuTcp };
    Transport transport = Transport::Rtu;
    QString portName; // serial device path or name (/dev/ttyUSB0, COM3, a pty path)
    int baud = 9600;
    QSerialPort::Parity parity = QSerialPort::NoParity;
    QSerialPort::StopBits stopBits = QSerialPort::OneStop;
    QString host = QStringLiteral("127.0.0.1");
    int tcpPort = 502;
    int deviceId = 1;
    // A 49-register read at 4800 baud takes about 280 ms on the wire plus the 35 ms answer
    // delay; 500 ms leaves room for USB adapters' latency. With adaptTimeout this is the most
    // the link waits: it waits less once it has timed a controller's answers.
    int timeoutMs = 500;
    // Fit the answer timeout to the measured round trips (4x the median plus the answer's
    // frame time), never below what the manual asks, never above timeoutMs.
    bool adaptTimeout = true;
    int retries = 2;
    // How long the controller takes to answer (the manual: allow 35 ms). Only a hint: the
    // least an adapted timeout leaves it. Answers are judged by what they say, whenever they
    // come: many controllers answer in a few ms.
    int answerDelayMs = 35;
    // The adapter returns every byte it sends (half-duplex adapters without echo suppression):
    // the request's own bytes are removed before the answer is read.
    bool echo = false;
    // Extra silence after an answer before the next request, for converters that need it.
    int turnaroundMs = 0;
    // Who switches an RS-485 adapter between sending and receiving. Auto: the adapter itself
    // (most do); Kernel: the driver's RS-485 mode (TIOCSRS485, RTS on send, the delays before
    // and after sending in us); Rts: StepCom raises RTS for a request and drops it once the
    // last byte has left.
    enum class Rs485 { Auto, Kernel, Rts };
    Rs485 rs485 = Rs485::Auto;
    int rs485DelayBeforeUs = 0;
    int rs485DelayAfterUs = 0;

    // Host and port rather than a serial port (Modbus TCP or RTU over TCP).
    bool isNetwork() const { return transport != Transport::Rtu; }
    // RTU frames with CRC (a serial port or a transparent converter).
    bool isRtuFraming() const { return transport != Transport::Tcp; }

    // "/dev/ttyUSB0 · 9600 8N1 · id 1" or "192.168.0.7:502 · id 1".
    QString describe() const;
    // Empty when usable, else what is wrong ("baud 1200 is not one of 4800, 9600, 19200, 38400").
    QString validate() const;
    // Seconds the wire needs for `bytes` characters at this baud (10 bits a character); 0 on TCP.
    double charTimeMs() const;

    static const QList<int> &supportedBauds();
    static QString parityName(QSerialPort::Parity parity);
    // "auto", "kernel", "rts"; parseRs485 false for anything else.
    static QString rs485Name(Rs485 mode);
    static bool parseRs485(const QString &text, Rs485 *mode);
    static bool parseParity(const QString &text, QSerialPort::Parity *parity);
    // "HOST:PORT" or, when `defaultPort` > 0, "HOST" alone; false when it is neither.
    static bool parseHostPort(const QString &text, int defaultPort, QString *host, int *port);
};

bool operator==(const LinkSettings &a, const LinkSettings &b);

} // namespace stepcom
