#include "pages/modespage.h"

#include "base/language.h"
#include "base/writechangesdialog.h"
#include "device/writereview.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "widgets/fields/aboutbox.h"
#include "widgets/fields/parameterfield.h"
#include "widgets/fields/parameterform.h"

#include <QComboBox>
#include <QEvent>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace stepcom {

namespace {

const QString kModeKey = QStringLiteral("mode.system");
const QString kTripsKey = QStringLiteral("mode.round_trips");

// The manual's special modes: what the mode does and what IN1-IN4 do in it.
struct ModeText
{
    const char *explanation;
    const char *inputs[4];
};

const ModeText kModes[] = {
    {QT_TRANSLATE_NOOP("stepcom::ModesPage",
                       "Normal operation (factory setting): the motors run from commands (this "
                       "program, the bus); the inputs are the limits and home inputs chosen in "
                       "the limit settings."),
     {QT_TRANSLATE_NOOP("stepcom::ModesPage", "as set in the limit settings"),
      QT_TRANSLATE_NOOP("stepcom::ModesPage", "as set in the limit settings"),
      QT_TRANSLATE_NOOP("stepcom::ModesPage", "as set in the limit settings"),
      QT_TRANSLATE_NOOP("stepcom::ModesPage", "as set in the limit settings")}},
    {QT_TRANSLATE_NOOP("stepcom::ModesPage",
                       "Motor 1 only. A start on IN4 runs it forward to the positive limit "
                       "(IN1), then in reverse to the negative limit (IN2): one round trip, "
                       "repeated the round-trip count of times (0 = endless). The speed comes "
                       "from the on-board or external potentiometer."),
     {QT_TRANSLATE_NOOP("stepcom::ModesPage", "positive limit"),
      QT_TRANSLATE_NOOP("stepcom::ModesPage", "negative limit"),
      QT_TRANSLATE_NOOP("stepcom::ModesPage", "emergency stop"),
      QT_TRANSLATE_NOOP("stepcom::ModesPage", "start (forward)")}},
    {QT_TRANSLATE_NOOP("stepcom::ModesPage",
                       "Motor 1 runs on a short pulse: IN1 starts it (forward the first time), "
                       "IN2-IN4 stop it and choose the direction of the next start. The limit "
                       "settings are ignored."),
     {QT_TRANSLATE_NOOP("stepcom::ModesPage", "start (forward the first time)"),
      QT_TRANSLATE_NOOP("stepcom::ModesPage", "stop; next start keeps the direction"),
      QT_TRANSLATE_NOOP("stepcom::ModesPage", "stop; next start reverses"),
      QT_TRANSLATE_NOOP("stepcom::ModesPage", "stop; next start goes forward")}},
    {QT_TRANSLATE_NOOP("stepcom::ModesPage",
                       "Motor 1 runs forward on a pulse on IN1 and in reverse on a pulse on IN2; "
                       "IN3 and IN4 are its limits. The limit settings are ignored."),
     {QT_TRANSLATE_NOOP("stepcom::ModesPage", "run forward"),
      QT_TRANSLATE_NOOP("stepcom::ModesPage", "run reverse"),
      QT_TRANSLATE_NOOP("stepcom::ModesPage", "positive limit: stops a forward run, only "
                                              "reverse allowed then"),
      QT_TRANSLATE_NOOP("stepcom::ModesPage", "negative limit: stops a reverse run")}},
    {QT_TRANSLATE_NOOP("stepcom::ModesPage",
                       "Motor 1 runs while IN1 (forward) or IN2 (reverse) is held and stops when "
                       "it is released; IN3 and IN4 are its limits. The limit settings are "
                       "ignored."),
     {QT_TRANSLATE_NOOP("stepcom::ModesPage", "held: forward; released: stop"),
      QT_TRANSLATE_NOOP("stepcom::ModesPage", "held: reverse; released: stop"),
      QT_TRANSLATE_NOOP("stepcom::ModesPage", "positive limit"),
      QT_TRANSLATE_NOOP("stepcom::ModesPage", "negative limit")}},
    {QT_TRANSLATE_NOOP("stepcom::ModesPage",
                       "Each pulse on IN1 moves motor 1 forward by its set move distance, each "
                       "pulse on IN2 in reverse; IN3 and IN4 are its limits. The limit settings "
                       "are ignored."),
     {QT_TRANSLATE_NOOP("stepcom::ModesPage", "forward by the set distance"),
      QT_TRANSLATE_NOOP("stepcom::ModesPage", "reverse by the set distance"),
      QT_TRANSLATE_NOOP("stepcom::ModesPage", "positive limit"),
      QT_TRANSLATE_NOOP("stepcom::ModesPage", "negative limit")}},
};
constexpr int kModeCount = int(std::size(kModes));

} // namespace

