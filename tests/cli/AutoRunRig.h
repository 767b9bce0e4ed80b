#pragma once

// `stellwerk-cli auto run` against the real stellwerk-sim, with what a fault test needs around them: the
// simulator on free loopback ports (its referee at GET /accidents), the command line as a process whose
// JSON lines are read as they come, and a neighbour on the bus (a second TCP connection to the simulator,
// as another control program or a second Central Station holds one) that hears every frame and sends its
// own.

#include "CliApplication.h"
#include "SimProgram.h"
#include "cs2/Codec.h"
#include "transport/FrameAssembler.h"
#include "transport/NetworkFraming.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTcpServer>
#include <QTcpSocket>
#include <csignal>
#include <functional>
#include <vector>

namespace stellwerk::cli::test {

inline std::uint16_t freePort() {
    QTcpServer server;
    server.listen(QHostAddress::LocalHost, 0);
    return server.serverPort();
}

// The simulator's referee: its accident counters ("total", per kind), empty when it did not answer.
inline QJsonObject accidentsOn(std::uint16_t httpPort) {
    QTcpSocket socket;
    socket.connectToHost(QHostAddress::LocalHost, httpPort);
    if (!socket.waitForConnected(5000))
        return {};
    socket.write("GET /accidents HTTP/1.0\r\n\r\n");
    QByteArray response;
    while (socket.state() == QAbstractSocket::ConnectedState && socket.waitForReadyRead(5000))
        response += socket.readAll();
    response += socket.readAll();
    return QJsonDocument::fromJson(response.mid(response.indexOf("\r\n\r\n") + 4)).object();
}

// A second program on the station's bus: hears every frame the simulator's gateway passes on, sends its own.
class BusNeighbour {
public:
    struct Heard {
        qint64 atMs = 0;
        cs2::Message message;
    };

    bool connectTo(std::uint16_t port) {
        clock_.start();
        QObject::connect(&socket_, &QTcpSocket::readyRead, &socket_, [this] { read(); });
        socket_.connectToHost(QHostAddress::LocalHost, port);
        return support::runEventsUntil([&] { return socket_.state() == QAbstractSocket::ConnectedState; },
                                       5000);
    }
    void send(cs2::MessageBody body, bool response = false) {
        const can::CanFrame frame = cs2::encode(cs2::Message{0, response, 0x2F11, std::move(body)});
        socket_.write(transport::encodeFrames(std::vector{frame}));
    }
    // The speed the station answers for the locomotive (a speed query on the bus), -1 without an answer.
    int stationSpeed(std::uint32_t loco) {
        const std::size_t from = heard_.size();
        send(cs2::LocoSpeed{cs2::LocId(loco), std::nullopt});
        int speed = -1;
        support::runEventsUntil(
            [&] {
                for (std::size_t i = from; i < heard_.size() && speed < 0; ++i)
                    if (const auto* answer = std::get_if<cs2::LocoSpeed>(&heard_[i].message.body);
                        answer && heard_[i].message.response && answer->loco.value() == loco && answer->speed)
                        speed = *answer->speed;
                return speed >= 0;
            },
            3000);
        return speed;
    }
    // Speed commands above 0 for the locomotive (not answers) heard at all.
    int speedsAboveZero(std::uint32_t loco) const {
        int count = 0;
        for (const Heard& heard : heard_)
            count += isSpeed(heard, loco, false, -1);
        return count;
    }
    // Where the frames heard so far end: a mark for speedsAboveZeroAfterStop().
    std::size_t mark() const { return heard_.size(); }
    // Speed commands above 0 for the locomotive (not answers) after the station's first answer of speed 0
    // to it since `mark`: frames reach the station in the order they were sent, so a command sent before
    // the stop and heard here late is not counted, one sent after it is.
    int speedsAboveZeroAfterStop(std::uint32_t loco, std::size_t mark = 0) const {
        std::size_t from = mark;
        while (from < heard_.size() && !isSpeed(heard_[from], loco, true, 0))
            ++from;
        int count = 0;
        for (std::size_t i = from; i < heard_.size(); ++i)
            count += isSpeed(heard_[i], loco, false, -1);
        return count;
    }
    // Every speed frame heard, for a failure's message.
    std::string speedsHeard() const {
        std::string text;
        for (const Heard& heard : heard_)
            if (const auto* speed = std::get_if<cs2::LocoSpeed>(&heard.message.body); speed && speed->speed)
                text += std::to_string(heard.atMs) + " ms: " + std::to_string(speed->loco.value()) +
                        (heard.message.response ? " answer " : " command ") + std::to_string(*speed->speed) +
                        "\n";
        return text;
    }

private:
    // A speed frame for the locomotive: an answer of `speed`, or (answer false) a command above 0.
    static bool isSpeed(const Heard& heard, std::uint32_t loco, bool answer, int speed) {
        const auto* frame = std::get_if<cs2::LocoSpeed>(&heard.message.body);
        if (!frame || !frame->speed || frame->loco.value() != loco || heard.message.response != answer)
            return false;
        return answer ? *frame->speed == speed : *frame->speed > 0;
    }

