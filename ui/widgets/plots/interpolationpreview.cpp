#include "widgets/plots/interpolationpreview.h"

#include "widgets/plots/xyplot.h"

#include <QDateTime>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScatterSeries>
#include <QStandardPaths>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace stepcom {

using interpolation::Geometry;
using interpolation::Point;

namespace {

const QString kPath = QStringLiteral("path");
const QString kInvalid = QStringLiteral("invalid");
const QString kApproach = QStringLiteral("approach");
const QString kStart = QStringLiteral("start");
const QString kEnd = QStringLiteral("end");
const QString kCentre = QStringLiteral("centre");
const QString kMiddle = QStringLiteral("middle");
const QString kArrow = QStringLiteral("arrow%1");
constexpr int kArrows = 3;

QPointF toQ(Point p)
{
    return {p.x, p.y};
}

QList<QPointF> circle(Point c, double r)
{
    QList<QPointF> points;
    for (int i = 0; i <= 128; ++i) {
        const double a = 2 * std::numbers::pi * i / 128;
        points << QPointF(c.x + r * std::cos(a), c.y + r * std::sin(a));
    }
    return points;
}

QList<QPointF> sampled(const InterpolationPath &path)
{
    QList<QPointF> points;
    const int n =
        path.isArc() ? std::max(32, int(std::abs(path.sweep()) * 180 / std::numbers::pi)) : 1;
    for (int i = 0; i <= n; ++i)
        points << toQ(path.pointAt(path.length() * i / n));
    return points;
}

// An arrowhead (wing, tip, wing) at arc length s, pointing along the path.
QList<QPointF> arrowhead(const InterpolationPath &path, double s, double size)
{
    const double ds = std::max(path.length() * 1e-3, 1e-6);
    const Point a = path.pointAt(std::max(0.0, s - ds));
    const Point b = path.pointAt(std::min(path.length(), s + ds));
    const double angle = std::atan2(b.y - a.y, b.x - a.x);
    const Point tip = path.pointAt(s);
    auto wing = [&](double side) {
        const double w = angle + std::numbers::pi + side * std::numbers::pi / 7;
        return QPointF(tip.x + size * std::cos(w), tip.y + size * std::sin(w));
    };
    return {wing(1), toQ(tip), wing(-1)};
}

} // namespace

InterpolationPreview::InterpolationPreview(QWidget *parent)
    : QWidget(parent)
    , m_plot(new XYPlot(this))
    , m_message(new QLabel(this))
    , m_key(new QLabel(this))
    , m_status(new QLabel(this))
    , m_fit(new QPushButton(this))
    , m_export(new QPushButton(this))
{
    setObjectName(QStringLiteral("interpolationPreview"));
    m_message->setObjectName(QStringLiteral("previewMessage"));
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_status->setObjectName(QStringLiteral("previewStatus"));
    m_status->setWordWrap(true);
    m_fit->setObjectName(QStringLiteral("previewFit"));
    m_export->setObjectName(QStringLiteral("previewExport"));
    m_plot->setMinimumSize(fontMetrics().height() * 18, fontMetrics().height() * 16);
    m_plot->setTraceLimit(50000);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_message);
    layout->addWidget(m_plot, 1);
    m_key->setWordWrap(true);
    m_key->setTextFormat(Qt::RichText);
    layout->addWidget(m_key);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_status, 1);
    buttons->addWidget(m_fit);
    buttons->addWidget(m_export);
    layout->addLayout(buttons);

    connect(m_fit, &QPushButton::clicked, m_plot, &XYPlot::fit);
    connect(m_export, &QPushButton::clicked, this, &InterpolationPreview::askForFile);
    retranslate();
}

void InterpolationPreview::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    else if (event->type() == QEvent::PaletteChange)
        redraw();
    QWidget::changeEvent(event);
}

void InterpolationPreview::retranslate()
{
    m_fit->setText(tr("&Fit"));
    m_fit->setToolTip(tr("Show the whole path again (or double-click the plot)"));
    m_export->setText(tr("Export P&NG…"));
    m_export->setToolTip(tr("Save the preview as it is shown as a PNG picture"));
    m_plot->setTraceName(tr("Real run"));
    m_plot->setToolTip(tr("Drag to zoom into a region, wheel or +/- to zoom, middle button or "
                          "arrow keys to pan, double-click to fit."));
    redraw();
}

QString InterpolationPreview::message() const
{
    return m_message->text();
}

void InterpolationPreview::setAxisTitles(const QString &x, const QString &y)
{
    m_plot->setAxisTitles(x, y);
}

