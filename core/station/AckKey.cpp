#include "station/AckKey.h"

#include <cstring>
#include <type_traits>

namespace stellwerk::station {
namespace {

using namespace cs2;

template <class... Ts>
struct Overloaded : Ts... {
    using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

constexpr std::uint8_t code(Command command) {
    return std::uint8_t(command);
}

AckKey systemKey(const MessageBody& body, std::uint32_t subject, std::uint32_t detail = 0) {
    return {code(Command::System), systemSubcommand(body).value_or(0), subject, detail};
}

AckKey fileKey(const ConfigDataRequest& request) {
    std::uint32_t first = 0;
    std::uint32_t second = 0;
    for (std::size_t i = 0; i < 4; ++i) {
        first = first << 8 | std::uint8_t(request.filename[i]);
        second = second << 8 | std::uint8_t(request.filename[i + 4]);
    }
    return {code(Command::ConfigDataRequest), 0, first, second};
}

std::optional<AckKey> locoKey(const MessageBody& body) {
    return std::visit(Overloaded{
                          [](const LocoSpeed& m) -> std::optional<AckKey> {
                              return AckKey{code(m.command), 0, m.loco.value()};
                          },
                          [](const LocoDirection& m) -> std::optional<AckKey> {
                              return AckKey{code(m.command), 0, m.loco.value()};
                          },
                          [](const LocoFunction& m) -> std::optional<AckKey> {
                              return AckKey{code(m.command), 0, m.loco.value(), m.function};
                          },
                          [](const ConfigRead& m) -> std::optional<AckKey> {
                              return AckKey{code(m.command), 0, m.loco.value(), m.cv.packed()};
                          },
                          [](const ConfigWrite& m) -> std::optional<AckKey> {
                              return AckKey{code(m.command), 0, m.loco.value(), m.cv.packed()};
                          },
                          [](const MfxBind& m) -> std::optional<AckKey> {
                              return AckKey{code(m.command), 0, m.mfxUid};
                          },
                          [](const MfxVerify& m) -> std::optional<AckKey> {
                              return AckKey{code(m.command), 0, m.mfxUid};
                          },
                          [](const AccessorySwitch& m) -> std::optional<AckKey> {
                              return AckKey{code(m.command), 0, m.article.value(), m.position};
                          },
                          [](const auto&) -> std::optional<AckKey> { return std::nullopt; },
                      },
                      body);
}

std::optional<AckKey> systemKey(const MessageBody& body) {
    return std::visit(
        Overloaded{
            [&](const SystemStop& m) -> std::optional<AckKey> { return systemKey(body, m.target); },
            [&](const SystemGo& m) -> std::optional<AckKey> { return systemKey(body, m.target); },
            [&](const SystemHalt& m) -> std::optional<AckKey> { return systemKey(body, m.target); },
            [&](const LocoEmergencyStop& m) -> std::optional<AckKey> {
                return systemKey(body, m.loco.value());
            },
            [&](const LocoCycleEnd& m) -> std::optional<AckKey> { return systemKey(body, m.loco.value()); },
            [&](const LocoProtocol& m) -> std::optional<AckKey> { return systemKey(body, m.loco.value()); },
            [&](const AccessorySwitchTime& m) -> std::optional<AckKey> { return systemKey(body, m.target); },
            [&](const TrackProtocols& m) -> std::optional<AckKey> { return systemKey(body, m.target); },
            [&](const MfxRegistrationCounter& m) -> std::optional<AckKey> {
                return systemKey(body, m.target);
            },
            [&](const SystemStatus& m) -> std::optional<AckKey> {
                return systemKey(body, m.device, m.channel);
            },
            [&](const DeviceId& m) -> std::optional<AckKey> { return systemKey(body, m.target); },
            [&](const SystemReset& m) -> std::optional<AckKey> { return systemKey(body, m.target); },
            [](const auto&) -> std::optional<AckKey> { return std::nullopt; },
        },
        body);
}

std::optional<AckKey> otherKey(const MessageBody& body) {
    return std::visit(Overloaded{
                          [](const S88Event& m) -> std::optional<AckKey> {
                              return AckKey{code(m.command), 0, std::uint32_t(m.device) << 16 | m.contact};
                          },
                          [](const StatusDataConfig& m) -> std::optional<AckKey> {
                              if (m.form == StatusDataConfig::Form::Packet)
                                  return std::nullopt;
                              return AckKey{code(m.command), 0, m.device, m.index};
                          },
                          [](const ConfigDataRequest& m) -> std::optional<AckKey> { return fileKey(m); },
                          [](const auto&) -> std::optional<AckKey> { return std::nullopt; },
                      },
                      body);
}

} // namespace

std::optional<AckKey> ackKeyOf(const cs2::Message& message) {
    if (auto key = locoKey(message.body))
        return key;
    if (auto key = systemKey(message.body))
        return key;
    return otherKey(message.body);
}

bool isRejection(const cs2::Message& answer) {
    return std::visit(Overloaded{
                          [](const SystemStatus& m) { return !m.value && !m.accepted.value_or(false); },
                          [](const ConfigRead& m) { return !m.value.has_value(); },
                          [](const ConfigWrite& m) { return (m.flags & ConfigWrite::WriteOk) == 0; },
                          [](const MfxVerify& m) { return m.sid == 0; },
                          [](const auto&) { return false; },
                      },
                      answer.body);
}

} // namespace stellwerk::station
