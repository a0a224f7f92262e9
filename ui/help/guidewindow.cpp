#include "help/guidewindow.h"

#include "base/fittoscreen.h"
#include "help/userguide.h"

#include <QAbstractTextDocumentLayout>
#include <QComboBox>
#include <QDesktopServices>
#include <QEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QImage>
#include <QLabel>
#include <QPixmap>
#include <QScrollBar>
#include <QStyle>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

namespace stepcom {

GuideWindow::GuideWindow(QWidget *parent)
    : QWidget(parent, Qt::Window)
    , m_browser(new QTextBrowser(this))
    , m_contents(new QComboBox(this))
    , m_back(new QToolButton(this))
    , m_note(new QLabel(this))
{
    setObjectName(QStringLiteral("guideWindow"));
    m_browser->setObjectName(QStringLiteral("guideBrowser"));
    m_contents->setObjectName(QStringLiteral("guideContents"));
    // Links are ours to follow: GitHub-style anchors, the web in the desktop's browser.
    m_browser->setOpenLinks(false);
    m_browser->setOpenExternalLinks(false);
    m_contents->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_contents->setMinimumContentsLength(20);
    m_note->setWordWrap(true);
    m_note->hide();
    m_back->setEnabled(false);
    auto *bar = new QHBoxLayout;
    bar->addWidget(m_back);
    bar->addWidget(m_contents, 1);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(bar);
    layout->addWidget(m_note);
    layout->addWidget(m_browser, 1);
    connect(m_browser, &QTextBrowser::anchorClicked, this, &GuideWindow::followLink);
    connect(m_browser, &QTextBrowser::backwardAvailable, m_back, &QToolButton::setEnabled);
    connect(m_back, &QToolButton::clicked, m_browser, &QTextBrowser::backward);
    connect(m_contents, &QComboBox::activated, this, [this](int index) {
        const QTextBlock block =
            m_browser->document()->findBlockByNumber(m_contents->itemData(index).toInt());
        if (block.isValid())
            scrollTo(block);
    });
    // The pictures follow the view's width (fitImages).
    m_browser->viewport()->installEventFilter(this);
    // A hundred characters by forty lines, but never larger than the screen (1366×768 at
    // 150 % leaves 910×512), with room for the window's frame.
    const QFontMetrics fm = fontMetrics();
    resize(
        fitToScreen(this, QSize(fm.horizontalAdvance(QLatin1Char('x')) * 100, fm.height() * 40)));
    retranslate();
}

bool GuideWindow::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_browser->viewport() && event->type() == QEvent::Resize)
        fitImages();
    return QWidget::eventFilter(watched, event);
}

void GuideWindow::fitImages()
{
    QTextDocument *doc = m_browser->document();
    // Room as if the vertical scroll bar were shown: the long guide has one, and the pictures'
    // widths must not make it come and go.
    const int bar = m_browser->verticalScrollBar()->isVisible()
                        ? 0
                        : m_browser->style()->pixelMetric(QStyle::PM_ScrollBarExtent);
    const int room = int(m_browser->viewport()->width() - bar - 2 * doc->documentMargin());
    if (room <= 0)
        return;
    for (QTextBlock b = doc->begin(); b.isValid(); b = b.next()) {
        for (auto it = b.begin(); !it.atEnd(); ++it) {
            const QTextFragment fragment = it.fragment();
            if (!fragment.charFormat().isImageFormat())
                continue;
            QTextImageFormat format = fragment.charFormat().toImageFormat();
            const QVariant resource =
                doc->resource(QTextDocument::ImageResource, QUrl(format.name()));
            QImage picture = resource.value<QImage>();
            if (picture.isNull() && !resource.value<QPixmap>().isNull())
                picture = resource.value<QPixmap>().toImage();
            if (picture.isNull())
                picture.loadFromData(resource.toByteArray());
            if (picture.isNull())
                continue;
            // Never wider than the view and never enlarged; the height follows (aspect kept).
            const int natural = int(picture.width() / picture.devicePixelRatio());
            const int width = std::min(natural, room);
            if (format.hasProperty(QTextFormat::ImageWidth) && std::abs(format.width() - width) < 1)
                continue;
            format.setWidth(width);
            format.clearProperty(QTextFormat::ImageHeight);
            QTextCursor cursor(doc);
            cursor.setPosition(fragment.position());
            cursor.setPosition(fragment.position() + fragment.length(), QTextCursor::KeepAnchor);
            cursor.setCharFormat(format);
        }
    }
}

