#pragma once

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
    // The sidebar's picture of the page: resources/sidebar/<name>.svg.
    virtual QString iconName() const = 0;
    // Where the page sits in the commissioning order: the sidebar's groups.
    enum class Stage { Connect, SetUp, MoveAndRun, CheckAndReport };
    virtual Stage stage() const = 0;
    // The page's work needs a controller that answers (jog, plots, the device's own settings):
    // the sidebar marks it while none does.
    virtual bool needsDevice() const { return false; }
    // Steps passed of the steps there are, for a page that has steps (the checklist); total 0
    // for the others; known false when the page cannot tell (its file unreadable).
    struct Progress
    {
        int passed = 0;
        int total = 0;
        bool known = true;
    };
    virtual Progress progress() const { return {}; }
    // Keys of the parameters the page shows (for "write this page" and tests).
    virtual QStringList keys() const { return {}; }

Q_SIGNALS:
    // progress() changed.
    void progressChanged();

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
