#pragma once

// One test program per test area (tests_device, tests_ui, ...) holds that area's QTest suites;
// `tests_device tst_poller [QTest arguments...]` runs the one suite, in a process of its own,
// as the suite's own program (QTEST_MAIN) did before. A suite registers itself under the base
// name of its file with STEPCOM_TEST in place of QTEST_MAIN / QTEST_GUILESS_MAIN:
//
//   #include "testregistry.h"
//   STEPCOM_TEST(TestPoller, Guiless) // was QTEST_GUILESS_MAIN(TestPoller)
//   #include "tst_poller.moc"
//
// Gui creates the application QTEST_MAIN creates in this program: QApplication when it links
// Qt Widgets, QGuiApplication when it links Qt Gui, otherwise QCoreApplication. Guiless creates
// a QCoreApplication, as QTEST_GUILESS_MAIN. tests/support/testmain.cpp is the programs' main().

#include <QByteArray>
#include <QList>
#include <QObject>

#include <memory>

namespace stepcom::test {

enum class TestApp { Gui, Guiless };

struct TestSuite
{
    const char *sourceFile; // __FILE__ of the suite: its name is the base name, "tst_poller"
    TestApp app;
    void (*initMain)(); // the class's static initMain(), called before the application exists
    std::unique_ptr<QObject> (*create)();
};

// Adds a suite to this program; a second suite of the same name ends the program at its start.
bool registerTestSuite(const TestSuite &suite);
// The suite of that name, or null.
const TestSuite *findTestSuite(const char *name);
// Every suite's name, sorted.
QList<QByteArray> testSuiteNames();

template<typename T>
void callInitMain()
{
    if constexpr (requires { T::initMain(); })
        T::initMain();
}

template<typename T>
std::unique_ptr<QObject> createSuite()
{
    return std::make_unique<T>();
}

} // namespace stepcom::test

#define STEPCOM_TEST(TestObject, App)                                                              \
    namespace {                                                                                    \
    [[maybe_unused]] const bool stepcomTestRegistered##TestObject =                                \
        ::stepcom::test::registerTestSuite({__FILE__, ::stepcom::test::TestApp::App,               \
                                            &::stepcom::test::callInitMain<TestObject>,            \
                                            &::stepcom::test::createSuite<TestObject>});           \
    }
