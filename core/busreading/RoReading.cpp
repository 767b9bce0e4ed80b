#include "busreading/RoReading.h"

#include "ro/FrameReport.h"

namespace stellwerk::busreading {
namespace {

// An RO request or answer; the JSON names the module by its place in the bus profile.
class RoReading final : public FrameReading {
public:
    RoReading(const can::CanFrame& frame, BusProfile::RoFrame where)
        : report_(frame, where.direction), module_(where.module) {}

    std::string_view name() const override { return report_.name(); }
    bool decoded() const override { return report_.decoded(); }
    bool isResponse() const override { return report_.direction() == ro::Direction::Answer; }
    std::string detailText() const override { return report_.detailText(); }
    std::string text() const override { return report_.text(); }
    std::string json() const override {
        return "{\"protocol\":\"ro\",\"module\":" + std::to_string(module_) + "," + report_.json().substr(1);
    }
    std::optional<std::uint64_t> number(std::string_view key) const override { return report_.number(key); }

private:
    ro::FrameReport report_;
    std::size_t module_;
};

} // namespace

std::shared_ptr<const FrameReading> roReading(const can::CanFrame& frame, const BusProfile& profile) {
    const auto where = profile.roFrame(frame);
    return std::make_shared<const RoReading>(frame, where.value_or(BusProfile::RoFrame{}));
}

} // namespace stellwerk::busreading