void InterpolationPreview::setGeometry(const Geometry &geometry,
                                       const std::optional<interpolation::Approach> &approach)
{
    // The page asks on every poll; the chart is rebuilt only when the drawing changes.
    auto same = [](const Point &a, const Point &b) { return a.x == b.x && a.y == b.y; };
    auto sameOpt = [&same](const std::optional<Point> &a, const std::optional<Point> &b) {
        return a.has_value() == b.has_value() && (!a || same(*a, *b));
    };
    auto sameApproach = [&same](const std::optional<interpolation::Approach> &a,
                                const std::optional<interpolation::Approach> &b) {
        if (a.has_value() != b.has_value())
            return false;
        if (!a)
            return true;
        return a->exact == b->exact && a->points.size() == b->points.size() &&
               std::equal(a->points.cbegin(), a->points.cend(), b->points.cbegin(), same);
    };
    const Geometry &g = m_geometry;
    if (m_drawn && g.valid == geometry.valid && g.arc == geometry.arc &&
        g.error == geometry.error && g.notes == geometry.notes && same(g.start, geometry.start) &&
        same(g.end, geometry.end) && sameOpt(g.centre, geometry.centre) &&
        sameOpt(g.middle, geometry.middle) && g.sweepDegrees == geometry.sweepDegrees &&
        g.startRadius == geometry.startRadius && sameApproach(m_approach, approach))
        return;
    m_geometry = geometry;
    m_approach = approach;
    m_drawn = true;
    redraw();
}

void InterpolationPreview::setPosition(const QPointF &position)
{
    m_plot->appendTrace(position);
    m_plot->setMarker(position);
}

void InterpolationPreview::clearPosition()
{
    m_plot->clearMarker();
}

void InterpolationPreview::restartTrace()
{
    m_plot->clearTrace();
}

