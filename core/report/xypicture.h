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
};

} // namespace stepcom