    void read() {
        std::vector<can::CanFrame> frames;
        assembler_.feed(transport::asBytes(socket_.readAll()), frames);
        for (const can::CanFrame& frame : frames)
            if (const cs2::DecodeResult decoded = cs2::decode(frame))
                heard_.push_back({clock_.elapsed(), *decoded});
    }

    QTcpSocket socket_;
    transport::FrameAssembler assembler_;
    std::vector<Heard> heard_;
    QElapsedTimer clock_;
};

// `stellwerk-cli --station tcp://127.0.0.1:PORT auto run ... --json` as a process; its lines as they come.
class AutoRunProcess {
public:
    void start(std::uint16_t stationPort, const QStringList& arguments) {
        process_.start(STELLWERK_CLI,
                       QStringList{"--station", QStringLiteral("tcp://127.0.0.1:%1").arg(stationPort), "auto",
                                   "run", "--json"} +
                           arguments);
    }
    ~AutoRunProcess() {
        if (process_.state() != QProcess::NotRunning) {
            process_.kill();
            process_.waitForFinished(5000);
        }
    }
    // Until an event line the predicate accepts came (true), or the time is up or the program ended.
    bool waitFor(const std::function<bool(const QJsonObject&)>& accepts, int timeoutMs = 30000) {
        std::size_t looked = 0;
        return support::runEventsUntil(
                   [&] {
                       read();
                       for (; looked < events_.size(); ++looked)
                           if (accepts(events_[looked]))
                               return true;
                       return process_.state() == QProcess::NotRunning && (read(), looked == events_.size());
                   },
                   timeoutMs) &&
               looked < events_.size();
    }
    bool waitForEvent(const QString& kind, const QString& loc = {}, int timeoutMs = 30000) {
        return waitFor([&](const QJsonObject& e) { return isEvent(e, kind, loc); }, timeoutMs);
    }
    static bool isEvent(const QJsonObject& event, const QString& kind, const QString& loc = {}) {
        return event["event"].toString() == kind && (loc.isEmpty() || event["loc"].toString() == loc);
    }
    int count(const QString& kind, const QString& loc = {}) {
        read();
        int n = 0;
        for (const QJsonObject& event : events_)
            n += isEvent(event, kind, loc);
        return n;
    }
    // Ctrl+C: the run ends as at the end of its seconds (every train stopped, a summary).
    void interrupt() { ::kill(pid_t(process_.processId()), SIGINT); }
    // Until the program ended; its exit code, -1 when it did not end in time.
    int ended(int timeoutMs = 20000) {
        support::runEventsUntil([&] { return process_.state() == QProcess::NotRunning; }, timeoutMs);
        read();
        return process_.state() == QProcess::NotRunning ? process_.exitCode() : -1;
    }
    QJsonObject summary() {
        read();
        return !events_.empty() && events_.back()["event"] == "summary" ? events_.back() : QJsonObject{};
    }
    const std::vector<QJsonObject>& events() {
        read();
        return events_;
    }
    std::string log() {
        read();
        return text_.toStdString() + QString::fromUtf8(process_.readAllStandardError()).toStdString();
    }

private:
    void read() {
        text_ += QString::fromUtf8(process_.readAllStandardOutput());
        qsizetype end = 0;
        while ((end = text_.indexOf('\n', parsed_)) >= 0) {
            events_.push_back(QJsonDocument::fromJson(text_.mid(parsed_, end - parsed_).toUtf8()).object());
            parsed_ = end + 1;
        }
    }

    QProcess process_;
    QString text_;
    qsizetype parsed_ = 0;
    std::vector<QJsonObject> events_;
};

} // namespace stellwerk::cli::test
