#pragma once

#include "session/devicesession.h"
#include "widgets/fields/elidedlabel.h"

#include <QTimer>

namespace stepcom {

class MessageView;

// The status bar's passing message, left of the permanent link status ("Not saved to flash"):
// one line, cut with "…" where the bar has no more room rather than running under the
// indicators, the whole text in its tooltip and in the messages dock.
class StatusMessage : public ElidedLabel
{
    Q_OBJECT
public:
    explicit StatusMessage(MessageView *log, QWidget *parent = nullptr);

    // Into the messages dock and, for a few seconds, into the status bar.
    void post(DeviceSession::Severity severity, const QString &text);
    // Only in the status bar, for `ms` milliseconds (0: until the next one).
    void showText(const QString &text, int ms = kShownMs);
    void clearText();

    static constexpr int kShownMs = 5000;

private:
    MessageView *m_log;
    QTimer m_clear;
};

} // namespace stepcom
