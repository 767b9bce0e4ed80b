#include "ro/RoProfile.h"

#include <cstdio>

namespace stellwerk::ro {
namespace {

constexpr std::uint32_t SimulatorRequestBase = 0x01FE0000;
constexpr std::uint32_t SimulatorAnswerBase = 0x01FF0000;

std::string blockProblem(const char* what, const RegisterBlock& block) {
    if (block.count == 0)
        return {};
    if (block.width == Width::None || block.width == Width::Bit)
        return std::string(what) + ": width must be byte, word or long";
    if (block.count > 8 * byteCount(block.width))
        return std::string(what) + ": " + std::to_string(block.count) + " registers do not fit a " +
               std::string(widthName(block.width));
    if (std::size_t(block.address) + byteCount(block.width) > 0x10000)
        return std::string(what) + ": the block runs past address 0xFFFF";
    return {};
}

std::string idText(std::uint32_t id, bool extended) {
    char text[16];
    std::snprintf(text, sizeof text, extended ? "0x%08X" : "0x%03X", id);
    return text;
}

} // namespace

std::optional<Direction> directionOf(const can::CanFrame& frame, const FrameIds& ids) {
    if (frame.extended != ids.extended)
        return std::nullopt;
    if (frame.id == ids.request)
        return Direction::Request;
    if (frame.id == ids.answer)
        return Direction::Answer;
    return std::nullopt;
}

RoProfile RoProfile::simulator(std::uint16_t module) {
    RoProfile profile;
    profile.name = "RO simulator " + std::to_string(module);
    profile.ids = {SimulatorRequestBase | module, SimulatorAnswerBase | module, true};
    profile.outputs = {0x0000, Width::Word, 16};
    profile.inputs = {0x0020, Width::Word, 16};
    profile.changeFlags = RegisterBlock{0x0022, Width::Word, 16};
    return profile;
}

std::string RoProfile::problem() const {
    const std::uint32_t mask = ids.extended ? can::CanFrame::ExtendedIdMask : can::CanFrame::StandardIdMask;
    for (const std::uint32_t id : {ids.request, ids.answer})
        if ((id & ~mask) != 0)
            return "id " + idText(id, true) + " does not fit a " + (ids.extended ? "29" : "11") +
                   "-bit frame";
    if (ids.request == ids.answer)
        return "request and answer id are both " + idText(ids.request, ids.extended);
    for (const auto& [what, block] : {std::pair{"outputs", outputs}, std::pair{"inputs", inputs}})
        if (auto problem = blockProblem(what, block); !problem.empty())
            return problem;
    return changeFlags ? blockProblem("change flags", *changeFlags) : std::string();
}

can::CanFrame RoProfile::requestFrame(const Request& request) const {
    return frameOf(ids.request, ids.extended, encode(request, readRequestSize));
}

can::CanFrame RoProfile::answerFrame(const Answer& answer) const {
    return frameOf(ids.answer, ids.extended, encode(answer));
}

can::CanFrame frameOf(std::uint32_t id, bool extended, const Payload& payload) {
    return extended ? can::CanFrame::extendedFrame(id, payload.span())
                    : can::CanFrame::standard(id, payload.span());
}

} // namespace stellwerk::ro
