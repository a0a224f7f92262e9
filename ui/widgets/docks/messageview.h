#pragma once

#include "session/devicesession.h"

#include <QWidget>

class QListWidget;
class QPushButton;

namespace stepcom {

// The messages dock: what the session reported (connected, written and verified, refused by
// the controller ...), newest last, with time and severity.
class MessageView : public QWidget
{
    Q_OBJECT
public:
    explicit MessageView(QWidget *parent = nullptr);
    void add(DeviceSession::Severity severity, const QString &text);
    QStringList texts() const;
    int count() const;

protected:
    void changeEvent(QEvent *event) override;

private:
    QListWidget *m_list;
    QPushButton *m_clear;
};

} // namespace stepcom
