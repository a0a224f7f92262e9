#pragma once

#include "proof/marginfinder.h"

#include <QChartView>

class QLineSeries;
class QScatterSeries;
class QValueAxis;

namespace stepcom {

// What a margin search found: the loss (mm, signed) at each speed or acceleration tested, the
// ones that kept their steps green, the first that lost them red, and the recommendation as a
// dashed line. It grows step by step while the search runs.
class MarginPlot : public QChartView
{
    Q_OBJECT
public:
    explicit MarginPlot(QWidget *parent = nullptr);

    // A new search of the speed (rpm) or the acceleration register.
    void clear(bool accel);
    void addStep(const MarginStep &step);
    // The search ended: the recommended value drawn (none: nothing kept).
    void setRecommended(std::optional<qint64> value);
    int pointCount() const;
    QScatterSeries *keptSeries() const { return m_kept; }
    QScatterSeries *lostSeries() const { return m_lost; }

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void fitAxes();

    bool m_accel = false;
    QLineSeries *m_line;
    QScatterSeries *m_kept;
    QScatterSeries *m_lost;
    QLineSeries *m_recommended;
    QValueAxis *m_axisX;
    QValueAxis *m_axisY;
};

} // namespace stepcom
