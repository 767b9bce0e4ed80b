#pragma once

// The real stellwerk-sim program (its path in STELLWERK_SIM) run by a test: started with arguments, its
// output collected, its TCP port read from what it prints, stopped when the test ends.

#include "EventLoopWait.h"

#include <QProcess>
#include <QRegularExpression>
#include <QStringList>
#include <csignal>
#include <cstdint>
#include <sys/types.h>

namespace stellwerk::support {

// stellwerk-sim on free loopback ports, without trains; its output collected.
class SimProgram {
public:
    explicit SimProgram(const QStringList& arguments) {
        process_.setProcessChannelMode(QProcess::MergedChannels);
        process_.start(QStringLiteral(STELLWERK_SIM), arguments);
    }
    ~SimProgram() {
        if (process_.state() != QProcess::NotRunning) {
            wake(); // a stopped process cannot end
            process_.terminate();
            process_.waitForFinished(5000);
        }
    }
    QString output() {
        out_ += QString::fromUtf8(process_.readAll());
        return out_;
    }
    bool printed(const QString& text) {
        return runEventsUntil([&] { return output().contains(text); }, 15000);
    }
    int exitCode() {
        process_.waitForFinished(5000);
        output();
        return process_.exitCode();
    }
    // Stalls the program as a frozen station does: it stops reading and answering without closing
    // anything (SIGSTOP); wake() lets it go on, and it reads everything that arrived meanwhile at once.
    bool stall() { return sendSignal(SIGSTOP); }
    bool wake() { return sendSignal(SIGCONT); }
    // The port of a listener the program printed ("udp" or "tcp"), 0 when it printed none in time.
    std::uint16_t port(const QString& kind) {
        const QRegularExpression listening(QStringLiteral("listening: %1 127\\.0\\.0\\.1:(\\d+)").arg(kind));
        QRegularExpressionMatch match;
        runEventsUntil([&] { return (match = listening.match(output())).hasMatch(); }, 15000);
        return match.hasMatch() ? std::uint16_t(match.captured(1).toUInt()) : 0;
    }
    std::uint16_t tcpPort() { return port(QStringLiteral("tcp")); }

private:
    bool sendSignal(int number) {
        const qint64 pid = process_.processId();
        return pid > 0 && ::kill(pid_t(pid), number) == 0;
    }

    QProcess process_;
    QString out_;
};

inline const QStringList Quiet = {"--listen",         "127.0.0.1", "--udp-port", "0",
                                  "--udp-reply-host", "127.0.0.1", "--tcp-port", "0",
                                  "--http-port",      "0",         "--no-trains"};

} // namespace stellwerk::support
