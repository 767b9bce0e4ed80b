// Test runner for the station connection: one QCoreApplication, whose event loop the tests run while they
// wait.

#include <QCoreApplication>
#include <gtest/gtest.h>

int main(int argc, char* argv[]) {
    ::testing::InitGoogleTest(&argc, argv);
    QCoreApplication app(argc, argv);
    return RUN_ALL_TESTS();
}
