#include "orc/MessageBuilder.h"

#include <charconv>
#include <functional>
#include <optional>
#include <set>

namespace stellwerk::orc {
namespace {

// Reads key=value pairs as numbers and flags, remembering the first error and which keys were used.
class Keys {
public:
    explicit Keys(const std::vector<KeyValue>& keyValues) : keyValues_(keyValues) {}

    bool has(std::string_view key) const { return find(key) != nullptr; }

    std::uint32_t number(std::string_view key, std::uint32_t max, std::uint32_t fallback = 0,
                         std::uint32_t min = 0) {
        const std::string* text = find(key);
        if (!text)
            return fallback;
        used_.insert(std::string(key));
        const std::optional<std::uint32_t> value = parse(*text);
        if (!value)
            fail(std::string(key) + "=" + *text + " is not a number (decimal or 0x hex)");
        else if (*value < min || *value > max)
            fail(std::string(key) + "=" + *text + " is out of range " + std::to_string(min) + ".." +
                 std::to_string(max));
        return value.value_or(fallback);
    }

    bool flag(std::string_view key) {
        const std::string* text = find(key);
        if (!text)
            return false;
        used_.insert(std::string(key));
        if (*text != "true" && *text != "false" && *text != "1" && *text != "0")
            fail(std::string(key) + "=" + *text + " is not true or false");
        return *text == "true" || *text == "1";
    }

    // One of the words; their index.
    std::uint8_t word(std::string_view key, std::initializer_list<std::string_view> words,
                      std::uint8_t fallback) {
        const std::string* text = find(key);
        if (!text)
            return fallback;
        used_.insert(std::string(key));
        std::uint8_t index = 0;
        for (const std::string_view w : words) {
            if (*text == w || *text == std::to_string(index))
                return index;
            ++index;
        }
        fail(std::string(key) + "=" + *text + " is not one of the allowed words");
        return fallback;
    }

    std::string error(std::string_view name) const {
        if (!error_.empty())
            return std::string(name) + ": " + error_;
        for (const KeyValue& kv : keyValues_)
            if (!used_.count(kv.first))
                return std::string(name) + ": unknown key '" + kv.first + "' (keys: prio type sender " +
                       std::string(keysOf(name)) + ")";
        return {};
    }

private:
    const std::string* find(std::string_view key) const {
        for (const KeyValue& kv : keyValues_)
            if (kv.first == key)
                return &kv.second;
        return nullptr;
    }
    static std::optional<std::uint32_t> parse(std::string_view text) {
        int base = 10;
        if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
            text.remove_prefix(2);
            base = 16;
        }
        std::uint32_t value = 0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value, base);
        if (ec != std::errc() || end != text.data() + text.size() || text.empty())
            return std::nullopt;
        return value;
    }
    void fail(std::string why) {
        if (error_.empty())
            error_ = std::move(why);
    }

    const std::vector<KeyValue>& keyValues_;
    std::set<std::string> used_;
    std::string error_;
};

using Builder = std::function<Message(Keys&, const Origin&)>;

struct Entry {
    std::string_view name;
    std::string_view keys;
    Builder build;
};

Target target(Keys& k) {
    if (k.has("uid"))
        return Target::uid(k.number("uid", 0xFFFFFFFF));
    if (k.has("target"))
        return Target::busId(std::uint16_t(k.number("target", 0xFFFF)));
    return Target::all();
}
std::uint16_t id16(Keys& k, std::string_view key) {
    return std::uint16_t(k.number(key, 0xFFFF));
}
std::uint8_t u8(Keys& k, std::string_view key, std::uint32_t max = 0xFF) {
    return std::uint8_t(k.number(key, max));
}
GroupAction action(Keys& k) {
    return GroupAction(k.word("action", {"off", "on", "restore"}, 0));
}

