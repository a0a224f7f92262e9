#pragma once

#include <QCoreApplication>
#include <QHash>
#include <QImage>

namespace stepcom {

class RegisterMap;

// The arc and line setup as an XY drawing (motor 1 = x, motor 2 = y), from raw register values;
// drawn with QPainter into an image so the report can embed it.
class XyPicture
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::XyPicture)
public:
    XyPicture(const RegisterMap &map, const QHash<QString, qint64> &values);
    QImage render(const QSize &size) const;
    // The distance between grid lines for a drawing `span` wide: 1, 2 or 5 times a power of ten,
    // about a sixth of it.
    static double gridStep(double span);
    // Why the arc cannot be drawn (start on the centre, three points on a line), or empty.
    QString arcProblem() const { return m_arcProblem; }

private:
    struct Shape
    {
        QList<QPointF> points;
        bool enabled = false;
    };
    Shape m_arc;
    Shape m_line;
    QString m_arcProblem;
    QString m_unit; // of the positions ("mm")
};

} // namespace stepcom
