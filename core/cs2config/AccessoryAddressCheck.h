#pragma once

#include "cs2config/AccessoryFile.h"
#include "cs2config/Diagnostics.h"

#include <cstdint>
#include <string_view>
#include <vector>

namespace stellwerk::cs2config {

// The highest keyboard address of a protocol: the protocol document's accessory Loc-ID ranges hold 1024
// MM addresses (0x3000-0x33FF) and 2048 DCC addresses (0x3800-0x3FFF).
std::int64_t highestAccessoryAddress(std::string_view protocol);

// Finds keyboard addresses used twice: the same id on two articles (legal only for two one-output
// articles on the two outputs of an address, `.ungerade` 0 and 1), an article whose further addresses
// (a three-way turnout takes id and id+1) hold another article, and ids outside the keyboard. Each
// finding is a warning; nothing is changed.
void checkAccessoryAddresses(const std::vector<Accessory>& accessories, Diagnostics& diagnostics);

} // namespace stellwerk::cs2config
