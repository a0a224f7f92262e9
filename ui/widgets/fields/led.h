#pragma once

#include <QWidget>

namespace stepcom {

// A round indicator lamp: on, off or unknown (hollow), with a caption under or beside it.
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
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override { return sizeHint(); }

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    State m_state = State::Unknown;
    QColor m_on = QColor(40, 200, 60);
};

} // namespace stepcom
