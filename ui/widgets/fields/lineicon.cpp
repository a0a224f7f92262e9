#include "widgets/fields/lineicon.h"

#include "widgets/fields/statetone.h"

#include <QFile>
#include <QIconEngine>
#include <QPainter>
#include <QPalette>
#include <QSvgRenderer>

#include <array>

namespace stepcom {

namespace {

// Renders the SVG with currentColor replaced by the colour of the icon's mode. QSvgRenderer
// (Qt 6.4) does not resolve currentColor by itself.
class LineIconEngine : public QIconEngine
{
public:
    LineIconEngine(QByteArray svg, std::array<QColor, 3> colours)
        : m_svg(std::move(svg))
        , m_colours(colours)
    {}

    void paint(QPainter *painter, const QRect &rect, QIcon::Mode mode, QIcon::State) override
    {
        const QColor colour = mode == QIcon::Disabled   ? m_colours[1]
                              : mode == QIcon::Selected ? m_colours[2]
                                                        : m_colours[0];
        QByteArray svg = m_svg;
        svg.replace("currentColor", colour.name().toLatin1());
        QSvgRenderer renderer(svg);
        renderer.render(painter, QRectF(rect));
    }

    // `size` in device pixels: QIcon::pixmap(size, ratio) asks for size × ratio.
    QPixmap pixmap(const QSize &size, QIcon::Mode mode, QIcon::State state) override
    {
        QPixmap pixmap(size);
        pixmap.fill(Qt::transparent);
        QPainter painter(&pixmap);
        painter.setRenderHint(QPainter::Antialiasing);
        paint(&painter, QRect(QPoint(0, 0), size), mode, state);
        return pixmap;
    }

    QPixmap scaledPixmap(const QSize &size, QIcon::Mode mode, QIcon::State state,
                         qreal scale) override
    {
        QPixmap p = pixmap(size, mode, state);
        p.setDevicePixelRatio(scale);
        return p;
    }

    QIconEngine *clone() const override { return new LineIconEngine(m_svg, m_colours); }
    QString key() const override { return QStringLiteral("stepcom-line"); }

private:
    QByteArray m_svg;
    std::array<QColor, 3> m_colours; // normal, disabled, selected
};

} // namespace

QIcon lineIcon(const QString &resource, const QPalette &palette)
{
    QFile file(resource);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QByteArray svg = file.readAll();
    if (!QSvgRenderer(svg).isValid())
        return {};
    return QIcon(new LineIconEngine(std::move(svg),
                                    {palette.color(QPalette::Active, QPalette::Text),
                                     stateColour(StateTone::Unknown, palette, QPalette::Base),
                                     palette.color(QPalette::Active, QPalette::HighlightedText)}));
}

} // namespace stepcom
