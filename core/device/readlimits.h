#pragma once

#include "device/readplanner.h"

#include <QSet>
#include <QString>

namespace stepcom {

class RegisterMap;

// What one controller refuses to read, learnt from its exception 02 answers: some firmwares
// refuse a read that covers a reserved (unlisted) register, some lack a listed one.
class ReadLimits
{
public:
    enum class Lesson {
        None,         // nothing new: a real refusal, report it
        AlreadyKnown, // the block was planned before a lesson; plan again
        GapsRefused,  // reads may cover listed registers only from now on
        Split,        // a gap-free block was refused: read its parameters one by one to find out
        Unsupported,  // one listed parameter this controller does not have
    };

    bool gapFree() const { return m_gapFree; }
    void setGapFree(bool gapFree) { m_gapFree = gapFree; }
    const QSet<QString> &unsupported() const { return m_unsupported; }
    bool isUnsupported(const QString &key) const { return m_unsupported.contains(key); }
    bool isEmpty() const;
    // For the saved connection settings: "gaps" and the unsupported keys, comma-separated
    // ("gaps,motor2.speed"); what is being narrowed down is not kept. fromText() ignores
    // words it does not know, so a file written by another version never hurts.
    QString toText() const;
    static ReadLimits fromText(const QString &text);

    // May one FC03 cover first..last (0-based addresses) on this controller as far as known?
    bool mayRead(const RegisterMap &map, int first, int last) const;
    // The controller answered exception 02 to this block: learn what that says.
    Lesson learn(const RegisterMap &map, const ReadBlock &block, QString *key = nullptr);

private:
    bool m_gapFree = false;
    QSet<QString> m_unsupported;
    QList<ReadBlock> m_split;
};

} // namespace stepcom
