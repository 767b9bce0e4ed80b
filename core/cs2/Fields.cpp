#include "cs2/Fields.h"

#include "cs2/Hash.h"

#include <algorithm>
#include <bit>
#include <charconv>

namespace stellwerk::cs2 {

// ---- FieldBinder helpers built on onNumber --------------------------------------------------

void FieldBinder::named(std::string_view key, std::uint8_t& byte, std::span<const NamedValue> names,
                        std::uint8_t mask) {
    const int shift = std::countr_zero(unsigned(mask));
    NumberSlot slot{key,
                    FieldFormat::Decimal,
                    1,
                    false,
                    true,
                    std::uint64_t((byte & mask) >> shift),
                    std::uint64_t(mask >> shift),
                    names,
                    mask};
    if (onNumber(slot))
        byte = std::uint8_t((byte & ~mask) | ((slot.value << shift) & mask));
}

void FieldBinder::named(std::string_view key, std::optional<std::uint8_t>& byte,
                        std::span<const NamedValue> names) {
    NumberSlot slot{key, FieldFormat::Decimal, 1, true, byte.has_value(), byte.value_or(0), 0xFF, names};
    if (onNumber(slot))
        byte = slot.present ? std::optional<std::uint8_t>(std::uint8_t(slot.value)) : std::nullopt;
}

void FieldBinder::flag(std::string_view key, std::uint8_t& byte, std::uint8_t bit) {
    NumberSlot slot{key, FieldFormat::Bool, 1, false, true, (byte & bit) ? 1u : 0u, 1};
    if (onNumber(slot))
        byte = slot.value ? std::uint8_t(byte | bit) : std::uint8_t(byte & ~bit);
}

void FieldBinder::boolean(std::string_view key, std::optional<bool>& value) {
    NumberSlot slot{key, FieldFormat::Bool, 1, true, value.has_value(), value.value_or(false) ? 1u : 0u, 1};
    if (onNumber(slot))
        value = slot.present ? std::optional<bool>(slot.value != 0) : std::nullopt;
}

namespace {

unsigned hexDigitsFor(std::uint64_t max) {
    if (max <= 0xFF)
        return 2;
    if (max <= 0xFFFF)
        return 4;
    return 8;
}

std::string hexString(std::span<const std::uint8_t> bytes) {
    static constexpr char Digits[] = "0123456789ABCDEF";
    std::string out;
    out.reserve(bytes.size() * 2);
    for (auto b : bytes) {
        out.push_back(Digits[b >> 4]);
        out.push_back(Digits[b & 0x0F]);
    }
    return out;
}

// Eight file-name bytes as text: trailing NULs dropped, other bytes outside printable ASCII (and
// the backslash) written as \xNN so that the text converts back to the same bytes.
std::string escapeChars(const std::array<char, 8>& text) {
    std::size_t end = text.size();
    while (end > 0 && text[end - 1] == '\0')
        --end;
    std::string out;
    for (std::size_t i = 0; i < end; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c < 0x20 || c > 0x7E || c == '\\')
            out += "\\x" + hexString(std::span(&c, 1));
        else
            out += char(c);
    }
    return out;
}

std::optional<std::string> unescapeChars(std::string_view text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '\\') {
            out += text[i];
            continue;
        }
        unsigned value = 0;
        if (i + 3 >= text.size() || text[i + 1] != 'x' ||
            std::from_chars(text.data() + i + 2, text.data() + i + 4, value, 16).ptr != text.data() + i + 4)
            return std::nullopt;
        out += char(value);
        i += 3;
    }
    return out;
}

// Reads every field of a message into a list.
class Describer final : public FieldBinder {
public:
    Describer(const Message& message, std::vector<Field>& out) : message_(message), out_(out) {}

    bool response() const override { return message_.response; }
    std::uint16_t hash() const override { return message_.hash; }

