#pragma once

// The real stellwerk-sim program (its path in STELLWERK_SIM) run by a test: started with arguments, its
// output collected, its TCP port read from what it prints, stopped when the test ends.

#include "EventLoopWait.h"

#include <QProcess>
#include <QRegularExpression>
#include <QStringList>
#include <cstdint>

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
    std::uint16_t tcpPort() {
        const QRegularExpression listening(QStringLiteral("listening: tcp 127\\.0\\.0\\.1:(\\d+)"));
        QRegularExpressionMatch match;
        runEventsUntil([&] { return (match = listening.match(output())).hasMatch(); }, 15000);
        return match.hasMatch() ? std::uint16_t(match.captured(1).toUInt()) : 0;
    }

private:
    QProcess process_;
    QString out_;
};

inline const QStringList Quiet = {"--listen",         "127.0.0.1", "--udp-port", "0",
                                  "--udp-reply-host", "127.0.0.1", "--tcp-port", "0",
                                  "--http-port",      "0",         "--no-trains"};

} // namespace stellwerk::support
