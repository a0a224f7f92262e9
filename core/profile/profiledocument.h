#pragma once

#include "profile/profile.h"

#include <QObject>
#include <QStringList>

namespace stepcom {

class DeviceSession;

// A profile file edited without a controller. While one is open the session's ParameterStore
// holds the file's values where the controller's would be and the user's changes as edits, so
// every page edits the file with its usual validation, units and derived values. Saving
// writes the file's values with the edits (atomically). Connecting to a controller ends the
// editing: the values (edits included) are handed on, for the usual compare and apply.
class ProfileDocument : public QObject
{
    Q_OBJECT
public:
    explicit ProfileDocument(DeviceSession *session, QObject *parent = nullptr);

    bool isOpen() const { return m_open; }
    // Empty for a new profile that was never saved.
    QString path() const { return m_path; }
    // The file's name, or "new profile" before the first save.
    QString displayName() const;
    // The profile as opened or last saved.
    const Profile &profile() const { return m_profile; }
    // Edits not saved yet.
    bool isModified() const;
    // What of the file this map cannot take or the file lacks, one line each (empty for a
    // profile of this very map): the maps, then unknown, rejected and missing keys.
    QStringList varianceLines(const QString &locale) const;

    // Read a profile (another map's too) and edit it; on failure the errors, nothing changed.
    // Only while no controller is connected.
    QStringList open(const QString &path);
    // A new profile holding the factory values (FactoryValues), not saved yet.
    QStringList newFromFactory();
    // The values as the pages show them: the file's, with the edits; the variance shrinks
    // by what the user has set.
    Profile current() const;
    // Save current() to `path` (atomic). The settings the profile still lacks (a variant
    // profile) are filled with factory values first; `filled` lists them. Empty on success.
    QString save(const QString &path, QStringList *filled = nullptr);
    // Stop editing; the store forgets the file and its edits.
    void close();

Q_SIGNALS:
    // Opened, saved, renamed, edited, closed: titles and banners follow.
    void changed();
    // A controller connected while a file was open: its values (edits included), its path and
    // how many edits were not saved. The document is closed.
    void leftForController(const stepcom::Profile &values, const QString &path, int unsavedEdits);

private:
    void start(const Profile &profile, const QString &path);

    DeviceSession *m_session;
    Profile m_profile;
    QString m_path;
    bool m_open = false;
};

} // namespace stepcom