    void loco(std::string_view key, LocId& id) override {
        out_.push_back({key, FieldFormat::Hex, id.value(), {}, id.value() > 0xFFFF ? 8u : 4u});
        const Protocol protocol = id.protocol();
        out_.push_back({"protocol", FieldFormat::Text, 0, std::string(protocolName(protocol)), 0, true});
        if (protocol != Protocol::Other)
            out_.push_back({"address", FieldFormat::Decimal, id.address(), {}, 0, true});
        else
            out_.push_back({"locIdRange", FieldFormat::Text, 0, std::string(rangeName(id.range())), 0, true});
    }
    void loco(std::string_view key, std::optional<LocId>& id) override {
        if (id)
            loco(key, *id);
    }
    void chars(std::string_view key, std::array<char, 8>& text) override {
        out_.push_back({key, FieldFormat::Text, 0, escapeChars(text), 0});
    }
    void bytes(std::string_view key, RawBytes& raw) override {
        out_.push_back({key, FieldFormat::Text, 0, hexString(raw.view()), 0});
    }
    void bytes(std::string_view key, std::array<std::uint8_t, 8>& data) override {
        out_.push_back({key, FieldFormat::Text, 0, hexString(data), 0});
    }
    void note(std::string_view key, std::string_view text) override {
        out_.push_back({key, FieldFormat::Text, 0, std::string(text), 0, true});
    }
    void version(std::string_view key, std::optional<std::uint16_t>& version) override {
        if (version)
            out_.push_back({key, FieldFormat::Text, 0,
                            std::to_string(*version >> 8) + "." + std::to_string(*version & 0xFF), 0});
    }
    void fixed(std::string_view key, std::uint64_t value, FieldFormat format) override {
        out_.push_back({key, format, value, {}, format == FieldFormat::Hex ? hexDigitsFor(value) : 0, true});
    }

protected:
    bool onNumber(NumberSlot& slot) override {
        if (!slot.present)
            return false;
        for (const auto& named : slot.names)
            if (named.value == slot.value) {
                out_.push_back({slot.key, FieldFormat::Text, 0, std::string(named.name), 0});
                return false;
            }
        out_.push_back({slot.key, slot.format, slot.value * slot.scale, {}, hexDigitsFor(slot.max)});
        return false;
    }

private:
    const Message& message_;
    std::vector<Field>& out_;
};

std::optional<std::uint64_t> parseUnsigned(std::string_view text) {
    int base = 10;
    if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
        text.remove_prefix(2);
        base = 16;
    }
    std::uint64_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value, base);
    if (ec != std::errc() || end != text.data() + text.size() || text.empty())
        return std::nullopt;
    return value;
}

// Keys of the frame header, handled by buildMessage before the body's fields.
bool isEnvelopeKey(std::string_view key) {
    return key == "prio" || key == "response" || key == "hash" || key == "packet";
}

std::optional<bool> parseBool(std::string_view text) {
    if (text == "true" || text == "1" || text == "yes" || text == "on")
        return true;
    if (text == "false" || text == "0" || text == "no" || text == "off")
        return false;
    return std::nullopt;
}

std::optional<std::vector<std::uint8_t>> parseHexBytes(std::string_view text) {
    std::vector<std::uint8_t> out;
    std::string digits;
    for (char c : text)
        if (c != ' ' && c != ':' && c != '.')
            digits.push_back(c);
    if (digits.size() % 2 != 0)
        return std::nullopt;
    for (std::size_t i = 0; i < digits.size(); i += 2) {
        unsigned value = 0;
        const auto [end, ec] = std::from_chars(digits.data() + i, digits.data() + i + 2, value, 16);
        if (ec != std::errc() || end != digits.data() + i + 2)
            return std::nullopt;
        out.push_back(std::uint8_t(value));
    }
    return out;
}

// Fills a message from key=value arguments, remembering which keys it used and the first error.
class Assigner final : public FieldBinder {
public:
    Assigner(std::span<const KeyValue> arguments, bool response, std::uint16_t hash)
        : arguments_(arguments), used_(arguments.size(), false), response_(response), hash_(hash) {}

    bool response() const override { return response_; }
    std::uint16_t hash() const override { return hash_; }
    const std::string& error() const { return error_; }

    void markUsed(std::string_view key) { (void)find(key); }

    std::string unusedKey() const {
        for (std::size_t i = 0; i < arguments_.size(); ++i)
            if (!used_[i])
                return arguments_[i].first;
        return {};
    }

