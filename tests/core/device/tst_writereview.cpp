#include "device/writereview.h"
#include "map/registermap.h"

#include <QTest>

using namespace stepcom;
using namespace Qt::StringLiterals;

using Values = QHash<QString, qint64>;

// The one review of a write, for the window's dialog and stepcomctl alike: what it asks, and
// that the registers it names (keysRead) are all it needs to ask it.
class TstWriteReview : public QObject
{
    Q_OBJECT
    const RegisterMap &map = RegisterMap::builtin();

    // Limits IN1/IN2 (home IN2) and IN3/IN4 (home IN4), mode 0, an arc round (10, 0) from
    // (0, 0) to (20, 0).
    static QHash<QString, qint64> machine()
    {
        return {{u"motor1.limit_positive"_s, 1}, {u"motor1.limit_negative"_s, 2},
                {u"motor1.home_input"_s, 2},     {u"motor2.limit_positive"_s, 3},
                {u"motor2.limit_negative"_s, 4}, {u"motor2.home_input"_s, 4},
                {u"mode.system"_s, 0},           {u"arc.mode"_s, 0},
                {u"arc.start_x"_s, 0},           {u"arc.start_y"_s, 0},
                {u"arc.end_x"_s, 2000},          {u"arc.end_y"_s, 0},
                {u"arc.center_x"_s, 1000},       {u"arc.center_y"_s, 0},
                {u"arc.middle_x"_s, 0},          {u"arc.middle_y"_s, 0},
                {u"arc.direction"_s, 0},         {u"arc.enabled"_s, 1},
                {u"arc.speed"_s, 100},           {u"motor1.speed"_s, 300}};
    }
    QList<ParameterWrite> writes(const QHash<QString, qint64> &values) const
    {
        QList<ParameterWrite> out;
        for (auto it = values.cbegin(); it != values.cend(); ++it)
            out.append({map.find(it.key()), it.value()});
        return out;
    }
    // The review on what the controller holds: everything, or only what keysRead() names.
    QStringList review(const QList<ParameterWrite> &w, bool onlyKeysRead) const
    {
        QHash<QString, qint64> held = machine();
        if (onlyKeysRead) {
            const QStringList keys = WriteReview::keysRead(map, w);
            for (auto it = held.begin(); it != held.end();)
                it = keys.contains(it.key()) ? std::next(it) : held.erase(it);
        }
        return WriteReview::problems(
            map,
            [held](const QString &key) {
                return held.contains(key) ? std::optional<qint64>(held.value(key)) : std::nullopt;
            },
            w);
    }

private Q_SLOTS:
    void asksWhatTheWindowAsks_data()
    {
        QTest::addColumn<Values>("values");
        QTest::addColumn<QString>("question"); // empty: nothing to ask
        QTest::newRow("home on the positive limit")
            << Values{{u"motor1.home_input"_s, 1}} << u"the home input IN1 is the positive limit"_s;
        QTest::newRow("mode 4") << Values{{u"mode.system"_s, 4}}
                                << u"System mode 4 “Hold-to-jog” changes what the inputs IN1-IN4 "
                                   "do, at once, and ignores the limit settings"_s;
        QTest::newRow("mode 1") << Values{{u"mode.system"_s, 1}} << u"System mode 1"_s;
        QTest::newRow("mode kept") << Values{{u"mode.system"_s, 0}} << QString();
        QTest::newRow("arc starting at its centre")
            << Values{{u"arc.start_x"_s, 1000}, {u"arc.start_y"_s, 0}} << u"Arc: "_s;
        QTest::newRow("a speed") << Values{{u"motor1.speed"_s, 250}} << QString();
        QTest::newRow("home on the negative limit")
            << Values{{u"motor1.home_input"_s, 2}} << QString();
    }
    void asksWhatTheWindowAsks()
    {
        QFETCH(Values, values);
        QFETCH(QString, question);
        const QList<ParameterWrite> w = writes(values);
        const QStringList all = review(w, false);
        if (question.isEmpty())
            QVERIFY2(all.isEmpty(), qPrintable(all.join(u'\n')));
        else
            QVERIFY2(all.join(u'\n').contains(question), qPrintable(all.join(u'\n')));
        // Read only what keysRead() names: the same questions.
        QCOMPARE(review(w, true), all);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstWriteReview, Guiless)
#include "tst_writereview.moc"
