#pragma once

#include <QScrollArea>

namespace stepcom {

// A scroll area that scrolls up and down only: it asks for the width its content needs (and
// the vertical scroll bar beside it), so the layout around it makes room instead of a sideways
// scroll bar appearing on a narrow screen. The content is resized to fit.
class VerticalScrollArea : public QScrollArea
{
    Q_OBJECT
public:
    explicit VerticalScrollArea(QWidget *content, QWidget *parent = nullptr);

    QSize minimumSizeHint() const override;

protected:
    bool event(QEvent *event) override;
    bool eventFilter(QObject *watched, QEvent *event) override;
};

} // namespace stepcom