    void loco(std::string_view key, LocId& id) override {
        std::optional<LocId> value = id;
        bindLoco(key, value, true);
        if (value)
            id = *value;
    }
    void loco(std::string_view key, std::optional<LocId>& id) override { bindLoco(key, id, false); }

    void chars(std::string_view key, std::array<char, 8>& text) override {
        const auto value = find(key);
        if (!value)
            return;
        const auto bytes = unescapeChars(*value);
        if (!bytes)
            return fail(std::string(key) + "=" + std::string(*value) + " has a broken \\xNN escape");
        if (bytes->size() > text.size())
            return fail(std::string(key) + "=" + std::string(*value) + " is longer than 8 characters");
        text.fill('\0');
        std::copy(bytes->begin(), bytes->end(), text.begin());
    }
    void bytes(std::string_view key, RawBytes& raw) override {
        const auto value = find(key);
        if (!value)
            return;
        const auto parsed = parseHexBytes(*value);
        if (!parsed || parsed->size() > 8)
            return fail(std::string(key) + "=" + std::string(*value) + " is not up to 8 hex bytes");
        raw.size = std::uint8_t(parsed->size());
        raw.bytes.fill(0);
        std::copy(parsed->begin(), parsed->end(), raw.bytes.begin());
    }
    void bytes(std::string_view key, std::array<std::uint8_t, 8>& data) override {
        RawBytes raw;
        bytes(key, raw);
        if (raw.size > 0) {
            data = raw.bytes;
        }
    }
    void note(std::string_view key, std::string_view) override { refuseDerived(key); }
    void fixed(std::string_view key, std::uint64_t, FieldFormat) override { refuseDerived(key); }
    void version(std::string_view key, std::optional<std::uint16_t>& version) override {
        const auto text = find(key);
        if (!text)
            return;
        const auto dot = text->find('.');
        const auto major = parseUnsigned(text->substr(0, dot));
        const auto minor = dot == std::string_view::npos ? std::optional<std::uint64_t>(0)
                                                         : parseUnsigned(text->substr(dot + 1));
        if (!major || !minor || *major > 255 || *minor > 255)
            return fail(std::string(key) + "=" + std::string(*text) + " is not a version like 1.62");
        version = std::uint16_t((*major << 8) | *minor);
    }

protected:
    bool onNumber(NumberSlot& slot) override {
        const auto text = find(slot.key);
        if (!text)
            return false;
        const auto value = parseNumber(slot, *text);
        if (!value)
            return false;
        slot.value = *value;
        slot.present = true;
        return true;
    }

private:
    std::optional<std::string_view> find(std::string_view key) {
        for (std::size_t i = 0; i < arguments_.size(); ++i)
            if (arguments_[i].first == key) {
                used_[i] = true;
                return std::string_view(arguments_[i].second);
            }
        return std::nullopt;
    }

    void refuseDerived(std::string_view key) {
        if (isEnvelopeKey(key))
            return;
        if (find(key))
            fail(std::string(key) + " is derived from the other fields and cannot be set");
    }

    void fail(std::string message) {
        if (error_.empty())
            error_ = std::move(message);
    }

    std::optional<std::uint64_t> parseNumber(const NumberSlot& slot, std::string_view text) {
        for (const auto& named : slot.names)
            if (named.name == text)
                return named.value;
        std::optional<std::uint64_t> value;
        if (slot.format == FieldFormat::Bool) {
            if (const auto b = parseBool(text))
                value = *b ? 1 : 0;
        } else {
            value = parseUnsigned(text);
        }
        const std::string shown = std::string(slot.key) + "=" + std::string(text);
        if (!value) {
            fail(shown + " is not a valid value" + expectedNames(slot));
            return std::nullopt;
        }
        if (*value % slot.scale != 0) {
            fail(shown + " must be a multiple of " + std::to_string(slot.scale));
            return std::nullopt;
        }
        if (*value / slot.scale > slot.max) {
            fail(shown + " is out of range (0.." + std::to_string(slot.max * slot.scale) + ")");
            return std::nullopt;
        }
        return *value / slot.scale;
    }

