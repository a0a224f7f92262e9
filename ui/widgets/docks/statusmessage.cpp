#include "widgets/docks/statusmessage.h"

#include "widgets/docks/messageview.h"

namespace stepcom {

StatusMessage::StatusMessage(MessageView *log, QWidget *parent)
    : ElidedLabel(parent)
    , m_log(log)
{
    setObjectName(QStringLiteral("statusMessage"));
    // Squeezed, a message still shows its first words; the link status gives way for it.
    setMinimumChars(16);
    m_clear.setSingleShot(true);
    connect(&m_clear, &QTimer::timeout, this, &StatusMessage::clearText);
}

void StatusMessage::post(DeviceSession::Severity severity, const QString &text)
{
    if (m_log)
        m_log->add(severity, text);
    showText(text);
}

void StatusMessage::showText(const QString &text, int ms)
{
    setFullText(text);
    if (ms > 0)
        m_clear.start(ms);
    else
        m_clear.stop();
}

void StatusMessage::clearText()
{
    m_clear.stop();
    setFullText(QString());
}

} // namespace stepcom
