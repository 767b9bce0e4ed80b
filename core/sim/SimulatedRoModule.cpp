#include "sim/SimulatedRoModule.h"

#include <QTimer>

namespace stellwerk::sim {
namespace {

bool covers(const ro::RegisterBlock& block, std::size_t address) {
    return address >= block.address && address < block.address + ro::byteCount(block.width);
}

std::uint32_t bitOf(int number) {
    return number >= 1 && number <= 32 ? 1u << (number - 1) : 0u;
}

} // namespace

SimulatedRoModule::SimulatedRoModule(ro::RoProfile profile, QObject* parent)
    : QObject(parent), profile_(std::move(profile)) {}

void SimulatedRoModule::receive(const can::CanFrame& frame) {
    if (ro::directionOf(frame, profile_.ids) != ro::Direction::Request || !plugged_)
        return;
    if (requestsToLose_ > 0) {
        --requestsToLose_;
        return;
    }
    ++requestsSeen_;
    answer(carryOut(frame.payload()));
}

// Notes R21: an invalid request earns 0xFE before its job id is looked at, and does not use it up.
ro::Answer SimulatedRoModule::carryOut(std::span<const std::uint8_t> payload) {
    const auto request = ro::decodeRequest(payload);
    if (!request)
        return ro::InvalidCommandAnswer{};
    if (lastJob_ == request->job) {
        ro::DuplicateJobAnswer duplicate{request->job};
        if (duplicateCarriesData_ && !request->isWrite())
            if (const auto value = registers_.read(request->address, request->width)) // no clearing here
                duplicate = {request->job, std::uint8_t(ro::byteCount(request->width)), *value};
        return duplicate;
    }
    const ro::Answer result = execute(*request);
    if (!std::holds_alternative<ro::InvalidCommandAnswer>(result))
        lastJob_ = request->job;
    return result;
}

ro::Answer SimulatedRoModule::execute(const ro::Request& request) {
    if (!request.isWrite()) {
        const auto value = readRegister(request);
        return value ? ro::Answer(ro::OkAnswer{request.width, request.job, *value})
                     : ro::InvalidCommandAnswer{};
    }
    if (!registers_.write(request.address, request.width, request.value))
        return ro::InvalidCommandAnswer{}; // R13: past 0xFFFF
    writes_.push_back(Write{request.address, request.width, request.value, request.job});
    emit relaysChanged(relays());
    return ro::OkAnswer{ro::Width::None, request.job, 0};
}

std::optional<std::uint32_t> SimulatedRoModule::readRegister(const ro::Request& request) {
    const auto value = registers_.read(request.address, request.width);
    if (value && profile_.changeFlags)
        clearChangeFlags(request);
    return value;
}

// Reading change flags clears them (004 §2.1), also when the read only overlaps them.
void SimulatedRoModule::clearChangeFlags(const ro::Request& read) {
    const ro::RegisterBlock& flags = *profile_.changeFlags;
    if (read.width == ro::Width::Bit) {
        if (covers(flags, std::size_t(read.address >> 3)))
            registers_.write(read.address, ro::Width::Bit, 0);
        return;
    }
    for (std::size_t address = read.address; address < read.address + ro::byteCount(read.width); ++address)
        if (covers(flags, address))
            registers_.write(std::uint16_t(address), ro::Width::Byte, 0);
}

void SimulatedRoModule::answer(const ro::Answer& result) {
    ++answersMade_;
    if (answersToLose_ > 0 || (loseEvery_ > 0 && answersMade_ % std::uint64_t(loseEvery_) == 0)) {
        answersToLose_ = std::max(0, answersToLose_ - 1);
        return;
    }
    const can::CanFrame frame = profile_.answerFrame(result);
    ++answersSent_;
    if (answerDelay_.count() <= 0) {
        emit framesEmitted({frame});
        return;
    }
    QTimer::singleShot(answerDelay_, this, [this, frame] {
        if (plugged_)
            emit framesEmitted({frame});
    });
}

bool SimulatedRoModule::relay(int number) const {
    return relays() & bitOf(number);
}

std::uint32_t SimulatedRoModule::relays() const {
    const ro::RegisterBlock& outputs = profile_.outputs;
    return outputs.count ? registers_.read(outputs.address, outputs.width).value_or(0) : 0;
}

bool SimulatedRoModule::input(int number) const {
    const ro::RegisterBlock& inputs = profile_.inputs;
    return inputs.count && (registers_.read(inputs.address, inputs.width).value_or(0) & bitOf(number));
}

void SimulatedRoModule::presetRelays(std::uint32_t relays) {
    if (profile_.outputs.count)
        registers_.write(profile_.outputs.address, profile_.outputs.width, relays);
}

void SimulatedRoModule::setInput(int number, bool on) {
    const ro::RegisterBlock& inputs = profile_.inputs;
    const std::uint32_t bit = bitOf(number);
    if (!bit || number > inputs.count)
        return;
    const std::uint32_t before = registers_.read(inputs.address, inputs.width).value_or(0);
    const std::uint32_t after = on ? before | bit : before & ~bit;
    registers_.write(inputs.address, inputs.width, after);
    if (after != before && profile_.changeFlags) {
        const ro::RegisterBlock& flags = *profile_.changeFlags;
        registers_.write(flags.address, flags.width,
                         registers_.read(flags.address, flags.width).value_or(0) | bit);
    }
}

} // namespace stellwerk::sim
