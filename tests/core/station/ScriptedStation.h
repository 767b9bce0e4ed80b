#pragma once

// A small scripted CS2 for the station tests: the far end of a loopback pair that answers the way the
// document says (acknowledgement = the command with the response bit; ping with its identity; files as
// 0x21 streams; status data as packets and an end frame), and can be told to stay silent.

#include "can/FrameText.h"
#include "cs2/Codec.h"
#include "cs2/Hash.h"
#include "cs2config/ConfigStreamSender.h"
#include "station/StationSession.h"
#include "transport/LoopbackTransport.h"

#include <QTest>
#include <functional>
#include <gtest/gtest.h>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <vector>

namespace stellwerk::cs2 {
inline void PrintTo(const CanFrame& frame, std::ostream* out) {
    *out << formatDocument(frame);
}
} // namespace stellwerk::cs2

namespace stellwerk::station::test {

using can::CanFrame;
using namespace std::chrono_literals;

// Long enough for a loaded two-core machine; waits end as soon as the condition holds.
inline constexpr int WaitMs = 5000;

inline bool waitFor(const std::function<bool()>& condition, int timeoutMs = WaitMs) {
    return QTest::qWaitFor(condition, timeoutMs);
}

inline CanFrame frame(std::uint8_t command, bool response, std::uint16_t hash,
                      std::initializer_list<std::uint8_t> data) {
    CanFrame result;
    result.id = cs2::makeId(0, command, response, hash);
    result.dlc = std::uint8_t(data.size());
    std::copy(data.begin(), data.end(), result.data.begin());
    return result;
}

inline CanFrame asAnswer(CanFrame frame, std::uint16_t hash) {
    frame.id = cs2::makeId(cs2::prio(frame), cs2::command(frame), true, hash);
    return frame;
}

// The scripted station: Gleisbox 60113 identity by default.
class ScriptedStation {
public:
    static constexpr std::uint32_t Uid = 0x4743F5DA;
    static constexpr std::uint16_t Hash = 0x9719;

    ScriptedStation() {
        QObject::connect(&end, &transport::Transport::framesReceived, &context_,
                         [this](const std::vector<CanFrame>& frames) {
                             for (const auto& f : frames)
                                 handle(f);
                         });
    }

    // Frames that arrive here and what to answer; the default answers per the document.
    std::function<std::vector<CanFrame>(const CanFrame&)> script;
    bool silent = false;
    int dropFirst = 0; // requests to ignore before answering (to exercise retries)
    std::vector<CanFrame> received;
    std::map<std::string, std::string> files;                                               // key -> contents
    std::map<std::pair<std::uint32_t, std::uint8_t>, std::vector<std::uint8_t>> statusData; // (uid, index)
    std::vector<cs2::DeviceIdentity> devices{{Uid, 1, 0x27, 0x0010}};

    std::size_t count(cs2::Command command) const {
        std::size_t n = 0;
        for (const auto& f : received)
            n += cs2::command(f) == std::uint8_t(command) && !cs2::isResponse(f);
        return n;
    }

    void sendToApp(const std::vector<CanFrame>& frames) { end.sendBatch(frames); }

    transport::LoopbackTransport end{QStringLiteral("station")};

private:
    void handle(const CanFrame& f) {
        if (cs2::isResponse(f))
            return;
        received.push_back(f);
        if (silent)
            return;
        if (dropFirst > 0) {
            --dropFirst;
            return;
        }
        sendToApp(script ? script(f) : documentAnswer(f));
    }