const std::vector<Entry>& systemEntries() {
    static const std::vector<Entry> entries{
        {"orc.system.allOff", "target|uid",
         [](Keys& k, const Origin& o) -> Message {
             return AllOff{o, target(k)};
         }},
        {"orc.system.allOn", "target|uid",
         [](Keys& k, const Origin& o) -> Message {
             return AllOn{o, target(k)};
         }},
        {"orc.system.overload", "kind port answer",
         [](Keys& k, const Origin& o) -> Message {
             return Overload{o, k.flag("answer"), u8(k, "kind"), k.has("port"), u8(k, "port")};
         }},
        {"orc.loco.stop", "target|uid",
         [](Keys& k, const Origin& o) -> Message {
             return LocoStop{o, target(k)};
         }},
        {"orc.loco.speedQuery", "target",
         [](Keys& k, const Origin& o) -> Message {
             return LocoSpeedQuery{o, id16(k, "target")};
         }},
        {"orc.loco.speed", "target speed answer",
         [](Keys& k, const Origin& o) -> Message {
             return LocoSpeed{o, k.flag("answer"), id16(k, "target"), id16(k, "speed")};
         }},
        {"orc.loco.speedQueryUid", "uid",
         [](Keys& k, const Origin& o) -> Message {
             return LocoSpeedQueryByUid{o, k.number("uid", 0xFFFFFFFF)};
         }},
        {"orc.loco.speedUid", "uid speed answer",
         [](Keys& k, const Origin& o) -> Message {
             return LocoSpeedByUid{o, k.flag("answer"), k.number("uid", 0xFFFFFFFF), id16(k, "speed"), false};
         }},
    };
    return entries;
}

const std::vector<Entry>& functionEntries() {
    static const std::vector<Entry> entries{
        {"orc.loco.functionsQuery", "target",
         [](Keys& k, const Origin& o) -> Message {
             return LocoFunctionsQuery{o, id16(k, "target")};
         }},
        {"orc.loco.functions", "target functions answer",
         [](Keys& k, const Origin& o) -> Message {
             return LocoFunctions{o, k.flag("answer"), id16(k, "target"), k.number("functions", 0xFFFFFFFF)};
         }},
        {"orc.loco.functionQuery", "target function",
         [](Keys& k, const Origin& o) -> Message {
             return LocoFunctionQuery{o, id16(k, "target"), u8(k, "function", 31)};
         }},
        {"orc.loco.function", "target function value answer",
         [](Keys& k, const Origin& o) -> Message {
             return LocoFunction{
                 o, k.flag("answer"), id16(k, "target"), u8(k, "function", 31), u8(k, "value"), 7};
         }},
    };
    return entries;
}

const std::vector<Entry>& accessoryEntries() {
    static const std::vector<Entry> entries{
        {"orc.decoder.all", "action=off|on|restore",
         [](Keys& k, const Origin& o) -> Message {
             return AllDecoders{o, action(k)};
         }},
        {"orc.decoder.switch", "target position answer",
         [](Keys& k, const Origin& o) -> Message {
             return DecoderSwitch{o, k.flag("answer"), id16(k, "target"), u8(k, "position")};
         }},
        {"orc.encoder.all", "action=off|on|restore",
         [](Keys& k, const Origin& o) -> Message {
             return AllEncoders{o, action(k)};
         }},
        {"orc.encoder.query", "target (none: every encoder)",
         [](Keys& k, const Origin& o) -> Message {
             return EncoderQuery{o, !k.has("target"), id16(k, "target")};
         }},
        {"orc.encoder.status", "encoder inputs count=8|16|24|32 answer",
         [](Keys& k, const Origin& o) -> Message {
             const std::uint32_t count = k.number("count", 32, 32, 8);
             return EncoderStatus{o, k.flag("answer"), id16(k, "encoder"), std::uint8_t((count + 7) / 8),
                                  k.number("inputs", 0xFFFFFFFF)};
         }},
    };
    return entries;
}

