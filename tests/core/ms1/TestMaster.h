#pragma once

#include "can/CanFrame.h"
#include "mcan/Messages.h"

#include <QObject>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace stellwerk::sim::test {

// A plain M-CAN master for the MS1 tests, answering at once as the trace's ECoS does: logins (MIDs from 12,
// a node pair per UID from 42/43), the upgrade's questions about one stack of locomotives, polls, take
// requests and the stop key. Tests change what it answers and push frames of their own.
class TestMaster : public QObject {
    Q_OBJECT

public:
    static constexpr std::uint32_t Uid = 0x000484D3;
    static constexpr std::uint16_t StartHandle = 0x0002;
    static constexpr std::uint16_t SdHandle = 0x0008;
    static constexpr std::uint16_t SyHandle = 0x0003;
    static constexpr std::uint16_t PollHandle = 0x0001;

    struct Loco {
        std::uint16_t handle = 0;
        std::string name;
        std::uint8_t type = 0;
        std::uint8_t railFormat = 0;
        std::vector<std::uint8_t> functionKinds; // f0, f1, ...: 01 latching, 02 momentary
    };

    std::vector<Loco> stack{{0x0009, "003 131-0", 3, 3, {}}};
    bool flash = false;      // the stage-7 reply sets the flash bit
    bool silent = false;     // answers nothing at all
    bool holdsLocos = false; // answers take requests with FFFF
    bool stopped = false;

    void receive(const can::CanFrame& frame);
    // A frame of the master to the slave at `slaveNode`: `message`'s address gets the master's node.
    void push(std::uint8_t slaveNode, mcan::Message message);
    // The node given to the MS1 with this UID (0: none).
    std::uint8_t nodeOf(std::uint32_t uid) const;

    std::vector<can::CanFrame> heard;

signals:
    void framesEmitted(const std::vector<stellwerk::can::CanFrame>& frames);

private:
    void login(const mcan::Message& message);
    bool upgrade(const mcan::Message& message);
    bool loco(const mcan::Message& message);
    bool operation(const mcan::Message& message);
    void send(const mcan::Message& message);
    const Loco* find(std::uint16_t handle) const;
    mcan::Address from(const mcan::Address& slave, std::uint8_t prio = 0) const;

    std::uint8_t nextMid_ = 12;
    std::uint8_t nextNode_ = 43;
    std::map<std::uint8_t, std::uint32_t> loginUid_; // MID -> UID from stage 4
    std::map<std::uint32_t, std::uint8_t> nodes_;    // UID -> slave node
};

} // namespace stellwerk::sim::test
