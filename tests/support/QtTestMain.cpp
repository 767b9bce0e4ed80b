// Test runner for the test programs that need Qt's event loop (transports, station, simulator, model,
// connection, end to end): one QCoreApplication, whose event loop the tests run while they wait.

#include <QCoreApplication>
#include <QLoggingCategory>
#include <gtest/gtest.h>

int main(int argc, char* argv[]) {
    ::testing::InitGoogleTest(&argc, argv);
    QCoreApplication app(argc, argv);
    // The virtualcan relay reports every client that comes and goes, and the garbage tests make the
    // transports and the station's server log every bad input: keep the test output readable.
    QLoggingCategory::setFilterRules(QStringLiteral("qt.canbus.plugins.virtualcan.info=false\n"
                                                    "stellwerk.*.info=false"));
    return RUN_ALL_TESTS();
}
