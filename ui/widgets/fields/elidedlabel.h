#pragma once

#include <QLabel>

namespace stepcom {

// A one-line label that gives way when its row is short: it asks for its whole text's width
// but can be squeezed to a few characters, then shows the text cut with "…" and the whole of
// it in its tooltip. For the status bar, where a text must not run into its neighbours.
class ElidedLabel : public QLabel
{
    Q_OBJECT
public:
    explicit ElidedLabel(QWidget *parent = nullptr);

    // The text to show (line breaks become spaces); use this, not QLabel::setText.
    void setFullText(const QString &text);
    QString fullText() const { return m_full; }
    bool isElided() const { return !m_full.isEmpty() && text() != m_full; }
    // The least it may be squeezed to, in average characters (the whole text when shorter).
    void setMinimumChars(int chars);
    // Shown whole in the tooltip when not elided; the cut text's tooltip is the text itself.
    void setFullToolTip(const QString &tip);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void resizeEvent(QResizeEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    void elide();

    QString m_full;
    QString m_tip;
    int m_minimumChars = 4;
};

} // namespace stepcom
