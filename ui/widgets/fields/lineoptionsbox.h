#pragma once

#include <QGroupBox>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace stepcom {

struct LinkSettings;

// The line's timing and the adapter's habits: answer delay, turnaround and echo. Rarely
// changed, so they sit below the Connect button; when answers begin with the request's own
// bytes the box says so and offers to turn the echo option on.
class LineOptionsBox : public QGroupBox
{
    Q_OBJECT
public:
    explicit LineOptionsBox(QWidget *parent = nullptr);

    void apply(const LinkSettings &settings);
    void fillInto(LinkSettings &settings) const;
    // Answers began with the request's own bytes: show the offer (not when echo is on already).
    void offerEcho();
    void hideEchoOffer();
    bool echoOffered() const;
    void retranslate();

    QSpinBox *answerDelay() const { return m_answerDelay; }
    QSpinBox *turnaround() const { return m_turnaround; }
    QCheckBox *echo() const { return m_echo; }
    // Who switches an RS-485 adapter's direction (LinkSettings::Rs485, in its order).
    QComboBox *rs485() const { return m_rs485; }
    QPushButton *acceptEcho() const { return m_acceptEcho; }

Q_SIGNALS:
    // The user took the offer: echo is on now, and the link should be opened again with it.
    void echoAccepted();

private:
    QLabel *m_answerDelayLabel;
    QSpinBox *m_answerDelay;
    QLabel *m_turnaroundLabel;
    QSpinBox *m_turnaround;
    QCheckBox *m_echo;
    QLabel *m_rs485Label;
    QComboBox *m_rs485;
    QWidget *m_offer;
    QLabel *m_offerText;
    QPushButton *m_acceptEcho;
};

} // namespace stepcom
