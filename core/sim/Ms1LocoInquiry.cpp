#include "sim/Ms1LocoInquiry.h"

#include "mcan/Codec.h"
#include "mcan/NameSegments.h"

#include <algorithm>

namespace stellwerk::sim {

bool echoes(const can::CanFrame& question, const can::CanFrame& answer) {
    const mcan::SessionId asked = mcan::readSession(question.id);
    const mcan::SessionId answered = mcan::readSession(answer.id);
    return asked.handle == answered.handle && asked.cmd == answered.cmd && answer.size() >= question.size() &&
           std::equal(question.payload().begin(), question.payload().end(), answer.payload().begin());
}

can::CanFrame Ms1LocoInquiry::start() {
    return *ask(Step::Type);
}

std::optional<can::CanFrame> Ms1LocoInquiry::ask(Step step, std::uint8_t n) {
    step_ = step;
    n_ = n;
    asked_.reset();
    if (step == Step::Done)
        return std::nullopt;
    asked_ = question();
    return asked_;
}

can::CanFrame Ms1LocoInquiry::question() const {
    const mcan::Address at = link_.at(handle_);
    switch (step_) {
    case Step::Type:
        return mcan::encode(mcan::LocoQuery{at, 0x03, 0});
    case Step::Format:
        return mcan::encode(mcan::LocoQuery{at, 0x01, 0});
    case Step::FormatDetail:
        return mcan::encode(mcan::LocoQuery{at, 0x01, 1});
    case Step::Description:
        return mcan::encode(mcan::FunctionQuery{at, n_, true});
    case Step::Value:
        return mcan::encode(mcan::FunctionQuery{at, n_, false});
    case Step::Extra:
        return mcan::encode(mcan::FunctionExtraQuery{at, n_});
    case Step::Unknown4004:
        return mcan::encode(mcan::LocoQuery{at, 0x04, 0});
    case Step::Assignment:
        return mcan::encode(mcan::AssignmentQuery{at});
    case Step::Name:
    case Step::Done:
        break;
    }
    return mcan::encode(mcan::NameRequest{at, n_});
}

std::optional<can::CanFrame> Ms1LocoInquiry::answer(const mcan::Message& message, Ms1Loco& loco) {
    switch (step_) {
    case Step::Type:
    case Step::Format:
    case Step::FormatDetail:
    case Step::Unknown4004:
    case Step::Assignment:
        return afterProperty(message, loco);
    case Step::Description:
    case Step::Value:
    case Step::Extra:
        return afterFunction(message, loco);
    case Step::Name:
        return afterName(message, loco);
    case Step::Done:
        break;
    }
    return std::nullopt;
}

std::optional<can::CanFrame> Ms1LocoInquiry::afterProperty(const mcan::Message& message, Ms1Loco& loco) {
    const auto* property = std::get_if<mcan::LocoAnswer>(&message);
    const std::uint8_t value = property && property->tail.size >= 2 ? property->tail.data[1] : 0;
    switch (step_) {
    case Step::Type:
        loco.type = value;
        return ask(Step::Format);
    case Step::Format:
        loco.railFormat = value;
        return ask(Step::FormatDetail);
    case Step::FormatDetail:
        return ask(Step::Description, 1);
    case Step::Unknown4004:
        return ask(Step::Assignment);
    default:
        break;
    }
    if (const auto* assignment = std::get_if<mcan::Throttle>(&message))
        loco.assignment = assignment->state;
    return ask(Step::Name, 0);
}

// FKT 1 is the speed and direction, FKT n the function f(n-2); the end echo or FKT 9 ends the list.
std::optional<can::CanFrame> Ms1LocoInquiry::afterFunction(const mcan::Message& message, Ms1Loco& loco) {
    if (step_ == Step::Extra)
        return n_ < 2 ? ask(Step::Extra, std::uint8_t(n_ + 1)) : ask(Step::Unknown4004);
    if (step_ == Step::Description) {
        const auto* description = std::get_if<mcan::FunctionDescription>(&message);
        if (!description)
            return ask(Step::Extra, 0);
        if (n_ >= 2)
            loco.functions.push_back({description->kind, description->icon, 0});
        return ask(Step::Value, n_);
    }
    if (const auto* value = std::get_if<mcan::FunctionValue>(&message)) {
        if (n_ == 1) {
            loco.speed = value->value & 0x7F;
            loco.reverse = (value->value & 0x80) != 0;
        } else if (!loco.functions.empty()) {
            loco.functions.back().value = value->value;
        }
    }
    return n_ < LastFunction ? ask(Step::Description, std::uint8_t(n_ + 1)) : ask(Step::Extra, 0);
}

std::optional<can::CanFrame> Ms1LocoInquiry::afterName(const mcan::Message& message, Ms1Loco& loco) {
    const auto* segment = std::get_if<mcan::NameSegment>(&message);
    if (!segment)
        return ask(Step::Done);
    mcan::addSegment(loco.name, *segment);
    return mcan::endsName(*segment) ? ask(Step::Done) : ask(Step::Name, std::uint8_t(n_ + 4));
}

} // namespace stellwerk::sim