    static std::string expectedNames(const NumberSlot& slot) {
        if (slot.names.empty())
            return slot.format == FieldFormat::Bool ? " (true or false)" : "";
        std::string list = " (one of";
        for (const auto& named : slot.names)
            list += " " + std::string(named.name);
        return list + ", or a number)";
    }

    void bindLoco(std::string_view key, std::optional<LocId>& id, bool required) {
        const auto locText = find(key);
        const auto protocolText = find("protocol");
        const auto addressText = find("address");
        if (locText) {
            const auto value = parseUnsigned(*locText);
            if (!value || *value > 0xFFFFFFFF)
                return fail(std::string(key) + "=" + std::string(*locText) + " is not a 32-bit Loc-ID");
            id = LocId(std::uint32_t(*value));
            return;
        }
        if (protocolText && addressText) {
            const auto protocol = protocolFromName(*protocolText);
            const auto address = parseUnsigned(*addressText);
            if (!protocol || !address)
                return fail("protocol=" + std::string(*protocolText) + " address=" +
                            std::string(*addressText) + " does not name a protocol and a number");
            const auto built =
                LocId::fromAddress(*protocol, std::uint32_t(std::min<std::uint64_t>(*address, 0xFFFFFFFF)));
            if (!built)
                return fail("address=" + std::string(*addressText) + " does not exist for protocol " +
                            std::string(*protocolText));
            id = *built;
            return;
        }
        if (required)
            fail("needs " + std::string(key) + "=<Loc-ID> or protocol=<name> address=<number>");
    }

    std::span<const KeyValue> arguments_;
    std::vector<bool> used_;
    bool response_;
    std::uint16_t hash_;
    std::string error_;
};

template <std::size_t... I>
std::optional<MessageBody> bodyByName(std::string_view name, std::index_sequence<I...>) {
    std::optional<MessageBody> body;
    ((std::variant_alternative_t<I, MessageBody>::name == name ? (void)body.emplace(std::in_place_index<I>)
                                                               : (void)0),
     ...);
    return body;
}

template <std::size_t... I>
std::vector<std::string_view> allNames(std::index_sequence<I...>) {
    return {std::variant_alternative_t<I, MessageBody>::name...};
}

constexpr auto BodyIndices = std::make_index_sequence<std::variant_size_v<MessageBody>>();

} // namespace

std::vector<Field> describe(const Message& message) {
    std::vector<Field> fields;
    Message copy = message;
    Describer describer(message, fields);
    std::visit([&](auto& body) { body.bind(describer); }, copy.body);
    return fields;
}

Expected<Message, std::string> buildMessage(std::string_view name, std::span<const KeyValue> arguments) {
    auto body = bodyByName(name, BodyIndices);
    if (!body)
        return std::string("unknown message name '") + std::string(name) + "'";

    Message message;
    message.body = std::move(*body);
    Assigner envelope(arguments, false, 0);
    std::optional<std::uint8_t> prio;
    std::optional<bool> response;
    std::optional<std::uint16_t> hash;
    std::optional<std::uint16_t> packet;
    envelope.number("prio", prio);
    envelope.boolean("response", response);
    envelope.number("hash", hash, FieldFormat::Hex);
    envelope.number("packet", packet);
    if (!envelope.error().empty())
        return envelope.error();
    if (prio && *prio > 15)
        return std::string("prio=") + std::to_string(*prio) + " is out of range (0..15)";
    if (packet && *packet > 0x1FFF)
        return std::string("packet=") + std::to_string(*packet) + " is out of range (0..8191)";
    message.prio = prio.value_or(0);
    message.response = response.value_or(false);
    message.hash = packet ? hashFromPacketNumber(*packet) : hash.value_or(0);

    Assigner assigner(arguments, message.response, message.hash);
    for (const auto& [key, value] : arguments)
        if (isEnvelopeKey(key))
            assigner.markUsed(key);
    std::visit([&](auto& b) { b.bind(assigner); }, message.body);
    if (!assigner.error().empty())
        return std::string(name) + ": " + assigner.error();
    if (const auto unused = assigner.unusedKey(); !unused.empty())
        return std::string(name) + " has no field '" + unused + "'";
    return message;
}

std::vector<std::string_view> messageNames() {
    return allNames(BodyIndices);
}

} // namespace stellwerk::cs2