ModesPage::ModesPage(DeviceSession *session, WriteFlow *writes, QWidget *parent)
    : Page(session, parent)
    , m_writeFlow(writes)
{
    QWidget *content = scrollableContent();
    auto *layout = new QVBoxLayout(content);
    m_about = new AboutBox(content); // Explanations on demand
    layout->addWidget(m_about);

    m_modeBox = new QGroupBox(content);
    auto *modeLayout = new QVBoxLayout(m_modeBox);
    auto *row = new QHBoxLayout;
    m_modeLabel = new QLabel(m_modeBox);
    m_mode = new QComboBox(m_modeBox);
    m_mode->setObjectName(QStringLiteral("modeBox"));
    m_modeLabel->setBuddy(m_mode);
    for (int i = 0; i < kModeCount; ++i)
        m_mode->addItem(QString(), i);
    row->addWidget(m_modeLabel);
    row->addWidget(m_mode, 1);
    m_current = new QLabel(m_modeBox);
    row->addWidget(m_current, 1);
    modeLayout->addLayout(row);
    m_explanation = new QLabel(m_modeBox);
    m_explanation->setObjectName(QStringLiteral("modeExplanation"));
    m_explanation->setWordWrap(true);
    modeLayout->addWidget(m_explanation);
    m_warning = new QLabel(m_modeBox);
    m_warning->setObjectName(QStringLiteral("limitsWarning"));
    m_warning->setWordWrap(true);
    QFont bold = m_warning->font();
    bold.setBold(true);
    m_warning->setFont(bold);
    modeLayout->addWidget(m_warning);
    layout->addWidget(m_modeBox);

    m_tableBox = new QGroupBox(content);
    auto *tableLayout = new QVBoxLayout(m_tableBox);
    m_table = new QTableWidget(kModeCount, 6, m_tableBox);
    m_table->setObjectName(QStringLiteral("inputsTable"));
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    m_table->setWordWrap(true);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_table->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    // As wide as the page gives it, as tall as its rows then are (fitTable()).
    m_table->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    m_table->installEventFilter(this);
    for (int r = 0; r < kModeCount; ++r) {
        for (int c = 0; c < 6; ++c)
            m_table->setItem(r, c, new QTableWidgetItem);
    }
    tableLayout->addWidget(m_table);
    layout->addWidget(m_tableBox);

    m_tripsBox = new QGroupBox(content);
    auto *tripsLayout = new QVBoxLayout(m_tripsBox);
    m_form = new ParameterForm(session->parameters()->store(), m_tripsBox);
    m_form->addParameter(kTripsKey);
    tripsLayout->addWidget(m_form);
    m_tripsNote = new QLabel(m_tripsBox);
    m_tripsNote->setWordWrap(true);
    tripsLayout->addWidget(m_tripsNote);
    m_write = new QPushButton(m_tripsBox);
    m_write->setObjectName(QStringLiteral("writeButton"));
    tripsLayout->addWidget(m_write, 0, Qt::AlignLeft);
    layout->addWidget(m_tripsBox);
    layout->addStretch(1);

    connect(m_mode, &QComboBox::activated, this,
            [this](int index) { confirmMode(m_mode->itemData(index).toInt()); });
    connect(m_mode, &QComboBox::currentIndexChanged, this, &ModesPage::describe);
    connect(m_write, &QPushButton::clicked, this, &ModesPage::openWriteDialog);
    connect(session->parameters()->store(), &ParameterStore::valueChanged, this,
            [this](const QString &k) {
                if (k == kModeKey || k == kTripsKey)
                    refresh();
            });
    connect(session->parameters()->store(), &ParameterStore::editsChanged, this,
            &ModesPage::refresh);
    connect(session->connection(), &SessionConnection::linkStateChanged, this, &ModesPage::refresh);
    connect(session->connection(), &SessionConnection::disconnected, this, &ModesPage::refresh);
    retranslate();
}

