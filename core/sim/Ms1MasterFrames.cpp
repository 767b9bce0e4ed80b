#include "sim/Ms1MasterFrames.h"

#include "mcan/NameSegments.h"

namespace stellwerk::sim {

namespace {

constexpr std::uint16_t Granted = 0x0008;
constexpr std::uint16_t HeldByMaster = 0xFFFF;

} // namespace

bool Ms1MasterFrames::take(const mcan::Message& message, Ms1Outbox& out) {
    return std::visit([this, &out](const auto& m) { return on(m, out); }, message);
}

// 6.4.1: `41 00 00 00 00 0A` (trace #23).
bool Ms1MasterFrames::on(const mcan::StackSizeRequest& request, Ms1Outbox& out) {
    out.send(mcan::StackSizeAnswer{memory_.link.at(request.at.handle), std::uint16_t(memory_.capacity)});
    return true;
}

// 6.4.2: the MS1's name in segments (trace #24-#26, #29); the master asks for a locomotive's name never.
bool Ms1MasterFrames::on(const mcan::NameRequest& request, Ms1Outbox& out) {
    if (request.at.handle != memory_.link.sdHandle)
        return false;
    out.send(mcan::nameSegment(memory_.link.at(request.at.handle), identity_.name, request.offset));
    return true;
}

// 7.2.2: the master has not heard the MS1 for a while; it answers `03 00 00 00` and its UID.
bool Ms1MasterFrames::on(const mcan::MasterPoll& poll, Ms1Outbox& out) {
    if (poll.aboutNode != memory_.link.node)
        return false;
    out.send(mcan::PollReply{memory_.link.at(Ms1Link::PollHandle, mcan::prio::Master), identity_.uid});
    return true;
}

bool Ms1MasterFrames::on(const mcan::StatusValue& status, Ms1Outbox& out) {
    if (status.at.handle != memory_.link.syHandle)
        return false;
    memory_.setStatus(status.index, status.value);
    out.tell(Ms1Outbox::Event::DisplayChanged);
    return true;
}

// FKT 1: speed and direction (bit 7 = reverse); FKT n: function f(n-2). Priority 011 ("Master fährt Lok").
bool Ms1MasterFrames::on(const mcan::FunctionValue& value, Ms1Outbox& out) {
    Ms1Loco* loco = memory_.loco(value.at.handle);
    if (!loco)
        return false;
    if (value.function == 1) {
        loco->speed = value.value & 0x7F;
        loco->reverse = (value.value & 0x80) != 0;
    } else if (value.function >= 2 && std::size_t(value.function - 2) < loco->functions.size()) {
        loco->functions[std::size_t(value.function - 2)].value = value.value;
    }
    out.tell(Ms1Outbox::Event::DisplayChanged);
    return true;
}

// 7.7.2: the MS1 asks about the new locomotive at once (no polls meanwhile).
bool Ms1MasterFrames::on(const mcan::StackAdd& add, Ms1Outbox& out) {
    upgrade_.inquire(add.locoHandle, out);
    out.tell(Ms1Outbox::Event::DisplayChanged);
    return true;
}

// 7.7.1: when the shown locomotive goes, the MS1 takes another entry of its stack, if there is one.
bool Ms1MasterFrames::on(const mcan::StackDelete& deletion, Ms1Outbox& out) {
    const auto index = memory_.indexOf(deletion.locoHandle);
    if (!index)
        return true;
    memory_.stack.erase(memory_.stack.begin() + std::ptrdiff_t(*index));
    out.tell(Ms1Outbox::Event::DisplayChanged);
    if (!memory_.shown || *memory_.shown < *index)
        return true;
    if (*memory_.shown > *index) {
        --*memory_.shown;
        return true;
    }
    memory_.shown.reset();
    memory_.control = Ms1Control::None;
    keys_.take(0, out);
    return true;
}

// 7.5: a new name for the MS1 on its SD handle, which it repeats from its own node; or (not in the
// documents) a new name for a locomotive on the locomotive's handle.
bool Ms1MasterFrames::on(const mcan::NameSegment& segment, Ms1Outbox& out) {
    if (segment.at.handle == memory_.link.sdHandle) {
        mcan::addSegment(identity_.name, segment);
        mcan::NameSegment echo = segment;
        echo.at = memory_.link.at(segment.at.handle);
        out.send(echo);
    } else if (Ms1Loco* loco = memory_.loco(segment.at.handle)) {
        mcan::addSegment(loco->name, segment);
    } else {
        return false;
    }
    out.tell(Ms1Outbox::Event::DisplayChanged);
    return true;
}

bool Ms1MasterFrames::on(const mcan::Throttle& throttle, Ms1Outbox& out) {
    Ms1Loco* loco = memory_.loco(throttle.at.handle);
    if (!loco)
        return false;
    loco->assignment = throttle.state;
    const Ms1Loco* shown = memory_.shownLoco();
    if (shown && shown->handle == throttle.at.handle)
        throttleOfShown(throttle.state, out);
    out.tell(Ms1Outbox::Event::DisplayChanged);
    return true;
}

// 7.6: the echo (0008) grants, FFFF means the master holds the locomotive (the MS1 only watches it), 0000
// releases it. A release of a locomotive the MS1 drove or watched makes it choose the locomotive again,
// once: a second release while that is open leaves it without one (the ECoS answers a choice it refuses
// with 0000, FFFF, 0000).
void Ms1MasterFrames::throttleOfShown(std::uint16_t state, Ms1Outbox& out) {
    const int index = int(*memory_.shown);
    const Ms1Control before = memory_.control;
    if (state == Granted) {
        memory_.control = Ms1Control::Granted;
        memory_.choosingAgain = false;
        if (before != Ms1Control::Granted)
            out.tell(Ms1Outbox::Event::LocoTaken, index);
    } else if (state == HeldByMaster) {
        memory_.control = Ms1Control::HeldByMaster;
        if (before == Ms1Control::Asked)
            out.tell(Ms1Outbox::Event::LocoRefused, index);
    } else if (before == Ms1Control::Granted || before == Ms1Control::HeldByMaster) {
        if (memory_.choosingAgain) {
            memory_.control = Ms1Control::None;
            return;
        }
        memory_.choosingAgain = true;
        keys_.chooseAgain(out);
    }
}

} // namespace stellwerk::sim
