#pragma once

#include <QWidget>

class QBoxLayout;
class QHBoxLayout;

namespace stepcom {

// Two groups of controls: side by side when there is room, the second under the first when
// not. What it asks for at least is the wider group, not both (the plots' buttons in
// one row left the window 3 px to spare at 1366×768 ×1.5 in English; the traffic's filters and
// actions in two rows took a line from the page at 1024×600). Side by side until it is seen
// narrower: hidden, or behind a tab, it asks for one row's height.
class WrappingRow : public QWidget
{
    Q_OBJECT
public:
    explicit WrappingRow(QWidget *parent = nullptr);

    QHBoxLayout *first() const { return m_first; }
    QHBoxLayout *second() const { return m_second; }
    bool isWrapped() const;

    QSize minimumSizeHint() const override;

protected:
    void resizeEvent(QResizeEvent *event) override;
    void showEvent(QShowEvent *event) override;
    bool event(QEvent *event) override;
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void arrange();

    QBoxLayout *m_rows;
    QHBoxLayout *m_first;
    QHBoxLayout *m_second;
    bool m_watchesDock = false;
};

} // namespace stepcom
