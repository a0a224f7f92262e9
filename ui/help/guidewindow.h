#pragma once

#include <QWidget>

class QComboBox;
class QLabel;
class QTextBlock;
class QTextBrowser;
class QToolButton;
class QUrl;

namespace stepcom {

// The user guide inside the program (F1): the Markdown guide in the window's language, its
// pictures beside it, opened at the section that explains what the user is looking at. It
// needs no browser and no network, so it works on a workshop laptop offline.
class GuideWindow : public QWidget
{
    Q_OBJECT
public:
    explicit GuideWindow(QWidget *parent = nullptr);

    // Loads the guide in `language` (once per language) and shows `topic`'s section
    // (UserGuide::heading). False, with the reason in the window and in `error`, when the guide
    // cannot be found or the section is missing.
    bool showTopic(const QString &topic, const QString &language, QString *error = nullptr);
    // The file shown and the heading the view stands at.
    QString file() const { return m_file; }
    QString currentHeading() const;
    QTextBrowser *browser() const { return m_browser; }

protected:
    void changeEvent(QEvent *event) override;

private:
    bool load(const QString &language, QString *error);
    void scrollTo(const QTextBlock &block);
    void followLink(const QUrl &url);
    void fillContents();
    void retranslate();

    QTextBrowser *m_browser;
    QComboBox *m_contents;
    QToolButton *m_back;
    QLabel *m_note;
    QString m_file;
    QString m_language;
};

} // namespace stepcom
