#pragma once

#include "sequence/sequencestep.h"

#include <QWidget>

class QLabel;
class QPushButton;
class QToolButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace stepcom {

class RegisterMap;
class SequenceStepForm;

// The steps of a sequence as a list: loops as indented groups, the selected step's fields
// beside it (SequenceStepForm). Add (after the selected step, or into a selected empty loop),
// remove, move up and down, into the loop above and out of a loop. Every edit renumbers the
// steps' paths ("steps[1].steps[0]") as the file would have them and says changed(); the page
// judges the whole and hands back the problems, which mark their steps here.
class SequenceEditor : public QWidget
{
    Q_OBJECT
public:
    SequenceEditor(const RegisterMap &map, QWidget *parent = nullptr);

    void setSteps(const QList<SequenceStep> &steps);
    const QList<SequenceStep> &steps() const { return m_steps; }
    // The names a move_to may use (the page's points).
    void setPointNames(const QStringList &names);
    // A point was renamed: the steps that moved to it move to the new name.
    void renamePoint(const QString &from, const QString &to);
    // Problems of the file's checks ("FILE: steps[1]: ..."): the steps they name are marked.
    void setProblems(const QStringList &problems);
    // The step running (its path), shown in bold and selected; empty: none.
    void setCurrent(const QString &path);
    QString current() const { return m_current; }
    // While a run goes on nothing may be edited.
    void setEditable(bool editable);

    QTreeWidget *tree() const { return m_tree; }
    SequenceStepForm *form() const { return m_form; }
    QToolButton *addButton() const { return m_add; }
    QPushButton *removeButton() const { return m_remove; }
    QPushButton *upButton() const { return m_up; }
    QPushButton *downButton() const { return m_down; }
    QPushButton *inButton() const { return m_in; }
    QPushButton *outButton() const { return m_out; }
    // The path of the selected step, or empty.
    QString selectedPath() const;
    void selectPath(const QString &path);
    // Adds a step of `kind` as the add menu does.
    void addStep(SequenceStep::Kind kind);
    QTreeWidgetItem *itemFor(const QString &path) const;

    // Each step's path, renumbered from its place ("steps[i]", "….steps[j]").
    static void renumber(QList<SequenceStep> &steps, const QString &parent = QString());

Q_SIGNALS:
    void changed();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void rebuild(const QString &select);
    void addItems(const QList<SequenceStep> &steps, QTreeWidgetItem *parent);
    void onSelected();
    void onEdited();
    void updateButtons();
    // The list holding the step at `path` and its index there; nullptr when none.
    QList<SequenceStep> *listOf(const QString &path, int *index);
    SequenceStep *stepAt(const QString &path);
    void moveSelected(int delta);
    void intoLoopAbove();
    void outOfLoop();
    void removeSelected();
    void commit(const QString &select);

    const RegisterMap &m_map;
    QList<SequenceStep> m_steps;
    QStringList m_points;
    QStringList m_problems;
    QString m_current;
    bool m_editable = true;
    QTreeWidget *m_tree;
    SequenceStepForm *m_form;
    QToolButton *m_add;
    QPushButton *m_remove;
    QPushButton *m_up;
    QPushButton *m_down;
    QPushButton *m_in;
    QPushButton *m_out;
    QLabel *m_hint;
    bool m_rebuilding = false;
};

} // namespace stepcom
