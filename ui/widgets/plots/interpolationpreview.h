#pragma once

#include "motion/interpolationgeometry.h"
#include "motion/interpolationtiming.h"

#include <QFileDialog>
#include <QPointer>
#include <QWidget>

#include <optional>

class QLabel;
class QPushButton;

namespace stepcom {

class XYPlot;

// The XY preview of an arc or a line, before and while it runs: the path with its start, end,
// centre or middle markers and arrowheads for the direction, the approach move the controller
// makes first (dashed), invalid geometry in red dashes with the reason, and the live position
// with the trace of the real run. Fit, zoom, pan (the plot's own navigation) and PNG export.
class InterpolationPreview : public QWidget
{
    Q_OBJECT
public:
    explicit InterpolationPreview(QWidget *parent = nullptr);

    XYPlot *plot() const { return m_plot; }
    // Draws `geometry` (valid or not) and, when given, the approach to its start.
    void setGeometry(const interpolation::Geometry &geometry,
                     const std::optional<interpolation::Approach> &approach);
    // The live position (distance units): the marker, and the trace while recording.
    void setPosition(const QPointF &position);
    void clearPosition();
    // Starts a new trace (a run was started).
    void restartTrace();
    void setAxisTitles(const QString &x, const QString &y);
    QString message() const;
    bool exportPng(const QString &path, QString *error);
    QFileDialog *fileDialog() const { return m_dialog; }

protected:
    void changeEvent(QEvent *event) override;

private:
    void redraw();
    void retranslate();
    void askForFile();

    XYPlot *m_plot;
    QLabel *m_message;
    QLabel *m_key;
    QLabel *m_status;
    QPushButton *m_fit;
    QPushButton *m_export;
    QPointer<QFileDialog> m_dialog;
    interpolation::Geometry m_geometry;
    std::optional<interpolation::Approach> m_approach;
    bool m_drawn = false;
};

} // namespace stepcom
