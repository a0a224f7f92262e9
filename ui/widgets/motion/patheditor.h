#pragma once

#include "motion/interpolationgeometry.h"
#include "motion/interpolationtiming.h"

#include "base/writechangesdialog.h"
#include "base/writeflow.h"

#include <QPointer>
#include <QTimer>
#include <QWidget>

#include <optional>

class QFormLayout;
class QGroupBox;
class QLabel;
class QPushButton;

namespace stepcom {

class DeviceSession;
class ParameterForm;

// The editor of the arc (40182-40201, coils 00100/00101) or the line (40202-40211, coils
// 00102/00103): the parameters as fields of the store (edit, then write through the write
// dialog with read-back, like every page), what the geometry works out to as the user types,
// and Start/Stop. Start only runs what the controller holds and the preview shows: it is off,
// with the reason beside it, while an edit is unwritten, the geometry is invalid, the values are
// unknown, interpolation is switched off, a motor moves, or the link is down. Stop is on
// whenever the link is up.
class PathEditor : public QWidget
{
    Q_OBJECT
public:
    enum class Kind { Arc, Line };

    PathEditor(DeviceSession *session, Kind kind, QWidget *parent = nullptr);

    Kind kind() const { return m_kind; }
    QStringList keys() const { return m_keys; }
    ParameterForm *form() const { return m_form; }
    QPushButton *startButton() const { return m_start; }
    QPushButton *stopButton() const { return m_stop; }
    QPushButton *writeButton() const { return m_write; }
    // Write, Start, Stop and what they say: the page may keep it in view below the scrolled
    // form (a low screen must not hide Start).
    QGroupBox *runBox() const { return m_runBox; }
    QLabel *startReason() const { return m_reason; }
    // How the last run of this path ended (judged from the controller), or that it runs.
    QLabel *outcomeLabel() const { return m_outcome; }
    WriteChangesDialog *writeDialog() const { return m_writeFlow->dialog(); }

    // The geometry of what the fields show now, typing included.
    interpolation::Geometry geometry() const;
    // Why Start is off; empty when it may run.
    QString startBlockedReason() const;
    // The approach from the current position (nullopt while it is unknown or a motor moves).
    std::optional<interpolation::Approach> approach(const interpolation::Geometry &g) const;
    // The live position of motors 1 and 2, when both are known.
    std::optional<QPointF> position() const;
    bool anyMotorRunning() const;
    // How the times are estimated, for the page's "About this page" and the tooltip.
    static QString assumptions();
    void retranslate();

Q_SIGNALS:
    // What the preview shows may have changed (typing, edits, device values).
    void changed();
    // The start command was sent.
    void started();

private:
    std::optional<double> typed(const char *local) const;
    interpolation::Point typedPoint(const char *name) const;
    QString key(const char *local) const;
    MotorParameters motor(int n) const;
    void update();
    void openWriteDialog();

    DeviceSession *m_session;
    Kind m_kind;
    QString m_prefix;
    QStringList m_keys;
    QGroupBox *m_parameterBox;
    QGroupBox *m_resultBox;
    QGroupBox *m_runBox;
    ParameterForm *m_form;
    QFormLayout *m_results;
    QLabel *m_radius = nullptr;
    QLabel *m_centre = nullptr;
    QLabel *m_radii = nullptr;
    QLabel *m_sweep = nullptr;
    QLabel *m_length;
    QLabel *m_speed;
    QLabel *m_time;
    QLabel *m_assumes;
    QLabel *m_problem;
    QList<QPair<QLabel *, const char *>> m_rowLabels;
    QPushButton *m_write;
    QPushButton *m_start;
    QPushButton *m_stop;
    QLabel *m_reason;
    QLabel *m_outcome;
    WriteFlow *m_writeFlow = nullptr;
    QTimer m_startSent; // a start was sent and the poll has not seen it yet
};

} // namespace stepcom
