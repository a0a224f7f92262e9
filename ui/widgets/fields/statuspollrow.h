#pragma once

#include <QTimer>
#include <QWidget>

class QComboBox;
class QLabel;

namespace stepcom {

class DeviceSession;

// How often the live status is read and how often it actually was, one row where the link is
// described (the Connection page's Link box): the choice (remembered; full rate watches a move
// closely, slower leaves the line to others) and the rate the poller achieves.
class StatusPollRow : public QWidget
{
    Q_OBJECT
public:
    explicit StatusPollRow(DeviceSession *session, QWidget *parent = nullptr);

    // The poll interval chooser (ms as item data; 0 = as fast as the link allows).
    QComboBox *intervalBox() const { return m_interval; }
    // "12.3 Hz", "measuring…" or "unknown".
    QString rateText() const;

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void refreshRate();

    DeviceSession *m_session;
    QLabel *m_intervalCaption;
    QComboBox *m_interval;
    QLabel *m_rateCaption;
    QLabel *m_rate;
    QTimer m_rateTimer;
};

} // namespace stepcom
