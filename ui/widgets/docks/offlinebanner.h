#pragma once

#include <QFrame>

class QLabel;

namespace stepcom {

class ProfileDocument;

// Above the pages while a profile file is edited without a controller: which file, that
// nothing here reaches a controller, unsaved edits, and what of a variant profile this map
// cannot take or the file lacks. Hidden otherwise.
class OfflineBanner : public QFrame
{
    Q_OBJECT
public:
    explicit OfflineBanner(ProfileDocument *document, QWidget *parent = nullptr);

    QString text() const;
    QString varianceText() const;

protected:
    void changeEvent(QEvent *event) override;

private:
    void refresh();

    ProfileDocument *m_document;
    QLabel *m_title;
    QLabel *m_variance;
};

} // namespace stepcom
