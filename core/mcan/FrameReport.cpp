#include "mcan/FrameReport.h"

#include "mcan/HandleRoles.h"

#include <cstdio>
#include <type_traits>

namespace stellwerk::mcan {
namespace {

using Fields = can::FieldList;

void address(Fields& f, const Address& at) {
    f.text("from", isSlaveNode(at.node) ? "slave" : "master")
        .number("node", at.node)
        .hex("handle", at.handle, 4);
    f.number("prio", at.prio);
}

std::uint32_t u32(const std::array<std::uint8_t, 8>& data, std::size_t i) {
    return std::uint32_t(data[i]) << 24 | std::uint32_t(data[i + 1]) << 16 | std::uint32_t(data[i + 2]) << 8 |
           data[i + 3];
}

void bytes(Fields& f, std::string_view key, const std::uint8_t* data, std::size_t size) {
    std::string text;
    for (std::size_t i = 0; i < size; ++i) {
        char pair[3];
        std::snprintf(pair, sizeof pair, "%02X", data[i]);
        text += pair;
    }
    f.text(key, text);
}

void add(Fields& f, const LoginRequest& m) {
    f.text("from", "slave").number("stage", m.stage).hex("uidByte", m.uidByte).number("mid", m.mid);
}
void add(Fields& f, const LoginReply& m) {
    f.text("from", "master").number("stage", m.stage).hex("uidByte", m.uidByte).number("mid", m.mid);
    if (m.stage == 0)
        f.hex("masterUid", u32(m.data, 0), 8).number("masterType", m.data[7]);
    else
        bytes(f, "data", m.data.data(), 8);
}
void add(Fields& f, const LoginDetails& m) {
    f.text("from", "slave").number("stage", m.stage).number("mid", m.mid);
    if (m.stage == 4)
        f.hex("uid", u32(m.data, 0), 8);
    bytes(f, "data", m.data.data() + (m.stage == 4 ? 4 : 0), m.stage == 4 ? 4 : 8);
}
void add(Fields& f, const LoginGrant& m) {
    f.text("from", "master").number("stage", 7).number("mid", m.mid).hex("uid", m.slaveUid, 8);
    f.hex("startHandle", m.startHandle, 4).number("slaveNode", m.node).number("masterNode", m.node - 1u);
    f.flag("multiSlave", m.multiSlave).flag("flashMode", (m.flags & 1) != 0);
}
void add(Fields& f, const BusBusy& m) {
    f.number("dlc", m.dlc);
}
void add(Fields& f, const SdHandleRequest& m) {
    address(f, m.at);
    f.number("slaveNode", m.slaveNode);
}
void add(Fields& f, const SdHandleAnswer& m) {
    address(f, m.at);
    f.number("slaveNode", m.slaveNode).hex("sdHandle", m.sdHandle, 4);
}
void add(Fields& f, const StackSizeRequest& m) {
    address(f, m.at);
}
void add(Fields& f, const StackSizeAnswer& m) {
    address(f, m.at);
    f.number("stackSize", m.size);
}
void add(Fields& f, const NameRequest& m) {
    address(f, m.at);
    f.number("offset", m.offset);
}
void add(Fields& f, const NameSegment& m) {
    address(f, m.at);
    f.number("offset", m.offset).text("chars", printable(std::string_view(m.chars.data(), m.count)));
    if (m.marker != 0)
        f.hex("marker", m.marker);
}
void add(Fields& f, const SyHandleRequest& m) {
    address(f, m.at);
}
void add(Fields& f, const SyHandleAnswer& m) {
    address(f, m.at);
    f.hex("syHandle", m.syHandle, 4);
    if (m.lead != 0x03)
        f.hex("lead", m.lead).number("slaveNode", m.second);
}
void add(Fields& f, const StatusQuery& m) {
    address(f, m.at);
    f.number("index", m.index).text("asks", m.type ? "type" : "value");
}
void add(Fields& f, const StatusType& m) {
    address(f, m.at);
    static constexpr std::string_view types[] = {"none", "stop-go", "short-circuit", "ms1-master",
                                                 "mfx-registration"};
    f.number("index", m.index).number("type", m.type);
    if (m.type < std::size(types))
        f.text("meaning", std::string(types[m.type]));
}
void add(Fields& f, const StatusListEnd& m) {
    address(f, m.at);
    f.number("index", m.index);
}
void add(Fields& f, const StatusValue& m) {
    address(f, m.at);
    f.number("index", m.index).number("value", m.value);
}
void add(Fields& f, const LocoListQuery& m) {
    address(f, m.at);
    f.hex("list", m.list).hex("previous", m.previous, 4);
}
void add(Fields& f, const LocoListAnswer& m) {
    address(f, m.at);
    f.hex("list", m.list).hex("previous", m.previous, 4).hex("next", m.next, 4);
}
void add(Fields& f, const LocoListEnd& m) {
    address(f, m.at);
    f.hex("list", m.list).hex("previous", m.previous, 4);
}
void add(Fields& f, const StackAdd& m) {
    address(f, m.at);
    f.hex("locoHandle", m.locoHandle, 4);
}
void add(Fields& f, const StackDelete& m) {
    address(f, m.at);
    f.hex("locoHandle", m.locoHandle, 4);
}
std::string locoProperty(std::uint8_t what) {
    return what == 0x03 ? "type" : what == 0x01 ? "rail-format" : "unexplained";
}
void add(Fields& f, const LocoQuery& m) {
    address(f, m.at);
    f.text("asks", locoProperty(m.what)).number("variant", m.variant);
}
void add(Fields& f, const LocoAnswer& m) {
    address(f, m.at);
    f.text("answers", locoProperty(m.what)).number("variant", m.variant);
    if (m.tail.size >= 2 && m.what != 0x04 && m.variant == 0)
        f.number("value", m.tail.data[1]);
    bytes(f, "tail", m.tail.data.data(), m.tail.size);
}
void add(Fields& f, const FunctionQuery& m) {
    address(f, m.at);
    f.number("function", m.function).text("asks", m.description ? "description" : "value");
}
void add(Fields& f, const FunctionDescription& m) {
    address(f, m.at);
    f.number("function", m.function).number("kind", m.kind).hex("icon", m.icon);
}
void add(Fields& f, const FunctionListEnd& m) {
    address(f, m.at);
    f.number("function", m.function);
}
void add(Fields& f, const FunctionValue& m) {
    address(f, m.at);
    f.number("function", m.function).number("value", m.value);
    if (m.function == 1)
        f.number("speed", m.value & 0x7F).text("direction", m.value & 0x80 ? "reverse" : "forward");
}
void add(Fields& f, const FunctionExtraQuery& m) {
    address(f, m.at);
    f.number("n", m.n);
}
void add(Fields& f, const FunctionExtraAnswer& m) {
    address(f, m.at);
    f.number("n", m.n).number("value", m.value);
}
void add(Fields& f, const AssignmentQuery& m) {
    address(f, m.at);
}
void add(Fields& f, const Throttle& m) {
    address(f, m.at);
    f.number("control", m.control).hex("state", m.state, 4).number("extra", m.extra);
}
void add(Fields& f, const Poll& m) {
    address(f, m.at);
    f.number("masterNode", m.masterNode);
}
void add(Fields& f, const PollAnswer& m) {
    address(f, m.at);
    f.hex("lead", m.lead).number("aboutNode", m.aboutNode).hex("uid", m.uid, 8);
}
void add(Fields& f, const MasterPoll& m) {
    address(f, m.at);
    f.number("aboutNode", m.aboutNode);
}
void add(Fields& f, const PollReply& m) {
    address(f, m.at);
    f.hex("uid", m.uid, 8);
}
void add(Fields& f, const FlashReady& m) {
    f.hex("uid", m.uid, 8);
}
void add(Fields& f, const FlashQuery& m) {
    f.number("flashHandle", m.handle).number("stage", m.stage).hex("uid", m.uid, 8);
}
void add(Fields& f, const FlashAnswer& m) {
    f.number("flashHandle", m.handle).number("stage", m.stage).hex("uid", m.uid, 8).hex("value", m.value, 8);
}
void add(Fields& f, const FlashStart& m) {
    f.number("flashHandle", m.handle).hex("uid", m.uid, 8).flag("abort", m.handle == 0);
}
void add(Fields& f, const FlashDataRequest& m) {
    f.number("flashHandle", m.handle).hex("offset", m.offset, 8).number("count", m.count);
}
void add(Fields& f, const FlashData& m) {
    f.number("flashHandle", m.handle).hex("offset", m.offset, 8);
    bytes(f, "bytes", m.bytes.data(), m.count);
}
void add(Fields& f, const FlashEnd& m) {
    f.number("flashHandle", m.handle).hex("uid", m.uid, 8);
}
void add(Fields& f, const Unknown& m) {
    const SessionId s = readSession(m.id);
    f.number("prio", s.prio).hex("handle", s.handle, 4).number("cmd", s.cmd).number("node", s.node);
    f.text("why", std::string(m.why));
}

// What the frame's handle is, when the roles know it: "object=loco loco=\"003 131-0\"".
void roleFields(std::vector<Field>& fields, const can::CanFrame& frame, const HandleRoles& roles) {
    const HandleRole role = roles.roleOf(frame);
    if (role == HandleRole::Unknown)
        return;
    fields.push_back({"object", 0, FieldFormat::Text, std::string(roleName(role)), 2});
    const SessionId s = readSession(frame.id);
    const std::string name = roles.name(s.node, s.handle);
    if (!name.empty())
        fields.push_back(
            {role == HandleRole::Loco ? "loco" : "slave", 0, FieldFormat::Text, printable(name), 2});
}

} // namespace

std::vector<Field> describe(const Message& message) {
    Fields fields;
    std::visit([&fields](const auto& m) { add(fields, m); }, message);
    return std::move(fields.list);
}

std::string printable(std::string_view bytes) {
    std::string text;
    for (const char c : bytes) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x20 && byte < 0x7F && c != '\\')
            text += c;
        else
            text += "\\x" + can::hexDigits(byte, 2);
    }
    return text;
}

FrameReport::FrameReport(const can::CanFrame& frame, const HandleRoles* roles)
    : frame_(frame), message_(roles ? roles->decode(frame) : decode(frame)), fields_(describe(message_)) {
    if (roles)
        roleFields(fields_, frame, *roles);
}

std::string FrameReport::detailText() const {
    return can::fieldsText(fields_);
}

std::string FrameReport::text() const {
    return can::reportText(frame_, name(), fields_);
}

std::string FrameReport::json() const {
    return can::reportJson(frame_, name(), fields_);
}

std::optional<std::uint64_t> FrameReport::number(std::string_view key) const {
    return can::fieldNumber(fields_, key);
}

} // namespace stellwerk::mcan
