#include "sim/Ms1Upgrade.h"

#include "mcan/Codec.h"

namespace stellwerk::sim {

namespace {

constexpr std::uint8_t StackList = 0x80;
constexpr std::uint8_t LastList = 0x82;

} // namespace

void Ms1Upgrade::start(bool askSlaveDescription, Ms1Outbox& out) {
    reset();
    const Ms1Link& link = memory_.link;
    if (askSlaveDescription)
        ask(Step::SdHandle, mcan::SdHandleRequest{link.at(link.startHandle), link.node}, out);
    else
        ask(Step::SyHandle, mcan::SyHandleRequest{link.at(link.startHandle)}, out);
}

void Ms1Upgrade::reset() {
    step_ = Step::Idle;
    index_ = 0;
    asked_.reset();
    inquiry_.reset();
    waiting_.clear();
}

void Ms1Upgrade::ask(Step step, const mcan::Message& question, Ms1Outbox& out) {
    step_ = step;
    asked_ = mcan::encode(question);
    out.frames.push_back(*asked_);
}

bool Ms1Upgrade::take(const can::CanFrame& frame, const mcan::Message& message, Ms1Outbox& out) {
    if (takeInquiry(frame, message, out))
        return true;
    if (!asked_ || !echoes(*asked_, frame))
        return false;
    switch (step_) {
    case Step::SdHandle:
    case Step::SyHandle:
        afterHandle(message, out);
        break;
    case Step::StatusType:
    case Step::StatusValue:
        afterStatus(message, out);
        break;
    case Step::LocoList:
        afterList(message, out);
        break;
    case Step::Idle:
    case Step::Done:
        return false;
    }
    return true;
}

// The SY handle answer (#30) starts the status list at index 1.
void Ms1Upgrade::afterHandle(const mcan::Message& message, Ms1Outbox& out) {
    Ms1Link& link = memory_.link;
    if (const auto* sd = std::get_if<mcan::SdHandleAnswer>(&message)) {
        link.sdHandle = sd->sdHandle;
        ask(Step::SyHandle, mcan::SyHandleRequest{link.at(link.startHandle)}, out);
        return;
    }
    if (const auto* sy = std::get_if<mcan::SyHandleAnswer>(&message))
        link.syHandle = sy->syHandle;
    index_ = 1;
    ask(Step::StatusType, mcan::StatusQuery{link.at(link.syHandle), index_, true}, out);
}

// Per index: the type (#31-#32), then the value (#33-#34); the bare echo of a type question ends the list.
void Ms1Upgrade::afterStatus(const mcan::Message& message, Ms1Outbox& out) {
    const mcan::Address at = memory_.link.at(memory_.link.syHandle);
    if (const auto* type = std::get_if<mcan::StatusType>(&message)) {
        memory_.statusTypes[index_] = type->type;
        ask(Step::StatusValue, mcan::StatusQuery{at, index_, false}, out);
        return;
    }
    if (step_ == Step::StatusValue) {
        if (const auto* value = std::get_if<mcan::StatusValue>(&message))
            memory_.setStatus(index_, value->value);
        ++index_;
        ask(Step::StatusType, mcan::StatusQuery{at, index_, true}, out);
        return;
    }
    askList(StackList, 0, out);
}

void Ms1Upgrade::askList(std::uint8_t list, std::uint16_t previous, Ms1Outbox& out) {
    index_ = list;
    ask(Step::LocoList, mcan::LocoListQuery{memory_.link.at(memory_.link.startHandle), list, previous}, out);
}

// The 0x80 list names the stack's locomotives one by one (#45-#49); 0x81 and 0x82 follow (#51-#57).
void Ms1Upgrade::afterList(const mcan::Message& message, Ms1Outbox& out) {
    if (const auto* entry = std::get_if<mcan::LocoListAnswer>(&message)) {
        askList(index_, entry->next, out);
        if (entry->list == StackList)
            addLoco(entry->next, out);
        return;
    }
    if (index_ < LastList) {
        askList(std::uint8_t(index_ + 1), 0, out);
        return;
    }
    step_ = Step::Done;
    asked_.reset();
}

void Ms1Upgrade::addLoco(std::uint16_t handle, Ms1Outbox& out) {
    if (memory_.loco(handle) || memory_.stack.size() >= memory_.capacity)
        return;
    memory_.stack.push_back(Ms1Loco{handle, {}, 0, 0, 0, false, {}, 0});
    waiting_.push_back(handle);
    if (!inquiry_)
        nextInquiry(out);
}

void Ms1Upgrade::inquire(std::uint16_t handle, Ms1Outbox& out) {
    if (step_ == Step::Idle)
        step_ = Step::Done; // a master's addition outside an upgrade
    addLoco(handle, out);
}

bool Ms1Upgrade::takeInquiry(const can::CanFrame& frame, const mcan::Message& message, Ms1Outbox& out) {
    if (!inquiry_ || !inquiry_->answeredBy(frame))
        return false;
    Ms1Loco* loco = memory_.loco(inquiry_->handle());
    Ms1Loco deleted; // the master deleted it meanwhile: learn into nothing
    if (const auto next = inquiry_->answer(message, loco ? *loco : deleted)) {
        out.frames.push_back(*next);
        return true;
    }
    inquiry_.reset();
    out.tell(Ms1Outbox::Event::DisplayChanged);
    nextInquiry(out);
    return true;
}

void Ms1Upgrade::nextInquiry(Ms1Outbox& out) {
    if (waiting_.empty())
        return;
    inquiry_.emplace(memory_.link, waiting_.front());
    waiting_.pop_front();
    out.frames.push_back(inquiry_->start());
}

} // namespace stellwerk::sim
