#include "busreading/OrcReading.h"

#include "orc/FrameReport.h"

namespace stellwerk::busreading {
namespace {

class OrcReading final : public FrameReading {
public:
    explicit OrcReading(const can::CanFrame& frame) : report_(frame), answer_(orc::readId(frame.id).answer) {}

    std::string_view name() const override { return report_.name(); }
    bool decoded() const override { return report_.decoded(); }
    // D=1: an answer, or an event (the document's "Antwort / Event").
    bool isResponse() const override { return answer_; }
    std::string detailText() const override { return report_.detailText(); }
    std::string text() const override { return report_.text(); }
    std::string json() const override { return "{\"protocol\":\"orc\"," + report_.json().substr(1); }
    std::optional<std::uint64_t> number(std::string_view key) const override { return report_.number(key); }

private:
    orc::FrameReport report_;
    bool answer_;
};

} // namespace

std::shared_ptr<const FrameReading> orcReading(const can::CanFrame& frame) {
    return std::make_shared<const OrcReading>(frame);
}

} // namespace stellwerk::busreading