QString ModesPage::title() const
{
    return tr("Special modes");
}

QStringList ModesPage::keys() const
{
    return {kModeKey, kTripsKey};
}

bool ModesPage::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_table && event->type() == QEvent::Resize)
        fitTable();
    return Page::eventFilter(watched, event);
}

void ModesPage::fitTable()
{
    m_table->resizeRowsToContents();
    int height = m_table->horizontalHeader()->height() + 2 * m_table->frameWidth();
    for (int r = 0; r < m_table->rowCount(); ++r)
        height += m_table->rowHeight(r);
    if (m_table->height() != height)
        m_table->setFixedHeight(height);
}

std::optional<qint64> ModesPage::deviceMode() const
{
    // Editing a profile file: the mode the file will hold.
    if (session()->parameters()->store()->isFile())
        return session()->parameters()->store()->shownValue(kModeKey);
    return session()->parameters()->store()->deviceValue(kModeKey);
}

int ModesPage::shownMode() const
{
    return m_mode->currentIndex() >= 0 ? m_mode->currentData().toInt() : -1;
}

void ModesPage::chooseMode(int mode)
{
    const int index = m_mode->findData(mode);
    if (index < 0 || !m_mode->isEnabled())
        return;
    m_mode->setCurrentIndex(index);
    confirmMode(mode);
}

void ModesPage::confirmMode(int mode)
{
    const Parameter *p = session()->map().find(kModeKey);
    if (p &&
        session()->parameters()->store()->isFile()) { // a file's value: an edit, nothing is sent
        session()->parameters()->store()->edit(kModeKey, mode);
        refresh();
        return;
    }
    if (!p || mode < 0 || mode >= kModeCount || !session()->connection()->isConnected() ||
        deviceMode() == mode) {
        refresh();
        return;
    }
    if (m_confirmation)
        m_confirmation->close();
    const QString lang = Language::instance().current();
    QString inputs;
    for (int i = 0; i < 4; ++i)
        inputs += tr("IN%1: %2").arg(i + 1).arg(tr(kModes[mode].inputs[i])) + QLatin1Char('\n');
    QString details = tr(kModes[mode].explanation) + QStringLiteral("\n\n") + inputs;
    // What stepcomctl prints before the same write: one review (core/device/writereview).
    const QStringList review =
        WriteReview::problems(*session()->parameters()->store(), {{p, mode}});
    if (!review.isEmpty())
        details += QLatin1Char('\n') + review.join(QLatin1Char('\n'));
    auto *box = new QMessageBox(
        QMessageBox::Warning, tr("Change the system mode"),
        tr("Change the controller to mode %1 “%2”? This changes what the machine's inputs "
           "IN1-IN4 do, at once.")
            .arg(mode)
            .arg(p->displayRaw(mode, lang)),
        QMessageBox::Yes | QMessageBox::Cancel, this);
    box->setInformativeText(details);
    box->button(QMessageBox::Yes)->setText(tr("Change mode"));
    // A stray Enter must not change the machine: the safe answer is the default.
    box->setDefaultButton(QMessageBox::Cancel);
    box->setEscapeButton(QMessageBox::Cancel);
    box->setAttribute(Qt::WA_DeleteOnClose);
    m_confirmation = box;
    connect(box, &QMessageBox::finished, this, [this, p, mode](int result) {
        m_confirmation.clear();
        // This question was the review (its problems are in it): the flow asks nothing more
        // and logs, writes and verifies it as the write dialog's writes.
        if (result == QMessageBox::Yes)
            m_writeFlow->writeConfirmed({ParameterWrite{p, mode}});
        refresh();
    });
    box->open();
    refresh();
}

void ModesPage::openWriteDialog()
{
    m_writeFlow->openFor({kTripsKey});
}

