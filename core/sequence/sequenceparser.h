#pragma once

#include "sequence/sequence.h"

#include <QCoreApplication>
#include <QJsonObject>
#include <QStringList>

#include <optional>

namespace stepcom {

class RegisterMap;

// Reads a .stepseq file (docs/sequence.md) with QJsonDocument into a Sequence, refusing it whole
// on the first sight of anything wrong with the file itself: invalid JSON (line and column), a
// wrong format or version, an unknown key, a wrong type, an unknown point, a motor, input or
// output this controller's map has not, a position the axis cannot count. Every message names
// the file and where ("FILE: steps[1].steps[0]: ..."). What needs the positions through the steps
// (limits, references) is SequenceCheck's.
class SequenceParser
{
public:
    Q_DECLARE_TR_FUNCTIONS(stepcom::SequenceParser)
public:
    static constexpr int kVersion = 1;
    static std::optional<Sequence> parse(const QByteArray &json, const QString &fileName,
                                         const RegisterMap &map, QStringList *errors);
    // Reads the file, then parse(); a file that cannot be read is said so.
    static std::optional<Sequence> load(const QString &path, const RegisterMap &map,
                                        QStringList *errors);
    // "line 3, column 7" of a byte offset in `json`.
    static QString lineColumn(const QByteArray &json, int offset);
};

} // namespace stepcom
