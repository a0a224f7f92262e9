#pragma once

#include <QCoreApplication>
#include <QDate>
#include <QHash>
#include <QString>

namespace stepcom {

class RegisterMap;

// Every device of a line saved into one folder, one profile file per device: the file names
// start with the id, so the folder lists the line in order, then the device's name and the
// date ("id2 Y axis 2026-11-25.json"). Each file is written whole or not at all (a temporary
// file renamed into place), so a folder never holds a half-written profile.
class BusDump
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::BusDump)
public:
    static QString fileName(int id, const QString &name, const QDate &date);
    // Empty when `directory` exists and can be written to, else why not.
    static QString checkDirectory(const QString &directory);

    struct Saved
    {
        QString path;
        QString error; // empty on success
        bool ok() const { return error.isEmpty(); }
    };
    // `values` as read from device `id` (link settings included) saved into `directory`;
    // `fromSimulator`: read from the built-in simulator (the file records it).
    static Saved save(const QString &directory, const RegisterMap &map, int id, const QString &name,
                      const QString &notes, const QHash<QString, qint64> &values, const QDate &date,
                      bool fromSimulator = false);
};

} // namespace stepcom
