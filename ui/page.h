#pragma once

#include <QIcon>
#include <QWidget>

namespace stepcom {

class DeviceSession;

// One page of the window (Connection, Motor 1, ...): a view of the session's parameter store.
// Pages build their widgets in the constructor and set every visible text in retranslate(),
// which runs once at the start and again whenever the language changes.
class Page : public QWidget
{
    Q_OBJECT
public:
    explicit Page(DeviceSession *session, QWidget *parent = nullptr);

    virtual QString title() const = 0;
    virtual QIcon icon() const { return {}; }
    // Keys of the parameters the page shows (for "write this page" and tests).
    virtual QStringList keys() const { return {}; }

protected:
    virtual void retranslate() = 0;
    void changeEvent(QEvent *event) override;
    DeviceSession *session() const { return m_session; }
    // The page's content widget inside a frameless scroll area filling the page: every field
    // stays reachable at 200% scale on a small screen. Call once, from the constructor.
    QWidget *scrollableContent();

private:
    DeviceSession *m_session;
};

} // namespace stepcom
