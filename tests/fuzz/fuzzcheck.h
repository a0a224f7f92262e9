#pragma once

// Shared by every fuzz target: a property that must hold for any input. A violation is a
// crash on purpose (abort), so libFuzzer saves the input and the replay test fails on it.

#include <QByteArray>
#include <QString>

#include <cstdio>
#include <cstdlib>

namespace stepcom::fuzz {

[[noreturn]] inline void fail(const char *what, const QString &detail, const char *file, int line)
{
    std::fprintf(stderr, "%s:%d: fuzz property violated: %s %s\n", file, line, what,
                 qPrintable(detail));
    std::abort();
}

// Arbitrary bytes as a QByteArray without a copy.
inline QByteArray bytes(const unsigned char *data, size_t size)
{
    return QByteArray::fromRawData(reinterpret_cast<const char *>(data), qsizetype(size));
}

} // namespace stepcom::fuzz

#define STEPCOM_FUZZ_CHECK(condition, detail)                                                      \
    do {                                                                                           \
        if (!(condition))                                                                          \
            ::stepcom::fuzz::fail(#condition, (detail), __FILE__, __LINE__);                       \
    } while (false)
