#include "busreading/McanReading.h"

#include "busreading/BusContext.h"
#include "mcan/FrameReport.h"

#include <variant>

namespace stellwerk::busreading {
namespace {

std::optional<Handheld> handheldOf(const can::CanFrame& frame, const mcan::Message& message,
                                   const BusContext* context) {
    const auto node = handheldNodeOf(frame, message);
    if (!node)
        return std::nullopt;
    return Handheld{*node, context ? context->handheldName(*node) : std::string()};
}

class McanReading final : public FrameReading {
public:
    McanReading(const can::CanFrame& frame, const BusContext* context)
        : report_(frame, context ? &context->handleRoles() : nullptr),
          handheld_(handheldOf(frame, report_.message(), context)) {}

    std::string_view name() const override { return report_.name(); }
    bool decoded() const override { return report_.decoded(); }
    // M-CAN has no response bit: an answer echoes the request from the other node of the pair, which the
    // field from=master|slave says.
    bool isResponse() const override { return false; }
    std::string detailText() const override { return report_.detailText(); }
    std::string text() const override { return report_.text(); }
    std::string json() const override { return "{\"protocol\":\"mcan\"," + report_.json().substr(1); }
    std::optional<std::uint64_t> number(std::string_view key) const override { return report_.number(key); }
    std::optional<Handheld> handheld() const override { return handheld_; }

private:
    mcan::FrameReport report_;
    std::optional<Handheld> handheld_;
};

} // namespace

std::shared_ptr<const FrameReading> mcanReading(const can::CanFrame& frame, const BusContext* context) {
    return std::make_shared<const McanReading>(frame, context);
}

std::optional<std::uint8_t> handheldNodeOf(const can::CanFrame& frame, const mcan::Message& message) {
    std::uint8_t node = std::uint8_t(frame.id & 0x7F);
    if (const auto* grant = std::get_if<mcan::LoginGrant>(&message))
        node = grant->node;
    else if (std::holds_alternative<mcan::BusBusy>(message) ||
             mcan::layoutOf(frame.id) != mcan::Layout::Session)
        return std::nullopt;
    const auto slave = std::uint8_t(node | 1);
    return mcan::isSlaveNode(slave) ? std::optional(slave) : std::nullopt;
}

} // namespace stellwerk::busreading
