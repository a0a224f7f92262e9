#pragma once

#include <QWidget>

class QFormLayout;
class QLabel;

namespace stepcom {

class ParameterField;
class ParameterStore;

// A column of labelled parameter fields, in the current language, built from map keys.
class ParameterForm : public QWidget
{
    Q_OBJECT
public:
    explicit ParameterForm(ParameterStore *store, QWidget *parent = nullptr);

    ParameterField *addParameter(const QString &key);
    void addRow(QLabel *label, QWidget *field);
    ParameterField *field(const QString &key) const;
    const QList<ParameterField *> &fields() const { return m_fields; }
    QStringList keys() const;
    QFormLayout *formLayout() const { return m_layout; }

Q_SIGNALS:
    void rejected(const QString &why);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    ParameterStore *m_store;
    QFormLayout *m_layout;
    QList<ParameterField *> m_fields;
    QList<QLabel *> m_labels;
};

} // namespace stepcom
