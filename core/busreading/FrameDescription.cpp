#include "busreading/FrameDescription.h"

#include "busreading/McanReading.h"
#include "busreading/OrcReading.h"
#include "busreading/RoReading.h"
#include "can/FrameText.h"
#include "cs2/Fields.h"
#include "cs2/FrameReport.h"
#include "cs2/LocId.h"
#include "mcan/Messages.h"
#include "orc/Messages.h"
#include "ro/FrameReport.h"

#include <cctype>
#include <charconv>
#include <iterator>

namespace stellwerk::busreading {
namespace {

// A CS2 frame, read by the CS2 codec's report.
class Cs2Reading final : public FrameReading {
public:
    explicit Cs2Reading(const can::CanFrame& frame) : report_(frame), response_(cs2::isResponse(frame)) {}

    std::string_view name() const override { return report_.name(); }
    bool decoded() const override { return report_.ok(); }
    bool isResponse() const override { return response_; }
    std::string detailText() const override { return report_.detailText(); }
    std::string text() const override { return report_.text(); }
    std::string json() const override { return "{\"protocol\":\"cs2\"," + report_.json().substr(1); }
    std::optional<std::uint64_t> number(std::string_view key) const override {
        if (!report_.ok())
            return std::nullopt;
        for (const cs2::Field& field : cs2::describe(report_.result().value()))
            if (field.key == key && field.format != cs2::FieldFormat::Text)
                return field.number;
        return std::nullopt;
    }

private:
    cs2::FrameReport report_;
    bool response_;
};

// "CS2", "CS2/M-CAN": the protocols a bus expects, as a person names them, in a fixed order; empty for none.
std::string protocolTitles(const BusProfile& profile) {
    static constexpr std::string_view titleOf[] = {"CS2", "M-CAN", "OpenRailCAN",
                                                   "RO"}; // by Protocol, Foreign left out
    std::string titles;
    for (std::size_t protocol = 0; protocol < std::size(titleOf); ++protocol)
        if (profile.expects(Protocol(protocol)))
            titles += (titles.empty() ? "" : "/") + std::string(titleOf[protocol]);
    return titles;
}

// A frame no protocol of the bus claims: shown with its identifier and bytes, never decoded.
class ForeignReading final : public FrameReading {
public:
    ForeignReading(const can::CanFrame& frame, const BusProfile& profile)
        : frame_(frame), expected_(protocolTitles(profile)) {}

    std::string_view name() const override { return "foreign"; }
    bool decoded() const override { return false; }
    bool isResponse() const override { return false; }
    std::string detailText() const override {
        const std::string why =
            expected_.empty() ? "no protocol expected on this bus" : "no protocol of a " + expected_ + " bus";
        return std::string(frame_.extended ? "29-bit" : "11-bit") + " frame (" + why + ")";
    }
    std::string text() const override { return can::formatDocument(frame_) + "  foreign " + detailText(); }
    std::string json() const override {
        const std::string candump = can::formatCandump(frame_);
        const std::size_t hash = candump.find('#');
        return "{\"protocol\":\"foreign\",\"id\":\"" + candump.substr(0, hash) +
               "\",\"extended\":" + (frame_.extended ? "true" : "false") +
               ",\"dlc\":" + std::to_string(frame_.dlc) + ",\"data\":\"" + candump.substr(hash + 1) + "\"}";
    }
    std::optional<std::uint64_t> number(std::string_view) const override { return std::nullopt; }

private:
    can::CanFrame frame_;
    std::string expected_;
};

std::shared_ptr<const FrameReading> readingOf(const can::CanFrame& frame, Protocol protocol,
                                              const BusProfile& profile, const BusContext* context) {
    switch (protocol) {
    case Protocol::Cs2:
        return std::make_shared<const Cs2Reading>(frame);
    case Protocol::Mcan:
        return mcanReading(frame, context);
    case Protocol::Orc:
        return orcReading(frame);
    case Protocol::Ro:
        return roReading(frame, profile);
    case Protocol::Foreign:
        break;
    }
    return std::make_shared<const ForeignReading>(frame, profile);
}

std::optional<std::uint32_t> parseNumber(std::string_view word) {
    int base = 10;
    if (word.size() > 2 && word[0] == '0' && (word[1] == 'x' || word[1] == 'X')) {
        word.remove_prefix(2);
        base = 16;
    }
    std::uint32_t value = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value, base);
    if (error != std::errc() || end != word.data() + word.size() || word.empty())
        return std::nullopt;
    return value;
}

std::vector<std::string> words(std::string_view text) {
    std::vector<std::string> found;
    std::string current;
    for (const char c : text) {
        if (std::isspace(static_cast<unsigned char>(c))) {
            if (!current.empty())
                found.push_back(std::move(current));
            current.clear();
        } else {
            current += char(std::tolower(static_cast<unsigned char>(c)));
        }
    }
    if (!current.empty())
        found.push_back(std::move(current));
    return found;
}

} // namespace

FrameDescription::FrameDescription(const can::CanFrame& frame, const BusProfile& profile,
                                   const BusContext* context)
    : frame_(frame), protocol_(classify(frame, profile)),
      reading_(readingOf(frame, protocol_, profile, context)) {}

std::string FrameDescription::frameText() const {
    return can::formatDocument(frame_);
}

// The CS2's names first, then M-CAN's, OpenRailCAN's and RO's, whatever order the profile asks them in.
std::vector<std::string_view> messageNames(const BusProfile& profile) {
    std::vector<std::string_view> names;
    if (profile.expects(Protocol::Cs2))
        names = cs2::messageNames();
    if (profile.expects(Protocol::Mcan)) {
        const std::vector<std::string_view> mcanNames = mcan::messageNames();
        names.insert(names.end(), mcanNames.begin(), mcanNames.end());
    }
    if (profile.expects(Protocol::Orc)) {
        const std::vector<std::string_view> orcNames = orc::messageNames();
        names.insert(names.end(), orcNames.begin(), orcNames.end());
    }
    if (profile.expects(Protocol::Ro)) {
        const std::vector<std::string_view> roNames = ro::messageNames();
        names.insert(names.end(), roNames.begin(), roNames.end());
    }
    return names;
}

std::optional<std::uint32_t> parseLocoReference(std::string_view text) {
    const std::vector<std::string> parts = words(text);
    if (parts.size() == 1)
        return parseNumber(parts.front());
    if (parts.size() != 2)
        return std::nullopt;
    const auto protocol = cs2::protocolFromName(parts[0]);
    const auto address = parseNumber(parts[1]);
    if (!protocol || !address || parts[1].starts_with("0x"))
        return std::nullopt;
    const auto locId = cs2::LocId::fromAddress(*protocol, *address);
    return locId ? std::optional<std::uint32_t>(locId->value()) : std::nullopt;
}

} // namespace stellwerk::busreading
