#include "cs2config/AccessoryAddressCheck.h"

#include <limits>
#include <map>
#include <string>

namespace stellwerk::cs2config {

namespace {

using ById = std::multimap<std::int64_t, const Accessory*>;

// Enough to show the problem; a hostile file with thousands of overlaps is not walked further.
constexpr int reportLimit = 1000;

std::int64_t lastAddress(const Accessory& accessory) {
    const int count = accessory.addressCount();
    if (accessory.id > std::numeric_limits<std::int64_t>::max() - count)
        return std::numeric_limits<std::int64_t>::max();
    return accessory.id + count - 1;
}

std::string describe(const Accessory& accessory) {
    return "accessory " + std::to_string(accessory.id) + " (" +
           (accessory.type.empty() ? std::string("no type") : accessory.type) + ", line " +
           std::to_string(accessory.lineNumber()) + ")";
}

// Two one-output articles may share an address when they sit on its two different outputs.
bool shareLegally(const Accessory& first, const Accessory& second) {
    const AccessoryTypeInfo* a = first.typeInfo();
    const AccessoryTypeInfo* b = second.typeInfo();
    return a && b && a->singleOutput && b->singleOutput && first.secondOutput != second.secondOutput;
}

void checkSharedIds(const std::vector<Accessory>& accessories, Diagnostics& diagnostics) {
    ById earlier;
    for (const Accessory& accessory : accessories) {
        const auto [from, to] = earlier.equal_range(accessory.id);
        for (auto it = from; it != to; ++it) {
            if (shareLegally(*it->second, accessory))
                continue;
            diagnostics.warning(accessory.lineNumber(),
                                "duplicate accessory id " + std::to_string(accessory.id) + ": " +
                                    describe(accessory) + " and " + describe(*it->second),
                                "both kept");
            break;
        }
        earlier.emplace(accessory.id, &accessory);
    }
}

void checkOverlaps(const std::vector<Accessory>& accessories, Diagnostics& diagnostics) {
    ById byId;
    for (const Accessory& accessory : accessories)
        byId.emplace(accessory.id, &accessory);
    int reports = 0;
    for (const Accessory& wide : accessories) {
        const int count = wide.addressCount();
        if (count <= 1)
            continue;
        const std::int64_t last = lastAddress(wide);
        for (auto it = byId.upper_bound(wide.id); it != byId.end() && it->first <= last; ++it) {
            if (++reports > reportLimit)
                return;
            diagnostics.warning(it->second->lineNumber(),
                                describe(*it->second) + " uses address " + std::to_string(it->first) +
                                    ", which " + describe(wide) + " also takes: it uses " +
                                    std::to_string(count) + " addresses, " + std::to_string(wide.id) + "-" +
                                    std::to_string(last),
                                "both kept");
        }
    }
}

void checkRange(const std::vector<Accessory>& accessories, Diagnostics& diagnostics) {
    for (const Accessory& accessory : accessories) {
        const std::int64_t highest = highestAccessoryAddress(accessory.protocol);
        if (accessory.id >= 1 && lastAddress(accessory) <= highest)
            continue;
        diagnostics.warning(accessory.lineNumber(),
                            describe(accessory) + " lies outside the keyboard addresses 1-" +
                                std::to_string(highest),
                            "kept");
    }
}

} // namespace

std::int64_t highestAccessoryAddress(std::string_view protocol) {
    return protocol == "mm2" ? 1024 : 2048;
}

void checkAccessoryAddresses(const std::vector<Accessory>& accessories, Diagnostics& diagnostics) {
    checkSharedIds(accessories, diagnostics);
    checkOverlaps(accessories, diagnostics);
    checkRange(accessories, diagnostics);
}

} // namespace stellwerk::cs2config
