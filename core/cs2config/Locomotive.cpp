#include "cs2config/Locomotive.h"

#include <algorithm>
#include <array>
#include <utility>

namespace stellwerk::cs2config {

namespace {

constexpr std::array<std::pair<LocomotiveDecoder, std::string_view>, 7> decoderNames{{
    {LocomotiveDecoder::Mm2Prg, "mm2_prg"},
    {LocomotiveDecoder::Mm2Dil8, "mm2_dil8"},
    {LocomotiveDecoder::MmPrg, "mm_prg"},
    {LocomotiveDecoder::Mmm2Lok, "mmm2_lok"},
    {LocomotiveDecoder::Dcc, "dcc"},
    {LocomotiveDecoder::Mfx, "mfx"},
    {LocomotiveDecoder::Sx1, "sx1"},
}};

} // namespace

std::string_view decoderName(LocomotiveDecoder decoder) {
    for (const auto& [known, name] : decoderNames)
        if (known == decoder)
            return name;
    return {};
}

LocomotiveDecoder decoderFromName(std::string_view name) {
    if (name.empty())
        return LocomotiveDecoder::None;
    for (const auto& [known, knownName] : decoderNames)
        if (knownName == name)
            return known;
    return LocomotiveDecoder::Unknown;
}

FunctionTrigger Function::trigger() const {
    if (duration == 0)
        return FunctionTrigger::Latching;
    if (duration == -1)
        return FunctionTrigger::Momentary;
    return duration > 0 ? FunctionTrigger::Timed : FunctionTrigger::Unknown;
}

void Function::setTrigger(FunctionTrigger trigger, int timed) {
    switch (trigger) {
    case FunctionTrigger::Latching:
        duration = 0;
        break;
    case FunctionTrigger::Momentary:
        duration = -1;
        break;
    case FunctionTrigger::Timed:
        duration = std::max(timed, 1);
        break;
    case FunctionTrigger::Unknown:
        break;
    }
}

const Function* Locomotive::function(int number) const {
    const auto found = std::find_if(functions.begin(), functions.end(),
                                    [number](const Function& f) { return f.number == number; });
    return found == functions.end() ? nullptr : &*found;
}

Function* Locomotive::function(int number) {
    return const_cast<Function*>(static_cast<const Locomotive*>(this)->function(number));
}

std::string Locomotive::decoderTypeText() const {
    return decoder == LocomotiveDecoder::Unknown ? decoderText : std::string(decoderName(decoder));
}

} // namespace stellwerk::cs2config
