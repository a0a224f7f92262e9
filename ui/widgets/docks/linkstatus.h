#pragma once

#include <QTimer>
#include <QWidget>

class QLabel;
class QPushButton;

namespace stepcom {

class DeviceSession;
class ElidedLabel;

// The status bar's right side: link state, port/baud/id, transactions per second, errors and
// the "not saved to flash" warning (the status rate is the Connection page's); after a link loss
// the countdown to the next attempt and a Cancel button.
class LinkStatus : public QWidget
{
    Q_OBJECT
public:
    explicit LinkStatus(DeviceSession *session, QWidget *parent = nullptr);
    QString stateText() const;

protected:
    void changeEvent(QEvent *event) override;

private:
    void refresh();
    void refreshReconnect();

    DeviceSession *m_session;
    QLabel *m_state;
    // Where, how fast and how many errors give way on a narrow screen (cut, whole in the
    // tooltip); the state and "not saved to flash" are always whole.
    ElidedLabel *m_where;
    ElidedLabel *m_rate;
    ElidedLabel *m_errors;
    QLabel *m_unsaved;
    QLabel *m_reconnect;
    QPushButton *m_cancelReconnect;
    QTimer m_timer;
    quint64 m_lastAnswers = 0;
    qint64 m_lastMs = 0;
    double m_perSecond = 0.0;
};

} // namespace stepcom
