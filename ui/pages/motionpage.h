#pragma once

#include "base/page.h"

#include <QHash>

#include <functional>

class QCheckBox;
class QFrame;
class QGroupBox;
class QLabel;
class QPushButton;

namespace stepcom {

class AboutBox;
class HomingOrderEditor;
class JogController;
class JogKeys;
class JogPanel;
class Led;
class GamepadPanel;
class TravelLimitsEditor;
class WriteFlow;

// "Jog and home": the part of commissioning where things move. Per motor a JogPanel (hold to
// move, stop, jog speed, single move, home); the homing order and the sequence commands;
// the outputs; opt-in keyboard jogging. Any jog stops when the page is left or hidden, the
// window loses focus, or the link goes (the JogController's rules). The jog speed and the homing
// order are written through the window's WriteFlow.
class MotionPage : public Page
{
    Q_OBJECT
public:
    MotionPage(DeviceSession *session, WriteFlow *writes, QWidget *parent = nullptr);
    ~MotionPage() override;

    QString title() const override;
    // The game pad's box: the window gives it its E-STOP.
    GamepadPanel *gamepadPanel() const { return m_gamepad; }
    QString iconName() const override { return QStringLiteral("jog"); }
    Stage stage() const override { return Stage::SetUp; }
    bool needsDevice() const override { return true; }
    QStringList keys() const override;

    JogPanel *panel(int motor) const { return m_panels.value(motor - 1); }
    int motorCount() const { return int(m_panels.size()); }
    HomingOrderEditor *homingOrder() const { return m_order; }
    TravelLimitsEditor *travelLimits() const { return m_limits; }
    QPushButton *applyOrderButton() const { return m_applyOrder; }
    QPushButton *homeAllButton() const { return m_homeAll; }
    QPushButton *zeroButton() const { return m_zero; }
    QPushButton *returnToZeroButton() const { return m_returnToZero; }
    QPushButton *outputButton(const QString &commandKey) const;
    Led *outputLed(int n) const { return m_outputLeds.value(n - 1); }
    QCheckBox *keyboardCheck() const { return m_keyboard; }
    QLabel *keyboardIndicator() const { return m_keyboardIndicator; }
    QString homingStatus() const;
    // The prominent note at the top: warnings from the jog controller and refused choices.
    bool bannerShown() const;
    QString bannerText() const;

protected:
    void retranslate() override;
    void hideEvent(QHideEvent *event) override;
    bool event(QEvent *event) override;

private:
    void buildHoming(QWidget *content);
    void buildOutputs(QWidget *content);
    void showBanner(const QString &text);
    // A banner made from state each time it is shown, so a language switch retranslates it.
    void showBannerOf(std::function<QString()> text);
    void setKeyboard(bool on);
    void sessionCommand(const QString &key);
    void refresh();

    JogController *m_jog;
    WriteFlow *m_writes;
    JogKeys *m_keys;
    QList<JogPanel *> m_panels;
    TravelLimitsEditor *m_limits = nullptr;
    GamepadPanel *m_gamepad = nullptr;
    AboutBox *m_about = nullptr; // Explanations on demand
    QFrame *m_banner;
    QLabel *m_bannerIcon;
    QLabel *m_bannerText;
    std::function<QString()> m_bannerSource; // set: the banner's text is made from state
    QPushButton *m_bannerClear;
    QCheckBox *m_keyboard;
    QLabel *m_keyboardIndicator;
    QLabel *m_keyboardHelp;
    QGroupBox *m_homingBox = nullptr;
    HomingOrderEditor *m_order = nullptr;
    QPushButton *m_applyOrder = nullptr;
    QLabel *m_orderNote = nullptr;
    QPushButton *m_homeAll = nullptr;
    QPushButton *m_zero = nullptr;
    QPushButton *m_returnToZero = nullptr;
    QLabel *m_homingStatus = nullptr;
    // What the homing box reports while idle: the last sequence's outcome, or the zeroing.
    enum class Shown { Nothing, HomeInOrder, ReturnToZero, Zeroed };
    Shown m_shown = Shown::Nothing;
    QGroupBox *m_outputsBox = nullptr;
    QHash<QString, QPushButton *> m_outputButtons;
    QList<Led *> m_outputLeds;
    QList<QLabel *> m_outputNames;
};

} // namespace stepcom
