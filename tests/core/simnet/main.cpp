// Test runner for the simulated station's network side: one QCoreApplication whose event loop the tests
// run while they wait for sockets.

#include <QCoreApplication>
#include <gtest/gtest.h>

int main(int argc, char* argv[]) {
    ::testing::InitGoogleTest(&argc, argv);
    QCoreApplication app(argc, argv);
    return RUN_ALL_TESTS();
}
