#pragma once

// A master on no bus: the test hands it frames and reads what it sends; a railway that records the intents
// it is given; and a scripted MS1 that logs in the way the chapter-11 trace's MS1 does.

#include "mcan/Codec.h"
#include "mcanhandhelds/HandheldMaster.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace stellwerk::mastertest {

// The railway the handhelds drive, as a record of what they asked for.
class RecordingRailway final : public mcanhandhelds::HandheldRailway {
public:
    std::vector<mcanhandhelds::HandheldLoco> locos;
    std::map<std::uint32_t, mcanhandhelds::LocoDrive> drives;
    std::optional<bool> power = true;
    std::vector<std::string>
        intents; // "speed 0x4006 500", "direction 0x4006 reverse", "function ...", "power off"

    std::vector<mcanhandhelds::HandheldLoco> locomotives() const override { return locos; }
    std::optional<mcanhandhelds::LocoDrive> drive(std::uint32_t locId) const override {
        const auto found = drives.find(locId);
        return found == drives.end() ? std::optional<mcanhandhelds::LocoDrive>(mcanhandhelds::LocoDrive{})
                                     : std::optional(found->second);
    }
    std::optional<bool> powerOn() const override { return power; }
    void setSpeed(std::uint32_t locId, int speed) override {
        drives[locId].speed = speed;
        intents.push_back("speed " + hex(locId) + " " + std::to_string(speed));
    }
    void setDirection(std::uint32_t locId, bool forward) override {
        drives[locId].forward = forward;
        intents.push_back("direction " + hex(locId) + (forward ? " forward" : " reverse"));
    }
    void setFunction(std::uint32_t locId, int function, bool on) override {
        drives[locId].functions =
            on ? drives[locId].functions | (1u << function) : drives[locId].functions & ~(1u << function);
        intents.push_back("function " + hex(locId) + " f" + std::to_string(function) + (on ? " on" : " off"));
    }
    void setPower(bool on) override {
        power = on;
        intents.push_back(on ? "power on" : "power off");
    }
    static std::string hex(std::uint32_t value) {
        char text[16];
        std::snprintf(text, sizeof text, "0x%X", value);
        return text;
    }
};

// A master whose frames go into `sent`.
struct MasterOnTable {
    explicit MasterOnTable(mcanhandhelds::MasterSettings settings = {})
        : master(
              [this](const std::vector<can::CanFrame>& frames) {
                  sent.insert(sent.end(), frames.begin(), frames.end());
              },
              settings) {
        master.setRailway(&railway);
    }
    // Hands the master one frame and returns what it sent in answer.
    std::vector<can::CanFrame> tell(const can::CanFrame& frame) {
        const std::size_t before = sent.size();
        master.receive({frame});
        return {sent.begin() + std::ptrdiff_t(before), sent.end()};
    }
    std::vector<can::CanFrame> tell(const mcan::Message& message) { return tell(mcan::encode(message)); }

    RecordingRailway railway;
    std::vector<can::CanFrame> sent;
    mcanhandhelds::HandheldMaster master;
};

inline std::vector<mcan::Message> decoded(const std::vector<can::CanFrame>& frames,
                                          mcan::HandleRole role = {}) {
    std::vector<mcan::Message> messages;
    for (const can::CanFrame& frame : frames)
        messages.push_back(mcan::decode(frame, role));
    return messages;
}

// Runs the event loop until `done` or `ms` pass.
template <class Done>
bool waitFor(Done done, int ms = 3000) {
    QElapsedTimer clock;
    clock.start();
    while (!done() && clock.elapsed() < ms)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    return done();
}

// An MS1 played by the test: the frames of the trace's slave, with its own UID and name.
class ScriptedMs1 {
public:
    ScriptedMs1(MasterOnTable& table, std::uint32_t uid, std::string name = "KS MS1")
        : table_(table), uid_(uid), name_(std::move(name)) {}

    std::uint8_t node() const { return node_; }
    std::uint8_t mid() const { return mid_; }

    // Stages 0..7 with the MID the master hands out; true when the master granted a node.
    bool logIn() {
        const std::uint8_t bytes[4] = {std::uint8_t(uid_ >> 24), std::uint8_t(uid_ >> 16),
                                       std::uint8_t(uid_ >> 8), std::uint8_t(uid_)};
        for (std::uint8_t stage = 0; stage < 4; ++stage) {
            const auto answers = decoded(
                table_.tell(mcan::LoginRequest{stage, bytes[stage], stage == 0 ? std::uint8_t(0) : mid_}));
            if (answers.empty() || !std::holds_alternative<mcan::LoginReply>(answers.back()))
                return false;
            const auto& reply = std::get<mcan::LoginReply>(answers.back());
            if (reply.uidByte != bytes[stage])
                return false;
            mid_ = reply.mid;
        }
        table_.tell(
            mcan::LoginDetails{4, mid_, {bytes[0], bytes[1], bytes[2], bytes[3], 0x00, 0x02, 0x00, 0x03}});
        table_.tell(mcan::LoginDetails{5, mid_, {0x00, 0x00, 0x00, 0x97, 0x01, 0x00, 0x40, 0x10}});
        table_.tell(mcan::LoginDetails{6, mid_, {0x01, 0x00, 0x00, 0x67, 0x00, 0x00, 0x40, 0x10}});
        for (const mcan::Message& answer : decoded(
                 table_.tell(mcan::LoginDetails{7, mid_, {0x00, 0x00, 0x40, 0x10, 0x01, 0x08, 0x00, 0x10}})))
            if (const auto* grant = std::get_if<mcan::LoginGrant>(&answer)) {
                node_ = grant->node;
                flags_ = grant->flags;
            }
        return node_ != 0;
    }
    std::uint8_t grantFlags() const { return flags_; }

    // The upgrade as the trace's slave runs it, cut short: SD handle, stack size and name, SY handle, the
    // loco list, then the first poll.
    void upgrade() {
        tell(mcan::SdHandleRequest{at(2), node_});
        tell(mcan::StackSizeAnswer{at(8), 10});
        for (std::uint8_t offset = 0; offset < 16; offset += 4) {
            mcan::NameSegment segment{at(8), offset, 4, {}, 0};
            for (std::uint8_t i = 0; i < 4; ++i)
                segment.chars[i] = offset + i < name_.size() ? name_[offset + i] : '\0';
            tell(segment);
        }
        tell(mcan::SyHandleRequest{at(2)});
        poll();
    }
    std::vector<mcan::Message> poll() {
        return decoded(tell(mcan::Poll{at(1, mcan::prio::Master), std::uint8_t(node_ - 1)}));
    }
    std::vector<mcan::Message> take(std::uint16_t handle) {
        return decoded(tell(mcan::Throttle{at(handle, mcan::prio::Throttle), 0, 0x0008, 1}));
    }
    std::vector<can::CanFrame> drive(std::uint16_t handle, std::uint8_t function, std::uint8_t value) {
        return tell(mcan::FunctionValue{at(handle, mcan::prio::SlaveDrive), function, value});
    }
    std::vector<can::CanFrame> tell(const mcan::Message& message) { return table_.tell(message); }
    mcan::Address at(std::uint16_t handle, std::uint8_t priority = mcan::prio::Data) const {
        return {priority, handle, node_};
    }

private:
    MasterOnTable& table_;
    std::uint32_t uid_;
    std::string name_;
    std::uint8_t mid_ = 0;
    std::uint8_t node_ = 0;
    std::uint8_t flags_ = 0xFF;
};

} // namespace stellwerk::mastertest
