#include "widgets/sequence/sequencepoints.h"

#include "map/parameter.h"
#include "motion/travellimits.h"
#include "session/devicesession.h"
#include "session/jogcontroller.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "widgets/fields/wrappingrow.h"
#include "widgets/motion/jogbutton.h"

#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QRegularExpression>
#include <QTableWidget>
#include <QVBoxLayout>

namespace stepcom {

namespace {

constexpr int kNameRole = Qt::UserRole;

const QRegularExpression &nameRule()
{
    static const QRegularExpression re(QStringLiteral("^[A-Za-z0-9_\\-]{1,40}$"));
    return re;
}

} // namespace

SequencePoints::SequencePoints(DeviceSession *session, QWidget *parent)
    : QWidget(parent)
    , m_session(session)
    , m_motors(session->map().blockCount(QStringLiteral("motor")))
    , m_table(new QTableWidget(this))
    , m_teach(new QPushButton(this))
    , m_update(new QPushButton(this))
    , m_remove(new QPushButton(this))
    , m_message(new QLabel(this))
{
    m_table->setObjectName(QStringLiteral("sequencePoints"));
    m_table->setColumnCount(1 + m_motors);
    m_table->verticalHeader()->hide();
    // The columns share the table's width: it never scrolls sideways on a narrow page.
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_teach->setObjectName(QStringLiteral("teachHere"));
    m_update->setObjectName(QStringLiteral("teachSelected"));
    m_remove->setObjectName(QStringLiteral("removePoint"));
    m_message->setObjectName(QStringLiteral("pointsMessage"));
    m_message->setWordWrap(true);
    m_message->hide();

    // Hold to move, as on the Jog page: the hand lets go, the axis stops.
    auto *jog = new QGridLayout;
    JogController *jogger = session->jog();
    for (int n = 1; n <= m_motors; ++n) {
        auto *label = new QLabel(this);
        auto *reverse = new JogButton(this);
        auto *forward = new JogButton(this);
        reverse->setObjectName(QStringLiteral("pointJogReverse%1").arg(n));
        forward->setObjectName(QStringLiteral("pointJogForward%1").arg(n));
        connect(reverse, &JogButton::jogPressed, this,
                [jogger, n] { jogger->press(n, JogController::Direction::Reverse); });
        connect(forward, &JogButton::jogPressed, this,
                [jogger, n] { jogger->press(n, JogController::Direction::Forward); });
        connect(reverse, &JogButton::jogReleased, this, [jogger, n] { jogger->release(n); });
        connect(forward, &JogButton::jogReleased, this, [jogger, n] { jogger->release(n); });
        jog->addWidget(label, n - 1, 0);
        jog->addWidget(reverse, n - 1, 1);
        jog->addWidget(forward, n - 1, 2);
        m_jog << reverse << forward;
        m_jogLabels << label;
    }
    jog->setColumnStretch(3, 1);
    auto *buttons = new WrappingRow(this);
    buttons->first()->addWidget(m_teach);
    buttons->first()->addWidget(m_update);
    buttons->second()->addWidget(m_remove);
    buttons->second()->addStretch(1);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(jog);
    layout->addWidget(buttons);
    layout->addWidget(m_message);
    layout->addWidget(m_table, 1);

    connect(m_teach, &QPushButton::clicked, this, [this] { teach(false); });
    connect(m_update, &QPushButton::clicked, this, [this] { teach(true); });
    connect(m_remove, &QPushButton::clicked, this, [this] {
        const int row = m_table->currentRow();
        if (row < 0)
            return;
        m_points.remove(m_table->item(row, 0)->data(kNameRole).toString());
        fill();
        Q_EMIT changed();
    });
    connect(m_table, &QTableWidget::cellChanged, this, &SequencePoints::onCellChanged);
    connect(m_table, &QTableWidget::itemSelectionChanged, this, &SequencePoints::updateButtons);
    connect(session->connection(), &SessionConnection::linkStateChanged, this,
            &SequencePoints::updateButtons);
    retranslate();
    fill();
    updateButtons();
}

JogButton *SequencePoints::jogButton(int motor, bool forward) const
{
    return m_jog.value((motor - 1) * 2 + (forward ? 1 : 0));
}

void SequencePoints::setPoints(const Points &points)
{
    m_points = points;
    fill();
}

void SequencePoints::setEditable(bool editable)
{
    m_editable = editable;
    m_table->setEditTriggers(editable ? QAbstractItemView::DoubleClicked |
                                            QAbstractItemView::EditKeyPressed |
                                            QAbstractItemView::AnyKeyPressed
                                      : QAbstractItemView::NoEditTriggers);
    updateButtons();
}

void SequencePoints::updateButtons()
{
    // Jogging and teaching need a controller that answers; editing the table does not.
    const bool connected = m_session->connection()->isConnected();
    const bool selected = m_table->currentRow() >= 0;
    m_teach->setEnabled(m_editable && connected);
    for (JogButton *b : m_jog)
        b->setEnabled(m_editable && connected);
    m_update->setEnabled(m_editable && connected && selected);
    m_remove->setEnabled(m_editable && selected);
}

QMap<int, double> SequencePoints::livePosition(QStringList *unknown) const
{
    QMap<int, double> out;
    const bool connected = m_session->connection()->isConnected();
    for (int n = 1; n <= m_motors; ++n) {
        const Parameter *p = TravelLimits::positionParameter(m_session->map(), n);
        const auto raw =
            p && connected ? m_session->parameters()->store()->deviceValue(p->key) : std::nullopt;
        if (raw)
            out.insert(n, p->toEngineering(*raw));
        else
            *unknown << tr("motor %1").arg(n);
    }
    return out;
}

bool SequencePoints::teach(bool update)
{
    QStringList unknown;
    const QMap<int, double> here = livePosition(&unknown);
    if (!unknown.isEmpty()) {
        say(tr("Not taught: the position of %1 is not known (connect, and let the status poll "
               "read it).")
                .arg(unknown.join(QLatin1String(", "))),
            true);
        return false;
    }
    const int row = m_table->currentRow();
    if (update && row >= 0) {
        const QString name = m_table->item(row, 0)->data(kNameRole).toString();
        m_points[name] = here;
        fill();
        say(tr("Point %1 taught again at the live position.").arg(name), false);
    } else {
        const QString name = addPoint(here);
        say(tr("Point %1 taught at the live position; double-click its name to rename it.")
                .arg(name),
            false);
    }
    Q_EMIT changed();
    return true;
}

QString SequencePoints::addPoint(const QMap<int, double> &position)
{
    int n = 1;
    while (m_points.contains(QStringLiteral("p%1").arg(n)))
        ++n;
    const QString name = QStringLiteral("p%1").arg(n);
    m_points.insert(name, position);
    fill();
    for (int row = 0; row < m_table->rowCount(); ++row) {
        if (m_table->item(row, 0)->data(kNameRole).toString() == name)
            m_table->selectRow(row);
    }
    return name;
}

void SequencePoints::fill()
{
    m_filling = true;
    const QString selected =
        m_table->currentRow() >= 0 && m_table->item(m_table->currentRow(), 0)
            ? m_table->item(m_table->currentRow(), 0)->data(kNameRole).toString()
            : QString();
    m_table->setRowCount(int(m_points.size()));
    int row = 0;
    for (auto it = m_points.begin(); it != m_points.end(); ++it, ++row) {
        auto *name = new QTableWidgetItem(it.key());
        name->setData(kNameRole, it.key());
        m_table->setItem(row, 0, name);
        for (int n = 1; n <= m_motors; ++n) {
            const Parameter *p = TravelLimits::positionParameter(m_session->map(), n);
            auto *cell = new QTableWidgetItem(
                it->contains(n) ? QLocale().toString(it->value(n), 'f', p ? p->decimals() : 2)
                                : QString());
            cell->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_table->setItem(row, n, cell);
        }
        if (it.key() == selected)
            m_table->selectRow(row);
    }
    m_filling = false;
}

void SequencePoints::onCellChanged(int row, int column)
{
    if (m_filling)
        return;
    QTableWidgetItem *nameItem = m_table->item(row, 0);
    const QString name = nameItem->data(kNameRole).toString();
    const QString text = m_table->item(row, column)->text().trimmed();
    if (column == 0) {
        if (text == name)
            return;
        if (!nameRule().match(text).hasMatch() || m_points.contains(text)) {
            say(m_points.contains(text)
                    ? tr("There is a point %1 already: the name stays %2.").arg(text, name)
                    : tr("\"%1\" cannot name a point: use 1-40 letters, digits, _ or -.").arg(text),
                true);
            fill();
            return;
        }
        m_points.insert(text, m_points.take(name));
        fill();
        say({}, false);
        Q_EMIT renamed(name, text);
        Q_EMIT changed();
        return;
    }
    if (text.isEmpty()) {
        m_points[name].remove(column);
    } else {
        bool ok = false;
        double v = QLocale().toDouble(text, &ok);
        if (!ok)
            v = text.toDouble(&ok); // "30.5" on a comma locale
        if (!ok) {
            say(tr("\"%1\" is no position: point %2 keeps motor %3 as it was.")
                    .arg(text, name)
                    .arg(column),
                true);
            fill();
            return;
        }
        m_points[name][column] = v;
    }
    fill();
    say({}, false);
    Q_EMIT changed();
}

void SequencePoints::say(const QString &text, bool problem)
{
    m_message->setText(text);
    m_message->setVisible(!text.isEmpty());
    m_message->setStyleSheet(problem ? QStringLiteral("color: #c62828;") : QString());
}

void SequencePoints::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void SequencePoints::retranslate()
{
    QStringList headers{tr("Point")};
    for (int n = 1; n <= m_motors; ++n) {
        const Parameter *p = TravelLimits::positionParameter(m_session->map(), n);
        headers << (p && !p->unit.isEmpty() ? tr("Motor %1 (%2)").arg(n).arg(p->unit)
                                            : tr("Motor %1").arg(n));
        m_jogLabels[n - 1]->setText(tr("Jog motor %1:").arg(n));
        jogButton(n, false)->setText(tr("◀ Hold"));
        jogButton(n, true)->setText(tr("Hold ▶"));
        jogButton(n, false)->setAccessibleName(tr("Jog motor %1 reverse (hold)").arg(n));
        jogButton(n, true)->setAccessibleName(tr("Jog motor %1 forward (hold)").arg(n));
    }
    m_table->setHorizontalHeaderLabels(headers);
    m_table->setAccessibleName(tr("Points"));
    m_teach->setText(tr("&Teach here"));
    m_teach->setToolTip(tr("A new point at the live position of every motor"));
    m_update->setText(tr("Teach &selected again"));
    m_remove->setText(tr("Remove point"));
}

} // namespace stepcom
