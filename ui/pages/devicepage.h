#pragma once

#include "base/page.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"

#include <QLabel>
#include <QPointer>

class QComboBox;
class QGroupBox;
class QMessageBox;
class QPushButton;
class QSpinBox;

namespace stepcom {

// The controller itself: its device id and baud (changed only behind a confirmation, with the
// old settings offered when it stops answering), save to flash, and factory reset.
class DevicePage : public Page
{
    Q_OBJECT
public:
    explicit DevicePage(DeviceSession *session, QWidget *parent = nullptr);
    ~DevicePage() override;

    QString title() const override;
    QString iconName() const override { return QStringLiteral("device"); }
    Stage stage() const override { return Stage::CheckAndReport; }
    bool needsDevice() const override { return true; }
    QStringList keys() const override;

    QSpinBox *idEditor() const { return m_id; }
    QComboBox *baudEditor() const { return m_baud; }
    QPushButton *applyLinkButton() const { return m_apply; }
    QPushButton *reconnectButton() const { return m_reconnect; }
    QPushButton *saveButton() const { return m_save; }
    QPushButton *factoryResetButton() const { return m_reset; }
    // The confirmation open now (link change or factory reset), else nullptr.
    QMessageBox *confirmation() const;
    QString linkStatus() const { return m_linkStatus->text(); }
    QString flashStatus() const { return m_flashStatus->text(); }
    bool unsavedWarningShown() const { return !m_unsavedRow->isHidden(); }

    // What the buttons do: ask (non-blocking), then act on "yes".
    void requestLinkChange();
    void requestFactoryReset();

protected:
    void retranslate() override;

private:
    enum class LinkEvent {
        None,
        Changing,
        Changed,
        Failed,
        Reconnecting,
        Reconnected,
        ReconnectFailed
    };
    enum class FlashEvent { None, Saving, Saved, SaveFailed, Resetting, ResetDone, ResetFailed };
    void showDeviceValues();
    void updateEnabled();
    void updateUnsaved();
    void setLinkEvent(LinkEvent event);
    void setFlashEvent(FlashEvent event);
    enum class Tone { Busy, Ok, Failed };
    std::pair<Tone, QString> linkText() const;
    std::pair<Tone, QString> flashText() const;
    void renderStatus();
    QString describe(int id, int baud) const;
    QMessageBox *makeConfirmation(const QString &title, const QString &text, const QString &details,
                                  const QString &yes);
    int chosenBaud() const;

    QGroupBox *m_linkBox;
    QGroupBox *m_flashBox;
    QGroupBox *m_factoryBox;
    QLabel *m_idLabel;
    QLabel *m_baudLabel;
    QSpinBox *m_id;
    QComboBox *m_baud;
    QLabel *m_idHeld;
    QLabel *m_baudHeld;
    QLabel *m_linkNote;
    QPushButton *m_apply;
    QLabel *m_linkIcon;
    QLabel *m_linkStatus;
    QPushButton *m_reconnect;
    QLabel *m_flashNote;
    QWidget *m_unsavedRow;
    QLabel *m_unsavedIcon;
    QLabel *m_unsavedText;
    QPushButton *m_save;
    QLabel *m_flashIcon;
    QLabel *m_flashStatus;
    QLabel *m_factoryNote;
    QPushButton *m_reset;
    QPointer<QMessageBox> m_confirmation;
    LinkEvent m_linkEvent = LinkEvent::None;
    FlashEvent m_flashEvent = FlashEvent::None;
    int m_targetId = 0;
    int m_targetBaud = 0;
    QString m_reason;
    LinkSettings m_previous;  // what worked before a failed change
    bool m_idTouched = false; // the user typed a new id: device updates must not undo it
    bool m_baudTouched = false;
    bool m_saveAfterLinkChange = false; // asked with the change: save once it answers there
};

} // namespace stepcom
