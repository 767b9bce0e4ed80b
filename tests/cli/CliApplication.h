#pragma once

// The Qt application the CLI tests need for their event loops and processes, made once per test program.

#include <QCoreApplication>

namespace stellwerk::cli::test {

inline void ensureApplication() {
    static int argc = 1;
    static char name[] = "stellwerk-cli-tests";
    static char* argv[] = {name, nullptr};
    if (!QCoreApplication::instance())
        new QCoreApplication(argc, argv);
}

} // namespace stellwerk::cli::test
