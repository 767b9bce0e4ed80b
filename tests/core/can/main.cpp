// Test runner for the transports: one QCoreApplication, whose event loop the tests run while they wait.

#include <QCoreApplication>
#include <QLoggingCategory>
#include <gtest/gtest.h>

int main(int argc, char* argv[]) {
    ::testing::InitGoogleTest(&argc, argv);
    QCoreApplication app(argc, argv);
    // The virtualcan relay reports every client that comes and goes.
    QLoggingCategory::setFilterRules(QStringLiteral("qt.canbus.plugins.virtualcan.info=false"));
    return RUN_ALL_TESTS();
}