bool GuideWindow::load(const QString &language, QString *error)
{
    if (language == m_language && !m_file.isEmpty())
        return true;
    const QString path = UserGuide::file(language);
    if (path.isEmpty()) {
        const QString why =
            tr("The user guide (%1) was not found in %2. It is installed with StepCom; "
               "reinstalling the package brings it back.")
                .arg(UserGuide::fileName(language),
                     UserGuide::searchDirectories().join(QLatin1String(", ")));
        m_browser->setPlainText(why);
        if (error)
            *error = why;
        m_file.clear();
        return false;
    }
    // Relative pictures (images/en/...) are found beside the guide.
    m_browser->setSearchPaths({QFileInfo(path).absolutePath()});
    m_browser->setSource(QUrl::fromLocalFile(path), QTextDocument::MarkdownResource);
    m_browser->clearHistory();
    // Fitting the pictures edits formats: nothing to undo in a guide.
    m_browser->document()->setUndoRedoEnabled(false);
    fitImages();
    m_file = path;
    m_language = language;
    fillContents();
    return true;
}

bool GuideWindow::showTopic(const QString &topic, const QString &language, QString *error)
{
    m_note->hide();
    if (!load(language, error)) {
        m_note->setText(m_browser->toPlainText());
        m_note->show();
        return false;
    }
    const QString heading = UserGuide::heading(topic, language);
    const QTextBlock block = UserGuide::findHeading(*m_browser->document(), heading);
    if (!block.isValid()) {
        const QString why = tr("The guide has no section \"%1\".").arg(heading);
        m_note->setText(why);
        m_note->show();
        if (error)
            *error = why;
        return false;
    }
    scrollTo(block);
    // Layout finishes once the window is shown: stand at the heading then too.
    const int number = block.blockNumber();
    QTimer::singleShot(0, this, [this, number] {
        const QTextBlock again = m_browser->document()->findBlockByNumber(number);
        if (again.isValid())
            scrollTo(again);
    });
    return true;
}

QString GuideWindow::currentHeading() const
{
    QTextBlock b = m_browser->textCursor().block();
    while (b.isValid() && b.blockFormat().headingLevel() == 0)
        b = b.previous();
    return b.isValid() ? b.text().trimmed() : QString();
}

void GuideWindow::scrollTo(const QTextBlock &block)
{
    m_browser->setTextCursor(QTextCursor(block));
    const QRectF rect = m_browser->document()->documentLayout()->blockBoundingRect(block);
    m_browser->verticalScrollBar()->setValue(int(rect.top()));
    for (int i = 0; i < m_contents->count(); ++i) {
        if (m_contents->itemData(i).toInt() == block.blockNumber())
            m_contents->setCurrentIndex(i);
    }
}

void GuideWindow::followLink(const QUrl &url)
{
    const bool here = url.isRelative() && url.path().isEmpty();
    if ((here || url.matches(m_browser->source(), QUrl::RemoveFragment)) && url.hasFragment()) {
        const QTextBlock block = UserGuide::findAnchor(*m_browser->document(), url.fragment());
        if (block.isValid())
            scrollTo(block);
        return;
    }
    const QUrl resolved = m_browser->source().resolved(url);
    if (resolved.isLocalFile() && !QFileInfo::exists(resolved.toLocalFile())) {
        m_note->setText(tr("%1 is not installed with the guide.").arg(resolved.fileName()));
        m_note->show();
        return;
    }
    if (resolved.isLocalFile() && resolved.fileName().endsWith(QLatin1String(".md"))) {
        m_browser->setSource(resolved, QTextDocument::MarkdownResource);
        fitImages();
        return;
    }
    QDesktopServices::openUrl(resolved); // the web and other files: the desktop's own programs
}

void GuideWindow::fillContents()
{
    m_contents->clear();
    for (QTextBlock b = m_browser->document()->begin(); b.isValid(); b = b.next()) {
        const int level = b.blockFormat().headingLevel();
        if (level >= 1 && level <= 3) {
            const QString indent(2 * (level - 1), QLatin1Char(' '));
            m_contents->addItem(indent + b.text().trimmed(), b.blockNumber());
        }
    }
}

void GuideWindow::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void GuideWindow::retranslate()
{
    setWindowTitle(tr("User guide"));
    m_back->setText(tr("Back"));
    m_back->setToolTip(tr("Back to where you were in the guide"));
    m_contents->setToolTip(tr("Go to a section of the guide"));
    m_contents->setAccessibleName(tr("Sections"));
}

} // namespace stepcom