const std::vector<Entry>& managementEntries() {
    static const std::vector<Entry> entries{
        {"orc.mgmt.ping", "uid",
         [](Keys& k, const Origin& o) -> Message {
             return Ping{o, k.number("uid", 0xFFFFFFFF)};
         }},
        {"orc.mgmt.pingAnswer", "uid version",
         [](Keys& k, const Origin& o) -> Message {
             return PingAnswer{o, k.number("uid", 0xFFFFFFFF), id16(k, "version")};
         }},
        {"orc.mgmt.find", "uid",
         [](Keys& k, const Origin& o) -> Message {
             return Find{o, k.number("uid", 0xFFFFFFFF)};
         }},
        {"orc.mgmt.findAnswer", "uid version (extension)",
         [](Keys& k, const Origin& o) -> Message {
             return FindAnswer{o, k.number("uid", 0xFFFFFFFF), id16(k, "version")};
         }},
        {"orc.mgmt.assign", "uid busId answer (extension)",
         [](Keys& k, const Origin& o) -> Message {
             return AssignBusId{o, k.flag("answer"), k.number("uid", 0xFFFFFFFF), id16(k, "busId")};
         }},
    };
    return entries;
}

const std::vector<Entry>& flashEntries() {
    static const std::vector<Entry> entries{
        {"orc.flash.cancel", "", [](Keys&, const Origin& o) -> Message { return FlashCancel{o}; }},
        {"orc.flash.init", "target|uid version",
         [](Keys& k, const Origin& o) -> Message {
             const Target t = k.has("uid") || k.has("target") ? target(k) : Target::busId(0);
             return FlashInit{o, t, u8(k, "version")};
         }},
        {"orc.flash.accepted", "target uid version",
         [](Keys& k, const Origin& o) -> Message {
             return FlashAccepted{o, id16(k, "target"), k.number("uid", 0xFFFFFFFF), u8(k, "version")};
         }},
        {"orc.flash.size", "target start size",
         [](Keys& k, const Origin& o) -> Message {
             return FlashSize{o, id16(k, "target"), k.number("start", 0xFFFFFF), id16(k, "size"), false};
         }},
        {"orc.flash.sizeAnswer", "target available countMax",
         [](Keys& k, const Origin& o) -> Message {
             return FlashSizeAnswer{o, id16(k, "target"), id16(k, "available"), u8(k, "countMax"), false};
         }},
        {"orc.flash.data", "target count bytes answer",
         [](Keys& k, const Origin& o) -> Message {
             const std::uint32_t b = k.number("bytes", 0xFFFFFFFF);
             return FlashData{
                 o,
                 k.flag("answer"),
                 id16(k, "target"),
                 u8(k, "count"),
                 {std::uint8_t(b >> 24), std::uint8_t(b >> 16), std::uint8_t(b >> 8), std::uint8_t(b)}};
         }},
        {"orc.flash.checksum", "target count crc answer",
         [](Keys& k, const Origin& o) -> Message {
             return FlashChecksum{o, k.flag("answer"), id16(k, "target"), u8(k, "count"),
                                  k.number("crc", 0xFFFFFFFF)};
         }},
    };
    return entries;
}

const Entry* entryOf(std::string_view name) {
    for (const auto* list :
         {&systemEntries(), &functionEntries(), &accessoryEntries(), &managementEntries(), &flashEntries()})
        for (const Entry& entry : *list)
            if (entry.name == name)
                return &entry;
    return nullptr;
}

Origin origin(Keys& k) {
    const std::uint8_t prio = std::uint8_t(k.number("prio", 3, 0, 1));
    const std::uint8_t type = k.word("type", {"system", "loco", "can-decoder", "can-encoder"}, 0);
    return {prio, type, std::uint16_t(k.number("sender", 0xFFFF))};
}

} // namespace

Expected<Message, std::string> buildMessage(std::string_view name, const std::vector<KeyValue>& keyValues) {
    const Entry* entry = entryOf(name);
    if (!entry)
        return std::string("unknown OpenRailCAN message '") + std::string(name) + "' (see encode --list)";
    Keys keys(keyValues);
    const Origin from = origin(keys);
    Message message = entry->build(keys, from);
    const std::string error = keys.error(name);
    if (!error.empty())
        return error;
    return message;
}

std::string_view keysOf(std::string_view name) {
    const Entry* entry = entryOf(name);
    return entry ? entry->keys : std::string_view();
}

} // namespace stellwerk::orc
