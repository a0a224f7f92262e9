#include "widgets/sequence/sequenceeditor.h"

#include "widgets/fields/wrappingrow.h"
#include "widgets/sequence/sequencestepform.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMenu>
#include <QPushButton>
#include <QRegularExpression>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace stepcom {

namespace {

using StepKind = SequenceStep::Kind;

constexpr int kPathRole = Qt::UserRole;

// "steps[1].steps[0]" → {1, 0}; empty when it is no step's path.
QList<int> indexesOf(const QString &path)
{
    static const QRegularExpression part(QStringLiteral("^steps\\[(\\d+)\\]$"));
    QList<int> out;
    for (const QString &p : path.split(QLatin1Char('.'))) {
        const auto m = part.match(p);
        if (!m.hasMatch())
            return {};
        out << m.captured(1).toInt();
    }
    return out;
}

// The step a problem of the file's checks names: "FILE: steps[1].steps[0].move_to: ..." →
// "steps[1].steps[0]".
QString problemPath(const QString &problem)
{
    static const QRegularExpression re(QStringLiteral("(steps\\[\\d+\\](?:\\.steps\\[\\d+\\])*)"));
    const auto m = re.match(problem);
    return m.hasMatch() ? m.captured(1) : QString();
}

} // namespace

SequenceEditor::SequenceEditor(const RegisterMap &map, QWidget *parent)
    : QWidget(parent)
    , m_map(map)
    , m_tree(new QTreeWidget(this))
    , m_form(new SequenceStepForm(map, this))
    , m_add(new QToolButton(this))
    , m_remove(new QPushButton(this))
    , m_up(new QPushButton(this))
    , m_down(new QPushButton(this))
    , m_in(new QPushButton(this))
    , m_out(new QPushButton(this))
    , m_hint(new QLabel(this))
{
    m_tree->setObjectName(QStringLiteral("sequenceSteps"));
    m_tree->setColumnCount(1);
    m_tree->setHeaderHidden(true);
    m_tree->setRootIsDecorated(true);
    m_tree->setUniformRowHeights(true);
    m_tree->setMinimumHeight(fontMetrics().height() * 8); // the run's controls stay in view
    m_tree->setSelectionMode(QAbstractItemView::SingleSelection);
    m_add->setObjectName(QStringLiteral("addStep"));
    m_add->setPopupMode(QToolButton::InstantPopup);
    m_add->setToolButtonStyle(Qt::ToolButtonTextOnly);
    auto *menu = new QMenu(m_add);
    for (StepKind k :
         {StepKind::Home, StepKind::MoveTo, StepKind::MoveBy, StepKind::WaitInput, StepKind::Output,
          StepKind::Outputs, StepKind::Dwell, StepKind::Repeat, StepKind::Speed}) {
        QAction *a = menu->addAction(QString());
        a->setObjectName(QStringLiteral("addStepKind"));
        a->setData(int(k));
        connect(a, &QAction::triggered, this, [this, k] { addStep(k); });
    }
    m_add->setMenu(menu);
    m_remove->setObjectName(QStringLiteral("removeStep"));
    m_up->setObjectName(QStringLiteral("stepUp"));
    m_down->setObjectName(QStringLiteral("stepDown"));
    m_in->setObjectName(QStringLiteral("stepIntoLoop"));
    m_out->setObjectName(QStringLiteral("stepOutOfLoop"));
    for (QPushButton *b : {m_remove, m_up, m_down, m_in, m_out})
        b->setAutoDefault(false);
    m_hint->setWordWrap(true);
    m_hint->setObjectName(QStringLiteral("stepProblem"));

    // Two rows on a narrow page, rather than a page that scrolls sideways.
    auto *buttons = new WrappingRow(this);
    buttons->first()->addWidget(m_add);
    buttons->first()->addWidget(m_remove);
    buttons->first()->addWidget(m_up);
    buttons->first()->addWidget(m_down);
    buttons->second()->addWidget(m_in);
    buttons->second()->addWidget(m_out);
    buttons->second()->addStretch(1);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(buttons);
    layout->addWidget(m_tree, 1);
    layout->addWidget(m_hint);
    layout->addWidget(m_form);

    connect(m_tree, &QTreeWidget::currentItemChanged, this, &SequenceEditor::onSelected);
    connect(m_form, &SequenceStepForm::edited, this, &SequenceEditor::onEdited);
    connect(m_remove, &QPushButton::clicked, this, &SequenceEditor::removeSelected);
    connect(m_up, &QPushButton::clicked, this, [this] { moveSelected(-1); });
    connect(m_down, &QPushButton::clicked, this, [this] { moveSelected(1); });
    connect(m_in, &QPushButton::clicked, this, &SequenceEditor::intoLoopAbove);
    connect(m_out, &QPushButton::clicked, this, &SequenceEditor::outOfLoop);
    retranslate();
    rebuild({});
}

