#pragma once

#include "device/wiringcheck.h"

#include <QFrame>
#include <QList>

class QLabel;
class QVBoxLayout;

namespace stepcom {

// The wiring check's findings, one line each with its icon, in a box that stands out (palette
// roles only, so a dark palette works); a quiet "nothing suspicious" line when clean.
class WiringWarnings : public QFrame
{
    Q_OBJECT
public:
    explicit WiringWarnings(QWidget *parent = nullptr);

    // `known`: false while the wiring has not been read (nothing can be said yet).
    void setWarnings(const QList<WiringWarning> &warnings, bool known);
    const QList<WiringWarning> &warnings() const { return m_warnings; }
    // The texts shown, one per line (for tests and accessibility).
    QStringList texts() const;

protected:
    void changeEvent(QEvent *event) override;

private:
    void rebuild();

    QVBoxLayout *m_layout;
    QList<QWidget *> m_rows;
    QList<QLabel *> m_texts;
    QList<WiringWarning> m_warnings;
    bool m_known = false;
};

} // namespace stepcom
