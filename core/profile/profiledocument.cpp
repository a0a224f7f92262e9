#include "profile/profiledocument.h"

#include "map/factoryvalues.h"
#include "profile/profilefile.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"

#include <QFileInfo>

namespace stepcom {

ProfileDocument::ProfileDocument(DeviceSession *session, QObject *parent)
    : QObject(parent)
    , m_session(session)
{
    // The session emits `connected` before it reads the controller: the file's values and the
    // edits are taken here, before a read could land in the store.
    connect(session->connection(), &SessionConnection::connected, this, [this](bool ok) {
        if (!ok || !m_open)
            return;
        const Profile values = current();
        const QString path = m_path;
        const int edits = int(m_session->parameters()->store()->editedKeys().size());
        close();
        Q_EMIT leftForController(values, path, edits);
    });
    connect(session->parameters()->store(), &ParameterStore::editsChanged, this, [this] {
        if (m_open)
            Q_EMIT changed();
    });
}

QString ProfileDocument::displayName() const
{
    return m_path.isEmpty() ? tr("new profile") : QFileInfo(m_path).fileName();
}

bool ProfileDocument::isModified() const
{
    return m_open && m_session->parameters()->store()->hasEdits();
}

QStringList ProfileDocument::varianceLines(const QString &locale) const
{
    if (!m_open)
        return {};
    const ProfileVariance variance = current().variance;
    QStringList lines;
    if (const QString maps = variance.describeMaps(); !maps.isEmpty())
        lines << maps;
    return lines + variance.describe(m_session->map(), locale);
}

QStringList ProfileDocument::open(const QString &path)
{
    if (m_session->connection()->linkState() != SessionConnection::LinkState::Disconnected)
        return {tr("a controller is connected: open the profile to compare it instead")};
    const ProfileParseResult r =
        ProfileFile::load(path, m_session->map(), ProfileFile::OtherMaps::Accept);
    if (!r.ok())
        return r.errors;
    start(*r.profile, path);
    return {};
}

QStringList ProfileDocument::newFromFactory()
{
    if (m_session->connection()->linkState() != SessionConnection::LinkState::Disconnected)
        return {tr("a controller is connected: disconnect to edit a profile without it")};
    Profile profile =
        Profile::fromValues(m_session->map(), FactoryValues::writable(m_session->map()), false);
    profile.name = tr("Factory values");
    start(profile, QString());
    return {};
}

void ProfileDocument::start(const Profile &profile, const QString &path)
{
    m_profile = profile;
    m_path = path;
    m_open = true;
    QHash<QString, qint64> values;
    for (auto it = profile.values.cbegin(); it != profile.values.cend(); ++it)
        values.insert(it.key(), it.value());
    m_session->parameters()->store()->openFile(displayName(), values);
    Q_EMIT changed();
}

Profile ProfileDocument::current() const
{
    Profile out = m_profile;
    const ParameterStore *store = m_session->parameters()->store();
    for (const Parameter *p : Profile::profileParameters(m_session->map(), true)) {
        const auto shown = store->shownValue(p->key);
        if (!shown)
            continue;
        out.values.insert(p->key, *shown);
        // Set by the user now: no longer left out of the profile.
        out.variance.missing.removeAll(p->key);
        out.variance.rejected.removeIf([&](const ProfileNote &n) { return n.key == p->key; });
    }
    return out;
}

QString ProfileDocument::save(const QString &path, QStringList *filled)
{
    if (!m_open)
        return tr("no profile is being edited");
    Profile profile = current();
    QStringList filledKeys;
    for (const QString &key : std::as_const(profile.variance.missing)) {
        if (const Parameter *p = m_session->map().find(key)) {
            profile.values.insert(key, FactoryValues::value(*p));
            filledKeys << key;
        }
    }
    profile.variance.missing.clear();
    if (profile.name.isEmpty())
        profile.name = QFileInfo(path).completeBaseName();
    profile.created = QDateTime::currentDateTimeUtc();
    profile.created.setTime(QTime(profile.created.time().hour(), profile.created.time().minute(),
                                  profile.created.time().second()));
    profile.stepcomVersion = QStringLiteral(STEPCOM_VERSION);
    if (const QString e = ProfileFile::save(path, profile, m_session->map()); !e.isEmpty())
        return e;
    if (filled)
        *filled = filledKeys;
    start(profile, path); // what was saved is now the file's: nothing edited
    return {};
}

void ProfileDocument::close()
{
    if (!m_open)
        return;
    m_open = false;
    m_path.clear();
    m_profile = Profile();
    m_session->parameters()->store()->closeFile();
    Q_EMIT changed();
}

} // namespace stepcom
