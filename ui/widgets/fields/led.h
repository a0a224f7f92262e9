#pragma once

#include <QWidget>

namespace stepcom {

// A round indicator lamp. Lit: filled, in its colour made to stand out from the window (3:1,
// on a light and on a dark palette); off: a hollow ring; unknown: a hollow dotted ring in the
// "unknown" grey. On and off differ by more than the colour.
class Led : public QWidget
{
    Q_OBJECT
public:
    enum class State { Unknown, Off, On };
    explicit Led(QWidget *parent = nullptr);

    void setState(State state);
    State state() const { return m_state; }
    void setOnColor(const QColor &color);
    QColor onColor() const { return m_on; }
    // What a lit lamp is filled with on this palette: the on colour, darkened on a light
    // window and lightened on a dark one until it stands out from it.
    QColor litColor() const;
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override { return sizeHint(); }

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    State m_state = State::Unknown;
    QColor m_on = QColor(40, 200, 60);
};

} // namespace stepcom
