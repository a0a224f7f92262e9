#pragma once

#include "base/page.h"

#include <QTimer>

class QSplitter;
class QTabWidget;

namespace stepcom {

class AboutBox;
class InterpolationPreview;
class PathEditor;

// Arc and line interpolation: the two editors in tabs and one XY preview of the one in front,
// following the typing, with the approach from where the axes are and the live run over it.
class InterpolationPage : public Page
{
    Q_OBJECT
public:
    explicit InterpolationPage(DeviceSession *session, QWidget *parent = nullptr);

    QString title() const override;
    QString iconName() const override { return QStringLiteral("interpolation"); }
    Stage stage() const override { return Stage::MoveAndRun; }
    QStringList keys() const override;

    PathEditor *arcEditor() const { return m_arc; }
    PathEditor *lineEditor() const { return m_line; }
    InterpolationPreview *preview() const { return m_preview; }
    QTabWidget *tabs() const { return m_tabs; }
    // The editor the preview shows.
    PathEditor *currentEditor() const;
    // Draw what is pending now instead of on the next turn of the event loop.
    void updatePreview();

protected:
    void retranslate() override;

private:
    void schedulePreview();
    void positionChanged();

    QTabWidget *m_tabs;
    PathEditor *m_arc;
    PathEditor *m_line;
    InterpolationPreview *m_preview;
    AboutBox *m_about; // How the times are estimated, on demand
    QSplitter *m_splitter;
    QTimer m_previewTimer;
    QTimer m_positionTimer;
};

} // namespace stepcom