void InterpolationPreview::redraw()
{
    const Geometry &g = m_geometry;
    const QPalette pal = palette();
    // The selection colour, lightened on a dark background so the path stands out.
    const bool dark = pal.color(QPalette::Base).lightness() < 128;
    const QColor pathColour =
        dark ? pal.color(QPalette::Highlight).lighter(170) : pal.color(QPalette::Highlight);
    const QColor bad(220, 40, 40);
    QColor approachColour = pal.color(QPalette::Text);
    approachColour.setAlphaF(0.6);

    m_plot->clearPaths();
    m_plot->chart()->legend()->setVisible(false); // the key below says it in full
    // The real run in its own colour, apart from the planned path.
    QPen tracePen = m_plot->traceSeries()->pen();
    tracePen.setColor(QColor(230, 120, 0));
    m_plot->traceSeries()->setPen(tracePen);
    auto style = [this](const QString &id, const QColor &colour, Qt::PenStyle penStyle,
                        double width) {
        if (QXYSeries *s = m_plot->series(id)) {
            QPen pen(colour, width, penStyle);
            pen.setCapStyle(Qt::RoundCap);
            s->setPen(pen);
        }
    };
    auto marker = [this](const QString &id, Point p, const QString &name, const QColor &colour,
                         QScatterSeries::MarkerShape shape) {
        m_plot->setPoints(id, {toQ(p)}, name);
        if (auto *s = qobject_cast<QScatterSeries *>(m_plot->series(id))) {
            s->setMarkerShape(shape);
            s->setMarkerSize(fontMetrics().height() * 0.7);
            s->setColor(colour);
            s->setBorderColor(palette().color(QPalette::Text));
        }
    };

    if (m_approach && m_approach->points.size() > 1) {
        QList<QPointF> points;
        for (const Point &p : m_approach->points)
            points << toQ(p);
        m_plot->setPath(kApproach, points, tr("Approach"));
        style(kApproach, approachColour, Qt::DashLine, 1.5);
    }
    if (g.valid && g.path) {
        m_plot->setPath(kPath, sampled(*g.path), g.arc ? tr("Arc") : tr("Line"));
        style(kPath, pathColour, Qt::SolidLine, 2.5);
        // Arrowheads a small part of the drawing, whatever its scale.
        const double extent = g.arc ? std::min(2 * g.radius(), g.length) : g.length;
        const double size = std::max(0.01, extent * 0.05);
        for (int i = 0; i < kArrows; ++i) {
            const QString id = kArrow.arg(i);
            m_plot->setPath(id, arrowhead(*g.path, g.length * (i + 1) / (kArrows + 0.5), size));
            style(id, pathColour, Qt::SolidLine, 2.5);
        }
    } else if (g.arc || !g.error.isEmpty()) {
        // Invalid: what was given, in red dashes: the points joined in order, and the circle
        // through the start around the centre when there is one.
        QList<QPointF> given{toQ(g.start)};
        if (g.middle)
            given << toQ(*g.middle);
        else if (g.centre)
            given << toQ(*g.centre);
        given << toQ(g.end);
        m_plot->setPath(kInvalid, given, tr("Invalid"));
        style(kInvalid, bad, Qt::DashLine, 2);
        if (g.centre && g.startRadius > 0) {
            m_plot->setPath(kPath, circle(*g.centre, g.startRadius));
            style(kPath, bad, Qt::DotLine, 1.5);
        }
    }
    if (g.arc || g.valid || !g.error.isEmpty()) {
        marker(kStart, g.start, tr("Start"), QColor(40, 170, 60),
               QScatterSeries::MarkerShapeCircle);
        marker(kEnd, g.end, tr("End"), QColor(220, 60, 60), QScatterSeries::MarkerShapeRectangle);
        if (g.middle)
            marker(kMiddle, *g.middle, tr("Middle point"), QColor(230, 160, 0),
                   QScatterSeries::MarkerShapeTriangle);
        if (g.centre)
            marker(kCentre, *g.centre, g.middle ? tr("Centre (computed)") : tr("Centre"),
                   pal.color(QPalette::Text), QScatterSeries::MarkerShapeStar);
    }

    QPalette labelPalette = m_message->palette();
    if (!g.valid && !g.error.isEmpty()) {
        labelPalette.setColor(QPalette::WindowText, bad);
        m_message->setText(tr("Invalid: %1").arg(g.error));
    } else {
        labelPalette.setColor(QPalette::WindowText, pal.color(QPalette::WindowText));
        m_message->setText(g.notes.join(QLatin1Char(' ')));
    }
    m_message->setPalette(labelPalette);
    m_message->setVisible(!m_message->text().isEmpty());
    QString status;
    if (m_approach && m_approach->points.size() > 1)
        status = m_approach->exact
                     ? tr("Dashed: the approach from the current position; both axes start "
                          "together, each at its own speed, so the last one finishes alone.")
                     : tr("Dashed: the approach from the current position (the motors' "
                          "parameters are not known yet: drawn as equal speeds).");
    // The key to the drawing (the chart's legend would take the plot's room).
    auto swatch = [](const QColor &c, const QString &symbol, const QString &text) {
        return QStringLiteral("<span style=\"color:%1\">%2</span>&nbsp;%3")
            .arg(c.name(), symbol, text.toHtmlEscaped());
    };
    QStringList key{swatch(pathColour, QStringLiteral("━"), tr("path, arrowheads: direction")),
                    swatch(approachColour, QStringLiteral("┅"), tr("approach")),
                    swatch(QColor(230, 120, 0), QStringLiteral("━"), tr("real run")),
                    swatch(QColor(40, 170, 60), QStringLiteral("●"), tr("start")),
                    swatch(QColor(220, 60, 60), QStringLiteral("■"), tr("end"))};
    if (g.middle)
        key << swatch(QColor(230, 160, 0), QStringLiteral("▲"), tr("middle point"));
    if (g.centre)
        key << swatch(pal.color(QPalette::Text), QStringLiteral("★"), tr("centre"));
    m_key->setText(key.join(QStringLiteral(" &nbsp; ")));
    m_status->setText(status);
}

void InterpolationPreview::askForFile()
{
    if (m_dialog)
        m_dialog->close();
    auto *dialog = new QFileDialog(this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setAcceptMode(QFileDialog::AcceptSave);
    dialog->setFileMode(QFileDialog::AnyFile);
    dialog->setWindowTitle(tr("Export the preview as PNG"));
    dialog->setNameFilter(tr("PNG images (*.png)"));
    dialog->setDefaultSuffix(QStringLiteral("png"));
    dialog->setDirectory(QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation));
    dialog->selectFile(QStringLiteral("stepcom-path-") +
                       QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")) +
                       QStringLiteral(".png"));
    connect(dialog, &QFileDialog::fileSelected, this, [this](const QString &path) {
        QString error;
        m_status->setText(exportPng(path, &error)
                              ? tr("Saved “%1”.").arg(QDir::toNativeSeparators(path))
                              : error);
    });
    m_dialog = dialog;
    dialog->open();
}

bool InterpolationPreview::exportPng(const QString &path, QString *error)
{
    return m_plot->exportPng(path, error);
}

} // namespace stepcom
