#pragma once

#include "motion/motorderived.h"

#include <QList>
#include <QWidget>

class QFormLayout;
class QLabel;

namespace stepcom {

// A read-only panel of the values derived from one motor's parameters, with units; "—" for
// whatever is unknown or zero. The numbers come from core (motorderived.h), never from here.
class DerivedValues : public QWidget
{
    Q_OBJECT
public:
    enum class Row {
        PulsesPerRev,
        PulseRate,
        SpeedPerSecond,
        SpeedPerMinute,
        RevolutionsPerMove,
        PulsesPerMove,
        Ramp,
        MoveTime
    };

    explicit DerivedValues(QWidget *parent = nullptr);

    // `unit` is the distance unit of the pitch ("mm").
    void setValues(const MotorDerived &values, const QString &unit);
    const MotorDerived &values() const { return m_values; }
    // What a row shows, as the technician reads it ("1600 pulses/rev").
    QString text(Row row) const;

    // "1500", "2.5", "0.125": at most `decimals` decimals, no trailing zeros.
    static QString number(double value, int decimals);
    static QString duration(double ms);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void refresh();

    QFormLayout *m_layout;
    QList<QLabel *> m_names;
    QList<QLabel *> m_texts;
    MotorDerived m_values;
    QString m_unit;
};

} // namespace stepcom