    std::vector<CanFrame> documentAnswer(const CanFrame& f) const {
        switch (cs2::Command(cs2::command(f))) {
        case cs2::Command::Ping:
            return pingAnswers();
        case cs2::Command::ConfigDataRequest:
            return fileAnswer(f);
        case cs2::Command::StatusDataConfig:
            return statusAnswer(f);
        case cs2::Command::S88Event:
            return {frame(0x11, true, Hash, {f.data[0], f.data[1], f.data[2], f.data[3], 1, 0, 0, 0})};
        case cs2::Command::LocoSpeed:
            if (f.dlc == 4) // query: answer in the form "set speed"
                return {frame(0x04, true, Hash, {f.data[0], f.data[1], f.data[2], f.data[3], 0x01, 0x2C})};
            return {asAnswer(f, Hash)};
        case cs2::Command::LocoDirection:
            if (f.dlc == 4)
                return {frame(0x05, true, Hash, {f.data[0], f.data[1], f.data[2], f.data[3], 1})};
            return {asAnswer(f, Hash)};
        case cs2::Command::LocoFunction:
            if (f.dlc == 5)
                return {frame(0x06, true, Hash, {f.data[0], f.data[1], f.data[2], f.data[3], f.data[4], 0})};
            return {asAnswer(f, Hash)};
        default:
            return {asAnswer(f, Hash)};
        }
    }

    std::vector<CanFrame> pingAnswers() const {
        std::vector<CanFrame> answers;
        for (const auto& d : devices)
            answers.push_back(
                frame(0x18, true, cs2::hashFromUid(d.uid),
                      {std::uint8_t(d.uid >> 24), std::uint8_t(d.uid >> 16), std::uint8_t(d.uid >> 8),
                       std::uint8_t(d.uid), d.versionMajor, d.versionMinor, std::uint8_t(d.deviceType >> 8),
                       std::uint8_t(d.deviceType)}));
        return answers;
    }

    std::vector<CanFrame> fileAnswer(const CanFrame& f) const {
        const std::string key(reinterpret_cast<const char*>(f.data.data()),
                              std::find(f.data.begin(), f.data.end(), 0) - f.data.begin());
        const auto it = files.find(key);
        if (it == files.end()) // the station acknowledges but has no such file: no stream follows
            return {asAnswer(f, Hash)};
        return cs2config::answerFrames(*cs2config::ConfigRequest::forKey(key), it->second, cs2::hash(f));
    }

    std::vector<CanFrame> statusAnswer(const CanFrame& f) const {
        const std::uint32_t uid =
            std::uint32_t(f.data[0]) << 24 | f.data[1] << 16 | f.data[2] << 8 | f.data[3];
        const auto it = statusData.find({uid, f.data[4]});
        if (it == statusData.end())
            return {};
        std::vector<CanFrame> answer;
        const auto& bytes = it->second;
        std::uint16_t packets = 0;
        for (std::size_t at = 0; at < bytes.size(); at += 8) {
            CanFrame packet = frame(0x1D, true, cs2::hashFromPacketNumber(++packets), {});
            packet.dlc = 8; // zero padded, as real devices send
            std::copy(bytes.begin() + long(at), bytes.begin() + long(std::min(at + 8, bytes.size())),
                      packet.data.begin());
            answer.push_back(packet);
        }
        answer.push_back(
            frame(0x1D, true, cs2::hashFromUid(uid),
                  {f.data[0], f.data[1], f.data[2], f.data[3], f.data[4], std::uint8_t(packets)}));
        return answer;
    }

    QObject context_;
};

// The application end with a session, joined to a scripted station; both ends open.
struct Bench {
    explicit Bench(StationSettings settings = fastSettings()) : session(bus, settings) {
        transport::LoopbackTransport::join(app, station.end);
        app.open();
        station.end.open();
    }

    static StationSettings fastSettings() {
        StationSettings settings;
        settings.uid = 0x53545700; // "STW\0"
        settings.commands = {40ms, 2};
        settings.liveness = {50ms, 3};
        settings.streamIdle = 1000ms;
        return settings;
    }

    transport::LoopbackTransport app{QStringLiteral("app")};
    bus::Bus bus{app, busreading::BusProfile::centralStation()};
    ScriptedStation station;
    StationSession session;
};

// Records the session's batched updates.
struct UpdateLog {
    explicit UpdateLog(StationSession& session) {
        QObject::connect(&session, &StationSession::updated, &context,
                         [this](const StationUpdates& u) { batches.push_back(u); });
    }
    std::vector<StationUpdates> batches;
    QObject context;
};

} // namespace stellwerk::station::test