void SequenceEditor::renumber(QList<SequenceStep> &steps, const QString &parent)
{
    for (int i = 0; i < steps.size(); ++i) {
        const QString here = QStringLiteral("steps[%1]").arg(i);
        steps[i].path = parent.isEmpty() ? here : parent + QLatin1Char('.') + here;
        renumber(steps[i].steps, steps[i].path);
    }
}

void SequenceEditor::setSteps(const QList<SequenceStep> &steps)
{
    QList<SequenceStep> numbered = steps;
    renumber(numbered);
    const auto shape = [](const QList<SequenceStep> &list) {
        QStringList paths;
        std::function<void(const QList<SequenceStep> &)> walk = [&](const auto &l) {
            for (const SequenceStep &s : l) {
                paths << s.path;
                walk(s.steps);
            }
        };
        walk(list);
        return paths;
    };
    const bool sameShape = shape(numbered) == shape(m_steps) && m_tree->topLevelItemCount() > 0;
    m_steps = numbered;
    if (sameShape) {
        // The same steps judged again (a point's values filled in): the texts, not the tree,
        // so the field being typed in keeps its focus.
        for (QTreeWidgetItemIterator it(m_tree); *it; ++it) {
            if (const SequenceStep *s = stepAt((*it)->data(0, kPathRole).toString()))
                (*it)->setText(0, s->describe());
        }
        setProblems(m_problems);
        return;
    }
    rebuild(selectedPath());
}

void SequenceEditor::setPointNames(const QStringList &names)
{
    m_points = names;
    if (const SequenceStep *s = stepAt(selectedPath())) {
        if (s->kind == StepKind::MoveTo)
            m_form->setStep(*s, m_points);
    }
}

void SequenceEditor::renamePoint(const QString &from, const QString &to)
{
    std::function<void(QList<SequenceStep> &)> walk = [&](QList<SequenceStep> &list) {
        for (SequenceStep &s : list) {
            if (s.kind == StepKind::MoveTo && s.point == from)
                s.point = to;
            walk(s.steps);
        }
    };
    walk(m_steps);
    if (const SequenceStep *s = stepAt(selectedPath()))
        m_form->setStep(*s, m_points);
}

void SequenceEditor::setProblems(const QStringList &problems)
{
    m_problems = problems;
    QHash<QString, QStringList> byPath;
    for (const QString &p : problems)
        byPath[problemPath(p)] << p;
    for (QTreeWidgetItemIterator it(m_tree); *it; ++it) {
        const QString path = (*it)->data(0, kPathRole).toString();
        const QStringList mine = byPath.value(path);
        (*it)->setForeground(0, mine.isEmpty() ? palette().brush(QPalette::Text)
                                               : QBrush(QColor(0xc6, 0x28, 0x28)));
        (*it)->setToolTip(0, mine.join(QLatin1Char('\n')));
        (*it)->setIcon(0, mine.isEmpty() ? QIcon()
                                         : style()->standardIcon(QStyle::SP_MessageBoxWarning));
    }
    const QStringList selected = byPath.value(selectedPath());
    m_hint->setText(selected.join(QLatin1Char('\n')));
    m_hint->setVisible(!selected.isEmpty());
}

void SequenceEditor::setCurrent(const QString &path)
{
    m_current = path;
    for (QTreeWidgetItemIterator it(m_tree); *it; ++it) {
        QFont f = (*it)->font(0);
        f.setBold(!path.isEmpty() && (*it)->data(0, kPathRole).toString() == path);
        (*it)->setFont(0, f);
    }
    if (QTreeWidgetItem *item = itemFor(path)) {
        m_tree->setCurrentItem(item);
        m_tree->scrollToItem(item);
    }
}

