#pragma once

#include <QWidget>

#include <array>

class QComboBox;
class QLabel;

namespace stepcom {

class ParameterStore;
struct Parameter;
struct ParameterWrite;

// The homing order (homing.first, homing.second: none, motor 1, motor 2 ...) as two choices.
// A choice goes to the store as an edit like any other; a motor chosen twice is refused with
// a message, so the order never holds a duplicate.
class HomingOrderEditor : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kSlots = 2;

    explicit HomingOrderEditor(ParameterStore *store, QWidget *parent = nullptr);

    bool isValid() const { return m_params[0] && m_params[1]; }
    QComboBox *combo(int slot) const { return m_combos.at(slot); }
    QLabel *label(int slot) const { return m_labels.at(slot); }
    QString key(int slot) const;
    // What a user does: pick `value` (0 none, n motor n) for a slot. False, with rejected(),
    // when the other slot already holds that motor.
    bool choose(int slot, qint64 value);
    // The edited slots: what "Apply order" writes (through the window's WriteFlow).
    QList<ParameterWrite> pendingWrites() const;
    bool isEdited() const;
    // Both slots read from the controller.
    bool isKnown() const;
    // The order the controller holds, in words ("Motor 1, then Motor 2"); empty while unknown.
    QString deviceOrderText() const;
    void retranslate();

Q_SIGNALS:
    void rejected(const QString &why);

protected:
    void changeEvent(QEvent *event) override;

private:
    void refresh();
    QString slotName(int slot) const;
    QString valueText(int slot, qint64 value) const;

    ParameterStore *m_store;
    std::array<const Parameter *, kSlots> m_params{};
    std::array<QComboBox *, kSlots> m_combos{};
    std::array<QLabel *, kSlots> m_labels{};
    std::array<QLabel *, kSlots> m_states{};
};

} // namespace stepcom
