#pragma once

#include <QList>
#include <QString>
#include <QVector>

#include <optional>

namespace stepcom {

// A string in the two languages StepCom speaks; `{n}` in block labels is already replaced.
struct LocalizedText
{
    QString en;
    QString zh;
    // The text for a locale name such as "zh_CN" or "en_US"; English when there is no match.
    QString text(const QString &locale = QString()) const;
};

struct EnumValue
{
    qint64 value = 0;
    LocalizedText label;
};

enum class Kind { Holding, Coil };
enum class Access { ReadOnly, ReadWrite, Command };
// What a coil does; decides its priority on the bus and whether it needs an explicit yes.
enum class CommandClass { None, Emergency, Motion, Output, Setting, Destructive };

// One entry of the register map: a holding register (1 or 2 words) or a coil.
// Values travel as "raw" integers (what the wire holds, scale applied); engineering values are
// raw / scale. Text is parsed as an exact decimal so 1.8 becomes 180 without rounding errors.
struct Parameter
{
    QString key;
    Kind kind = Kind::Holding;
    int plc = 0;         // 40001.., or 1.. for coils
    quint16 address = 0; // protocol address
    int words = 1;       // 1 or 2 (holding registers)
    bool isSigned = false;
    int scale = 1; // 1, 10, 100, 1000
    QString unit;
    qint64 rawMin = 0;
    qint64 rawMax = 0;
    QString enumName;
    QList<EnumValue> values; // non-empty: only these raw values are allowed
    Access access = Access::ReadWrite;
    CommandClass command = CommandClass::None;
    QString group;
    int instance = 0; // 1.. for entries of a block (motor 1, motor 2), 0 otherwise
    QString block;    // block prefix ("motor") or empty
    QString localKey; // key within the block ("speed")
    LocalizedText label;
    LocalizedText help;

    bool isHolding() const { return kind == Kind::Holding; }
    bool isCoil() const { return kind == Kind::Coil; }
    bool readable() const { return kind == Kind::Holding; }
    bool writable() const { return kind == Kind::Holding && access == Access::ReadWrite; }
    int decimals() const;
    quint16 lastAddress() const { return quint16(address + (isHolding() ? words : 1) - 1); }
    // "40006 · 0x0005" -- the register as technicians and protocol analysers name it.
    QString registerName() const;

    // The value as shown to people: "1.80" for scale 100, "-12.50", "9600".
    QString formatRaw(qint64 raw) const;
    // formatRaw plus the unit, or the enum label: "1.80 °", "Reverse".
    QString displayRaw(qint64 raw, const QString &locale = QString()) const;
    double toEngineering(qint64 raw) const { return double(raw) / scale; }

    // Parse what a person typed ("1.8", "-3.25", "9600", or an enum label such as "IN2").
    // On failure returns nullopt and a message that names the key and what was wrong.
    std::optional<qint64> parse(const QString &text, QString *error) const;
    // From a JSON number in engineering units; rejects more decimals than the scale holds.
    std::optional<qint64> fromEngineering(double value, QString *error) const;
    // Empty when raw is allowed; otherwise why not ("must be between 0.01 and 360.00 °").
    QString checkRaw(qint64 raw) const;
    QString rangeText() const;

    // Register words as on the wire: low word first for 2-word values.
    QVector<quint16> encode(qint64 raw) const;
    // Inverse of encode(); `words` points at this parameter's first register.
    qint64 decode(const quint16 *wordsIn) const;
};

} // namespace stepcom
