#include "testregistry.h"

#include <QFileInfo>
#include <QMap>

#include <cstdio>
#include <cstdlib>

namespace stepcom::test {

namespace {

QMap<QByteArray, TestSuite> &suites()
{
    static QMap<QByteArray, TestSuite> all;
    return all;
}

QByteArray suiteName(const char *sourceFile)
{
    return QFileInfo(QString::fromLocal8Bit(sourceFile)).completeBaseName().toLocal8Bit();
}

} // namespace

bool registerTestSuite(const TestSuite &suite)
{
    const QByteArray name = suiteName(suite.sourceFile);
    if (suites().contains(name)) {
        std::fprintf(stderr, "test suite %s registered twice (%s and %s)\n", name.constData(),
                     suites().value(name).sourceFile, suite.sourceFile);
        std::abort();
    }
    suites().insert(name, suite);
    return true;
}

const TestSuite *findTestSuite(const char *name)
{
    const auto it = suites().constFind(QByteArray(name));
    return it == suites().cend() ? nullptr : &it.value();
}

QList<QByteArray> testSuiteNames()
{
    return suites().keys();
}

} // namespace stepcom::test