void ModesPage::refresh()
{
    const std::optional<qint64> device = deviceMode();
    const bool connected = session()->connection()->isConnected();
    // While nothing is being asked the list shows what the controller holds.
    if (!m_confirmation) {
        const int index = device ? m_mode->findData(int(*device)) : -1;
        if (index != m_mode->currentIndex()) {
            const QSignalBlocker block(m_mode);
            m_mode->setCurrentIndex(index);
        }
    }
    m_mode->setEnabled((connected || session()->parameters()->store()->isFile()) &&
                       device.has_value() && !m_confirmation);
    describe();
    bool edited = session()->parameters()->store()->entry(kTripsKey).edited.has_value();
    m_write->setEnabled(connected && edited);
}

void ModesPage::describe()
{
    const std::optional<qint64> device = deviceMode();
    const int shown = shownMode();
    if (session()->parameters()->store()->isFile())
        m_current->setText(!device       ? tr("The profile file does not set the mode.")
                           : device == 0 ? tr("The profile sets the normal mode.")
                                         : tr("The profile sets special mode %1.").arg(*device));
    else
        m_current->setText(!device ? tr("The controller's mode is not known yet.")
                           : device == 0
                               ? tr("The controller runs normally.")
                               : tr("The controller is in special mode %1.").arg(*device));
    m_explanation->setText(shown >= 0 ? tr(kModes[shown].explanation) : QString());
    const bool ignoring =
        (shown >= 0 && WriteReview::modeIgnoresLimits(shown)) ||
        (device && *device >= 0 && *device < kModeCount && WriteReview::modeIgnoresLimits(*device));
    QPalette pal = m_warning->palette();
    pal.setColor(QPalette::WindowText,
                 ignoring ? QColor(220, 40, 40) : palette().color(QPalette::WindowText));
    m_warning->setPalette(pal);
    for (int r = 0; r < kModeCount; ++r) {
        for (int c = 0; c < 6; ++c) {
            QTableWidgetItem *item = m_table->item(r, c);
            QFont f = item->font();
            f.setBold(device == r);
            item->setFont(f);
            item->setBackground(device == r ? palette().brush(QPalette::AlternateBase) : QBrush());
        }
    }
}

void ModesPage::retranslate()
{
    const QString lang = Language::instance().current();
    const Parameter *p = session()->map().find(kModeKey);
    m_modeBox->setTitle(tr("System mode (40300)"));
    m_modeLabel->setText(tr("&Mode:"));
    for (int i = 0; i < kModeCount; ++i)
        m_mode->setItemText(
            i, QStringLiteral("%1 — %2").arg(i).arg(p ? p->displayRaw(i, lang) : QString()));
    // The warning in one line; which inputs still stop is in the table below and on demand.
    const QString limits = tr("Modes 2-5 ignore the limit settings: the limit and home inputs set "
                              "for the motors no longer stop anything. In modes 3-5 only IN3 and "
                              "IN4 act as limits; in mode 2 nothing does (IN2-IN4 only stop). Wire "
                              "and test them before using these modes.");
    m_warning->setText(tr("Modes 2-5 ignore the limit settings: the limit and home inputs set "
                          "for the motors no longer stop anything."));
    m_warning->setToolTip(limits);
    m_warning->setWhatsThis(limits);
    m_about->setText(limits);
    m_tableBox->setTitle(tr("What the inputs do in each mode (motor 1; short pulses unless "
                            "“held”)"));
    m_table->setHorizontalHeaderLabels(
        {tr("Mode"), tr("IN1"), tr("IN2"), tr("IN3"), tr("IN4"), tr("Limit settings")});
    for (int r = 0; r < kModeCount; ++r) {
        m_table->item(r, 0)->setText(m_mode->itemText(r));
        for (int i = 0; i < 4; ++i)
            m_table->item(r, i + 1)->setText(tr(kModes[r].inputs[i]));
        m_table->item(r, 5)->setText(WriteReview::modeIgnoresLimits(r) ? tr("ignored")
                                                                       : tr("used"));
    }
    m_tripsBox->setTitle(tr("Round trips (40301)"));
    m_tripsNote->setText(tr("Only used in mode 1 (round trip): how many round trips motor 1 "
                            "makes after a start; 0 = endless."));
    m_write->setText(tr("&Write changes…"));
    fitTable();
    refresh();
}

} // namespace stepcom
