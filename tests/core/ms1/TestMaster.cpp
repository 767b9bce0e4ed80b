#include "TestMaster.h"

#include "mcan/Codec.h"
#include "mcan/NameSegments.h"

namespace stellwerk::sim::test {

namespace {

// The trace's master answers to login stages 0-3 (#4, #6, #8, #10).
std::array<std::uint8_t, 8> loginData(std::uint8_t stage) {
    switch (stage) {
    case 0:
        return {0x00, 0x04, 0x84, 0xD3, 0x00, 0x01, 0x00, 0x01};
    case 1:
        return {0x00, 0x00, 0x00, 0x97, 0x00, 0x00, 0x01, 0x03};
    case 2:
        return {0x01, 0x13, 0x00, 0x05, 0x00, 0x00, 0x00, 0x00};
    default:
        return {0x00, 0x00, 0x00, 0x01, 0x03, 0x00, 0x00, 0x01};
    }
}

mcan::Bytes bytes(std::initializer_list<std::uint8_t> values) {
    mcan::Bytes result;
    for (const std::uint8_t value : values)
        result.data[result.size++] = value;
    return result;
}

} // namespace

void TestMaster::receive(const can::CanFrame& frame) {
    if (!mcan::isMcan(frame))
        return;
    heard.push_back(frame);
    if (silent)
        return;
    if (mcan::layoutOf(frame.id) == mcan::Layout::Login) {
        login(mcan::decode(frame));
        return;
    }
    const std::uint16_t handle = mcan::readSession(frame.id).handle;
    const auto role = handle == SyHandle ? mcan::HandleRole::SystemStatus
                      : find(handle)     ? mcan::HandleRole::Loco
                                         : mcan::HandleRole::Unknown;
    const mcan::Message message = mcan::decode(frame, role);
    upgrade(message) || loco(message) || operation(message);
}

void TestMaster::login(const mcan::Message& message) {
    if (const auto* request = std::get_if<mcan::LoginRequest>(&message)) {
        const std::uint8_t mid = request->stage == 0 ? nextMid_++ : request->mid;
        send(mcan::LoginReply{request->stage, request->uidByte, mid, loginData(request->stage)});
        return;
    }
    const auto* details = std::get_if<mcan::LoginDetails>(&message);
    if (!details)
        return;
    if (details->stage == 4)
        loginUid_[details->mid] = std::uint32_t(details->data[0]) << 24 |
                                  std::uint32_t(details->data[1]) << 16 |
                                  std::uint32_t(details->data[2]) << 8 | details->data[3];
    if (details->stage != 7)
        return;
    const std::uint32_t uid = loginUid_[details->mid];
    if (!nodes_.contains(uid)) {
        nodes_[uid] = nextNode_;
        nextNode_ = std::uint8_t(nextNode_ + 2);
    }
    send(mcan::LoginGrant{details->mid, uid, StartHandle, nodes_[uid], true, std::uint8_t(flash ? 1 : 0)});
}

// Handles, the status list (1 stop/go, 2 short circuit) and the loco-stack lists.
bool TestMaster::upgrade(const mcan::Message& message) {
    if (const auto* m = std::get_if<mcan::SdHandleRequest>(&message)) {
        send(mcan::SdHandleAnswer{from(m->at), m->slaveNode, SdHandle});
    } else if (const auto* m = std::get_if<mcan::SyHandleRequest>(&message)) {
        send(mcan::SyHandleAnswer{from(m->at), SyHandle, 0x03, 0});
    } else if (const auto* m = std::get_if<mcan::StatusQuery>(&message); m && m->type) {
        if (m->index <= 2)
            send(mcan::StatusType{from(m->at), m->index, m->index});
        else
            send(mcan::StatusListEnd{from(m->at), m->index});
    } else if (const auto* m = std::get_if<mcan::StatusQuery>(&message)) {
        const bool on = m->index == 1 && stopped;
        send(mcan::StatusValue{from(m->at, mcan::prio::Status), m->index, std::uint8_t(on ? 1 : 0)});
    } else if (const auto* m = std::get_if<mcan::LocoListQuery>(&message)) {
        auto entry = m->list != 0x80    ? stack.end()
                     : m->previous == 0 ? stack.begin()
                                        : std::ranges::find(stack, m->previous, &Loco::handle);
        if (entry != stack.end() && m->previous != 0)
            ++entry;
        if (entry == stack.end())
            send(mcan::LocoListEnd{from(m->at), m->list, m->previous});
        else
            send(mcan::LocoListAnswer{from(m->at), m->list, m->previous, entry->handle});
    } else {
        return false;
    }
    return true;
}

// What the MS1 asks about a locomotive (notes B§3.2 step 6), answered as the trace's ECoS answers.
bool TestMaster::loco(const mcan::Message& message) {
    if (const auto* m = std::get_if<mcan::LocoQuery>(&message)) {
        const Loco* known = find(m->at.handle);
        const mcan::Bytes tail = m->what == 0x03   ? bytes({0, known->type})
                                 : m->what == 0x04 ? bytes({0, 0})
                                 : m->variant == 0 ? bytes({0, known->railFormat, 0, 0})
                                                   : bytes({0, 0, 0, 0});
        send(mcan::LocoAnswer{from(m->at), m->what, m->variant, tail});
    } else if (const auto* m = std::get_if<mcan::FunctionQuery>(&message)) {
        const Loco* known = find(m->at.handle);
        const bool exists = m->function == 1 || std::size_t(m->function - 2) < known->functionKinds.size();
        if (!exists)
            send(mcan::FunctionListEnd{from(m->at), m->function});
        else if (!m->description)
            send(mcan::FunctionValue{from(m->at), m->function, 0});
        else
            send(mcan::FunctionDescription{from(m->at), m->function,
                                           m->function == 1 ? std::uint8_t(1)
                                                            : known->functionKinds[m->function - 2U],
                                           std::uint8_t(m->function == 1 ? 1 : 0)});
    } else if (const auto* m = std::get_if<mcan::FunctionExtraQuery>(&message)) {
        send(mcan::FunctionExtraAnswer{from(m->at), m->n, 0});
    } else if (const auto* m = std::get_if<mcan::AssignmentQuery>(&message)) {
        send(mcan::Throttle{from(m->at), 0, 0x0000, 1});
    } else if (const auto* m = std::get_if<mcan::NameRequest>(&message); m && find(m->at.handle)) {
        send(mcan::nameSegment(from(m->at), find(m->at.handle)->name, m->offset));
    } else {
        return false;
    }
    return true;
}

// Polls, take requests (echo, or FFFF while holdsLocos) and the stop key (answered as in 7.4).
bool TestMaster::operation(const mcan::Message& message) {
    if (const auto* m = std::get_if<mcan::Poll>(&message)) {
        send(mcan::PollAnswer{from(m->at), 0, m->masterNode, Uid});
    } else if (const auto* m = std::get_if<mcan::Throttle>(&message)) {
        send(mcan::Throttle{from(m->at), 0, holdsLocos ? std::uint16_t(0xFFFF) : std::uint16_t(0x0008), 1});
    } else if (const auto* m = std::get_if<mcan::StatusValue>(&message); m && m->index == 1) {
        stopped = m->value != 0;
        send(mcan::StatusValue{from(m->at, mcan::prio::Status), 1, m->value});
        send(mcan::StatusValue{from(m->at, mcan::prio::Status), 2, 0});
    } else {
        return false;
    }
    return true;
}

void TestMaster::push(std::uint8_t slaveNode, mcan::Message message) {
    std::visit(
        [slaveNode](auto& m) {
            if constexpr (requires { m.at; })
                m.at.node = std::uint8_t(slaveNode - 1);
        },
        message);
    send(message);
}

void TestMaster::send(const mcan::Message& message) {
    emit framesEmitted({mcan::encode(message)});
}

const TestMaster::Loco* TestMaster::find(std::uint16_t handle) const {
    const auto found = std::ranges::find(stack, handle, &Loco::handle);
    return found == stack.end() ? nullptr : &*found;
}

mcan::Address TestMaster::from(const mcan::Address& slave, std::uint8_t prio) const {
    return {prio != 0 ? prio : slave.prio, slave.handle, std::uint8_t(slave.node - 1)};
}

std::uint8_t TestMaster::nodeOf(std::uint32_t uid) const {
    const auto found = nodes_.find(uid);
    return found == nodes_.end() ? 0 : found->second;
}

} // namespace stellwerk::sim::test
