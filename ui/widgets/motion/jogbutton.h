#pragma once

#include <QPushButton>

namespace stepcom {

// A hold-to-move button. jogPressed() when the left mouse button goes down on it; jogReleased()
// exactly once when the hand lets go: released anywhere, dragged off the button, the button
// hidden or disabled, the window deactivated, the mouse grab lost. Dragging back onto it does
// not restart the motion: press again. It takes no keyboard focus and ignores mnemonics and
// Space, so no key can start a motion through it (keyboard jogging is the page's, opt-in).
class JogButton : public QPushButton
{
    Q_OBJECT
public:
    explicit JogButton(QWidget *parent = nullptr);

    bool isHeld() const { return m_held; }
    // End the hold now (emits jogReleased() when it was held).
    void letGo();

Q_SIGNALS:
    void jogPressed();
    void jogReleased();

protected:
    bool event(QEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void keyReleaseEvent(QKeyEvent *event) override;
    void hideEvent(QHideEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    bool m_held = false;
};

} // namespace stepcom
