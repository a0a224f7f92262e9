// The ordinary (gcc, no libFuzzer) driver of a fuzz target: feeds every file named on the
// command line, or found under a directory named there, to LLVMFuzzerTestOneInput once. A
// property violation aborts, so the ctest fails naming the input it was working on; no input
// at all fails too.

#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QStringList>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int main(int argc, char **argv)
{
    QStringList files;
    for (int i = 1; i < argc; ++i) {
        const QString path = QString::fromLocal8Bit(argv[i]);
        const QFileInfo info(path);
        if (info.isDir()) {
            QDirIterator it(path, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
            while (it.hasNext())
                files << it.next();
        } else if (info.isFile()) {
            files << path;
        } else {
            // A target without regressions yet has no such directory: fine, as long as the
            // corpus gives at least one input (checked below).
            std::fprintf(stderr, "replay: %s: no such file or directory, skipped\n", argv[i]);
        }
    }
    std::sort(files.begin(), files.end());
    if (files.isEmpty()) {
        std::fprintf(stderr, "replay: no inputs (give corpus files or directories)\n");
        return 2;
    }
    for (const QString &path : std::as_const(files)) {
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly)) {
            std::fprintf(stderr, "replay: cannot read %s: %s\n", qPrintable(path),
                         qPrintable(file.errorString()));
            return 2;
        }
        const QByteArray data = file.readAll();
        std::fprintf(stderr, "replay: %s (%lld bytes)\n", qPrintable(path),
                     static_cast<long long>(data.size()));
        std::fflush(stderr);
        // A copy of exactly `size` bytes, so reading past the end is a sanitizer finding.
        std::vector<uint8_t> exact(data.begin(), data.end());
        LLVMFuzzerTestOneInput(exact.data(), exact.size());
    }
    std::printf("replay: %lld input(s), all passed\n", static_cast<long long>(files.size()));
    return 0;
}