void SequenceEditor::setEditable(bool editable)
{
    m_editable = editable;
    m_form->setEnabled(editable && m_form->hasStep());
    updateButtons();
}

QString SequenceEditor::selectedPath() const
{
    const QTreeWidgetItem *item = m_tree->currentItem();
    return item ? item->data(0, kPathRole).toString() : QString();
}

void SequenceEditor::selectPath(const QString &path)
{
    if (QTreeWidgetItem *item = itemFor(path))
        m_tree->setCurrentItem(item);
}

QTreeWidgetItem *SequenceEditor::itemFor(const QString &path) const
{
    for (QTreeWidgetItemIterator it(m_tree); *it; ++it) {
        if ((*it)->data(0, kPathRole).toString() == path)
            return *it;
    }
    return nullptr;
}

QList<SequenceStep> *SequenceEditor::listOf(const QString &path, int *index)
{
    const QList<int> at = indexesOf(path);
    if (at.isEmpty())
        return nullptr;
    QList<SequenceStep> *list = &m_steps;
    for (int i = 0; i + 1 < at.size(); ++i) {
        if (at[i] >= list->size())
            return nullptr;
        list = &(*list)[at[i]].steps;
    }
    if (at.last() >= list->size())
        return nullptr;
    *index = at.last();
    return list;
}

SequenceStep *SequenceEditor::stepAt(const QString &path)
{
    int i = 0;
    QList<SequenceStep> *list = listOf(path, &i);
    return list ? &(*list)[i] : nullptr;
}

void SequenceEditor::rebuild(const QString &select)
{
    m_rebuilding = true;
    m_tree->clear();
    addItems(m_steps, nullptr);
    m_tree->expandAll();
    m_rebuilding = false;
    QTreeWidgetItem *item = itemFor(select);
    if (!item && m_tree->topLevelItemCount() > 0)
        item = m_tree->topLevelItem(0);
    m_tree->setCurrentItem(item);
    onSelected();
    setProblems(m_problems);
    setCurrent(m_current);
}

void SequenceEditor::addItems(const QList<SequenceStep> &steps, QTreeWidgetItem *parent)
{
    for (const SequenceStep &s : steps) {
        auto *item = parent ? new QTreeWidgetItem(parent) : new QTreeWidgetItem(m_tree);
        item->setText(0, s.describe());
        item->setData(0, kPathRole, s.path);
        addItems(s.steps, item);
    }
}

void SequenceEditor::onSelected()
{
    if (m_rebuilding)
        return;
    if (const SequenceStep *s = stepAt(selectedPath()))
        m_form->setStep(*s, m_points);
    else
        m_form->clear();
    m_form->setEnabled(m_editable && m_form->hasStep());
    setProblems(m_problems);
    updateButtons();
}

void SequenceEditor::onEdited()
{
    SequenceStep *s = stepAt(selectedPath());
    if (!s)
        return;
    const SequenceStep edited = m_form->step();
    const QList<SequenceStep> inner = s->steps;
    *s = edited;
    // A loop keeps what it holds; a step that is no loop any more holds nothing.
    s->steps = s->kind == StepKind::Repeat ? inner : QList<SequenceStep>();
    const bool shapeChanged = inner.size() != s->steps.size();
    if (QTreeWidgetItem *item = m_tree->currentItem())
        item->setText(0, s->describe());
    if (shapeChanged)
        rebuild(selectedPath());
    updateButtons();
    Q_EMIT changed();
}

void SequenceEditor::updateButtons()
{
    int i = 0;
    QList<SequenceStep> *list = listOf(selectedPath(), &i);
    const bool any = list != nullptr && m_editable;
    m_add->setEnabled(m_editable);
    m_remove->setEnabled(any);
    m_up->setEnabled(any && i > 0);
    m_down->setEnabled(any && i + 1 < list->size());
    m_in->setEnabled(any && i > 0 && (*list)[i - 1].kind == StepKind::Repeat);
    m_out->setEnabled(any && selectedPath().contains(QLatin1Char('.')));
}

