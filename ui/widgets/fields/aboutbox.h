#pragma once

#include <QWidget>

class QLabel;
class QToolButton;

namespace stepcom {

// "About this page" (help on demand): a page's explanation behind a button that
// starts closed, so the page shows values and actions first. The text is the page's (set in
// its retranslate()); it is also the box's What's This, and the guide (F1) says more.
class AboutBox : public QWidget
{
    Q_OBJECT
public:
    explicit AboutBox(QWidget *parent = nullptr);

    void setText(const QString &text);
    QString text() const;
    bool isOpen() const;
    void setOpen(bool open);
    QToolButton *button() const { return m_button; }
    // "More in the user guide (F1)", shown with the text: the window's F1 (its "userGuide"
    // action), so the guide opens at this page.
    QToolButton *guideButton() const { return m_guide; }

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    QToolButton *m_button;
    QLabel *m_text;
    QToolButton *m_guide;
};

} // namespace stepcom
