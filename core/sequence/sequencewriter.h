#pragma once

#include "sequence/sequence.h"

#include <QByteArray>
#include <QJsonObject>

namespace stepcom {

class RegisterMap;

// Writes a Sequence back as the .stepseq JSON SequenceParser reads (docs/sequence.md), so a file
// the window saves reloads to the same sequence. `map` gives the limits' units.
class SequenceWriter
{
public:
    static QJsonObject toJson(const Sequence &sequence, const RegisterMap &map);
    static QByteArray write(const Sequence &sequence, const RegisterMap &map);
};

} // namespace stepcom
