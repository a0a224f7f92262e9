#include "pages/interpolationpage.h"

#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "widgets/fields/aboutbox.h"
#include "widgets/fields/verticalscrollarea.h"
#include "widgets/motion/patheditor.h"
#include "widgets/plots/interpolationpreview.h"

#include <QGroupBox>
#include <QHBoxLayout>
#include <QSplitter>
#include <QTabWidget>
#include <QVBoxLayout>

namespace stepcom {

InterpolationPage::InterpolationPage(DeviceSession *session, QWidget *parent)
    : Page(session, parent)
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_about = new AboutBox(this);
    layout->addWidget(m_about);
    m_splitter = new QSplitter(this);
    layout->addWidget(m_splitter, 1);
    m_tabs = new QTabWidget(m_splitter);
    m_arc = new PathEditor(session, PathEditor::Kind::Arc);
    m_line = new PathEditor(session, PathEditor::Kind::Line);
    for (PathEditor *editor : {m_arc, m_line}) {
        // The form scrolls; Write, Start and Stop stay in view below it.
        auto *tab = new QWidget(m_tabs);
        auto *column = new QVBoxLayout(tab);
        column->setContentsMargins(0, 0, 0, 0);
        QGroupBox *run = editor->runBox();
        if (QLayout *form = editor->layout())
            form->removeWidget(run);
        // Up and down only: read values made it scroll sideways at 1024×600.
        column->addWidget(new VerticalScrollArea(editor, tab), 1);
        column->addWidget(run);
        m_tabs->addTab(tab, QString());
    }
    m_preview = new InterpolationPreview(m_splitter);
    m_splitter->addWidget(m_tabs);
    m_splitter->addWidget(m_preview);
    m_splitter->setStretchFactor(0, 2);
    m_splitter->setStretchFactor(1, 3);

    // A burst of changes (a read of every value, each keystroke) redraws once.
    m_previewTimer.setSingleShot(true);
    m_previewTimer.setInterval(0);
    connect(&m_previewTimer, &QTimer::timeout, this, &InterpolationPage::updatePreview);
    m_positionTimer.setSingleShot(true);
    m_positionTimer.setInterval(0);
    connect(&m_positionTimer, &QTimer::timeout, this, &InterpolationPage::positionChanged);
    for (PathEditor *e : {m_arc, m_line}) {
        connect(e, &PathEditor::changed, this, [this, e] {
            if (e == currentEditor())
                schedulePreview();
        });
        connect(e, &PathEditor::started, m_preview, &InterpolationPreview::restartTrace);
    }
    connect(m_tabs, &QTabWidget::currentChanged, this, &InterpolationPage::schedulePreview);
    connect(session->parameters()->store(), &ParameterStore::valueChanged, this,
            [this](const QString &k) {
                if (k.endsWith(QLatin1String(".position")) && !m_positionTimer.isActive())
                    m_positionTimer.start(); // x and y of one poll make one point of the trace
            });
    connect(session->connection(), &SessionConnection::disconnected, m_preview,
            &InterpolationPreview::clearPosition);
    retranslate();
    updatePreview();
}

QString InterpolationPage::title() const
{
    return tr("Interpolation");
}

QStringList InterpolationPage::keys() const
{
    return m_arc->keys() + m_line->keys();
}

PathEditor *InterpolationPage::currentEditor() const
{
    return m_tabs->currentIndex() == 1 ? m_line : m_arc;
}

void InterpolationPage::schedulePreview()
{
    if (!m_previewTimer.isActive())
        m_previewTimer.start();
}

void InterpolationPage::updatePreview()
{
    m_previewTimer.stop();
    const PathEditor *e = currentEditor();
    const interpolation::Geometry g = e->geometry();
    m_preview->setGeometry(g, g.valid ? e->approach(g) : std::nullopt);
}

void InterpolationPage::positionChanged()
{
    const std::optional<QPointF> p = m_arc->position();
    if (!p)
        return;
    m_preview->setPosition(*p);
}

void InterpolationPage::retranslate()
{
    m_tabs->setTabText(0, tr("Arc"));
    m_tabs->setTabText(1, tr("Line"));
    m_arc->retranslate();
    m_line->retranslate();
    m_about->setText(PathEditor::assumptions());
    const QString unit = [this] {
        const Parameter *p = session()->map().find(QStringLiteral("arc.start_x"));
        return p ? p->unit : QString();
    }();
    m_preview->setAxisTitles(tr("Motor 1 (X) [%1]").arg(unit), tr("Motor 2 (Y) [%1]").arg(unit));
}

} // namespace stepcom
