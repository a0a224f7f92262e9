// main() of the test programs (tests_device, tests_ui, ...): runs the one suite named by the
// first argument in this process, with the remaining arguments going to QTest::qExec, as the
// suite's own QTEST_MAIN / QTEST_GUILESS_MAIN program did (testregistry.h). Compiled into every
// test program, so QT_WIDGETS_LIB / QT_GUI_LIB are the program's, as for QTEST_MAIN.
#include "testregistry.h"

#include <QCoreApplication>
#include <QTest>
#if defined(QT_WIDGETS_LIB)
#include <QApplication>
#elif defined(QT_GUI_LIB)
#include <QGuiApplication>
#endif

#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace {

int usage(const char *program, const char *problem)
{
    if (problem)
        std::fprintf(stderr, "%s: %s\n", program, problem);
    std::fprintf(stderr,
                 "usage: %s SUITE [QTest arguments: -v2, a test function, ...]\nsuites:", program);
    for (const QByteArray &name : stepcom::test::testSuiteNames())
        std::fprintf(stderr, " %s", name.constData());
    std::fprintf(stderr, "\n");
    return 2;
}

// The application QTEST_MAIN (Gui) or QTEST_GUILESS_MAIN (Guiless) creates in this program.
std::unique_ptr<QCoreApplication> makeApplication(stepcom::test::TestApp kind, int &argc,
                                                  char **argv)
{
    std::unique_ptr<QCoreApplication> app;
    if (kind == stepcom::test::TestApp::Gui) {
#if defined(QT_WIDGETS_LIB)
        app = std::make_unique<QApplication>(argc, argv);
#elif defined(QT_GUI_LIB)
        app = std::make_unique<QGuiApplication>(argc, argv);
#endif
    }
    if (!app)
        app = std::make_unique<QCoreApplication>(argc, argv);
    QCoreApplication::setAttribute(Qt::AA_Use96Dpi, true);
#if defined(QT_WIDGETS_LIB) && defined(QT_KEYPAD_NAVIGATION)
    if (kind == stepcom::test::TestApp::Gui)
        QApplication::setNavigationMode(Qt::NavigationModeNone);
#endif
    return app;
}

} // namespace

int main(int argc, char *argv[])
{
    if (argc < 2)
        return usage(argv[0], "no suite given");
    const stepcom::test::TestSuite *suite = stepcom::test::findTestSuite(argv[1]);
    if (!suite) {
        const std::string problem = std::string("no suite ") + argv[1];
        return usage(argv[0], problem.c_str());
    }

    // The suite sees itself started as its own program: argv[0] ends in the suite's name
    // (the application name, and so QSettings' and QStandardPaths' names, are the suite's, as
    // when each suite was a program of its own), followed by the QTest arguments.
    std::string program = argv[0];
    const std::size_t slash = program.rfind('/');
    program = (slash == std::string::npos ? std::string() : program.substr(0, slash + 1)) + argv[1];
    std::vector<char *> args{program.data()};
    for (int i = 2; i < argc; ++i)
        args.push_back(argv[i]);
    args.push_back(nullptr);
    int qtestArgc = int(args.size()) - 1;
    char **qtestArgv = args.data();

    suite->initMain();
    const std::unique_ptr<QCoreApplication> app = makeApplication(suite->app, qtestArgc, qtestArgv);
    const std::unique_ptr<QObject> testObject = suite->create();
#ifdef QT_TESTCASE_BUILDDIR
    QTest::setMainSourcePath(suite->sourceFile, QT_TESTCASE_BUILDDIR);
#else
    QTest::setMainSourcePath(suite->sourceFile);
#endif
    return QTest::qExec(testObject.get(), qtestArgc, qtestArgv);
}
