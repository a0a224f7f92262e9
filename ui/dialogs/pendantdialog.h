#pragma once

#include <QDialog>
#include <QImage>

class QCheckBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace stepcom {

class PendantServer;

// Device → Pendant…: starts and stops the phone pendant, shows the QR code and the address to
// pair with (a new token at every start), the phones connected (address, browser, since when)
// with Disconnect, whether jogging from the pendant is allowed (off at every start) and who
// holds control, with "Take control back". Not modal: the window stays usable beside it.
class PendantDialog : public QDialog
{
    Q_OBJECT
public:
    explicit PendantDialog(PendantServer *server, QWidget *parent = nullptr);

    // The QR code of `text` (libqrencode), black modules on white with the quiet zone, each
    // module `scale` pixels; a null image when it cannot be encoded.
    static QImage qrCode(const QString &text, int scale);

    QPushButton *startButton() const { return m_start; }
    QCheckBox *allowJog() const { return m_allow; }
    QLabel *addressLabel() const { return m_address; }
    QLabel *qrLabel() const { return m_qr; }
    QTableWidget *phones() const { return m_phones; }
    QPushButton *disconnectButton() const { return m_disconnect; }
    QPushButton *takeBackButton() const { return m_takeBack; }
    QLabel *controlLabel() const { return m_control; }

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void refresh();
    void toggle();

    PendantServer *m_server;
    QLabel *m_intro;
    QLabel *m_portLabel;
    QSpinBox *m_port;
    QPushButton *m_start;
    QLabel *m_error;
    QLabel *m_qr;
    QLabel *m_address;
    QCheckBox *m_allow;
    QLabel *m_control;
    QPushButton *m_takeBack;
    QLabel *m_phonesLabel;
    QTableWidget *m_phones;
    QPushButton *m_disconnect;
    QLabel *m_safety;
    QPushButton *m_close;
};

} // namespace stepcom