void SequenceEditor::addStep(StepKind kind)
{
    SequenceStep step = SequenceStepForm::defaultStep(kind, m_points);
    int i = 0;
    QList<SequenceStep> *list = listOf(selectedPath(), &i);
    QList<int> at = indexesOf(selectedPath());
    if (list && (*list)[i].kind == StepKind::Repeat && (*list)[i].steps.isEmpty()) {
        (*list)[i].steps.append(step); // an empty loop takes its first step
        at << 0;
    } else if (list) {
        list->insert(i + 1, step);
        at.last() = i + 1;
    } else {
        m_steps.append(step);
        at = {int(m_steps.size()) - 1};
    }
    QStringList parts;
    for (int n : at)
        parts << QStringLiteral("steps[%1]").arg(n);
    commit(parts.join(QLatin1Char('.')));
}

void SequenceEditor::removeSelected()
{
    int i = 0;
    QList<SequenceStep> *list = listOf(selectedPath(), &i);
    if (!list)
        return;
    QString select = selectedPath();
    list->removeAt(i);
    if (list->isEmpty()) {
        const int dot = select.lastIndexOf(QLatin1Char('.'));
        select = dot > 0 ? select.left(dot) : QString();
    } else if (i >= list->size()) {
        select.replace(select.lastIndexOf(QLatin1Char('[')) + 1, QString::number(i).size(),
                       QString::number(i - 1));
    }
    commit(select);
}

void SequenceEditor::moveSelected(int delta)
{
    int i = 0;
    QList<SequenceStep> *list = listOf(selectedPath(), &i);
    if (!list || i + delta < 0 || i + delta >= list->size())
        return;
    list->swapItemsAt(i, i + delta);
    QString select = selectedPath();
    select.replace(select.lastIndexOf(QLatin1Char('[')) + 1, QString::number(i).size(),
                   QString::number(i + delta));
    commit(select);
}

void SequenceEditor::intoLoopAbove()
{
    int i = 0;
    QList<SequenceStep> *list = listOf(selectedPath(), &i);
    if (!list || i == 0 || (*list)[i - 1].kind != StepKind::Repeat)
        return;
    const SequenceStep step = list->takeAt(i);
    SequenceStep &loop = (*list)[i - 1];
    loop.steps.append(step);
    QString parent = selectedPath();
    parent.chop(parent.size() - parent.lastIndexOf(QLatin1Char('[')) - 1);
    commit(QStringLiteral("%1%2].steps[%3]").arg(parent).arg(i - 1).arg(loop.steps.size() - 1));
}

void SequenceEditor::outOfLoop()
{
    const QString path = selectedPath();
    const int dot = path.lastIndexOf(QLatin1Char('.'));
    int i = 0;
    QList<SequenceStep> *list = listOf(path, &i);
    int loopIndex = 0;
    QList<SequenceStep> *outer = listOf(path.left(dot), &loopIndex);
    if (!list || !outer)
        return;
    const SequenceStep step = list->takeAt(i);
    outer->insert(loopIndex + 1, step);
    QString select = path.left(dot);
    select.replace(select.lastIndexOf(QLatin1Char('[')) + 1, QString::number(loopIndex).size(),
                   QString::number(loopIndex + 1));
    commit(select);
}

void SequenceEditor::commit(const QString &select)
{
    renumber(m_steps);
    rebuild(select);
    Q_EMIT changed();
}

void SequenceEditor::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void SequenceEditor::retranslate()
{
    m_add->setText(tr("&Add step"));
    for (QAction *a : m_add->menu()->actions())
        a->setText(SequenceStepForm::kindLabel(StepKind(a->data().toInt())));
    m_remove->setText(tr("&Remove"));
    m_up->setText(tr("Up"));
    m_down->setText(tr("Down"));
    m_in->setText(tr("Into the loop above"));
    m_out->setText(tr("Out of the loop"));
    m_tree->setAccessibleName(tr("Steps"));
    for (QTreeWidgetItemIterator it(m_tree); *it; ++it) {
        if (const SequenceStep *s = stepAt((*it)->data(0, kPathRole).toString()))
            (*it)->setText(0, s->describe());
    }
}

} // namespace stepcom
