#include "cs2config/TrackFile.h"

#include "cs2config/TrackFields.h"

#include <algorithm>
#include <utility>

namespace stellwerk::cs2config {

namespace {

constexpr std::string_view keyVersion = "version";
constexpr std::string_view keyMajor = "major";
constexpr std::string_view keyMinor = "minor";
constexpr std::string_view sectionCs3 = "conf";

bool contains(std::span<const std::string_view> list, std::string_view word) {
    return std::find(list.begin(), list.end(), word) != list.end();
}

} // namespace

void checkRecords(const Document& document, std::span<const std::string_view> known,
                  std::span<const std::string_view> single, Diagnostics& diagnostics) {
    ReportOnce unknown;
    std::vector<std::string_view> seen;
    for (const Node& node : document.topLevel()) {
        if (!node.isEntry())
            continue;
        const std::string_view keyword = node.key();
        if (!contains(known, keyword)) {
            if (unknown.first(keyword))
                diagnostics.warning(node.lineNumber(),
                                    "unknown record '" + std::string(keyword) + "' (reported once)",
                                    "kept unchanged");
            continue;
        }
        if (!contains(single, keyword))
            continue;
        if (contains(seen, keyword))
            diagnostics.warning(node.lineNumber(), "second '" + std::string(keyword) + "' record",
                                "the first one is used; both are kept");
        else
            seen.push_back(keyword);
    }
}

TrackPlanFormat checkTrackSection(const Document& document, std::string_view expected,
                                  std::string_view fileKind, Diagnostics& diagnostics) {
    if (!document.hasHeader())
        return TrackPlanFormat::Cs2Grid;
    const std::string_view section = document.section();
    if (section == sectionCs3) {
        diagnostics.error(1,
                          "CS3 track plan format (pixel coordinates) is not supported; only the CS2 grid "
                          "format ([gleisbild], [gleisbildseite]) is read",
                          "the file is kept unchanged and no elements are read");
        return TrackPlanFormat::Cs3Pixels;
    }
    if (section != expected)
        diagnostics.warning(
            1, "section [" + std::string(section) + "] where [" + std::string(expected) + "] was expected",
            "read as " + std::string(fileKind) + " anyway");
    return TrackPlanFormat::Cs2Grid;
}

std::optional<TrackFileVersion> readTrackVersion(const Document& document, Diagnostics* diagnostics) {
    const Node* record = document.record(keyVersion);
    if (!record)
        return std::nullopt;
    const TrackFieldReader fields(*record, "version", diagnostics);
    TrackFileVersion version;
    version.major = fields.integer(keyMajor, 0, 0, INT32_MAX);
    version.minor = fields.integer(keyMinor, 0, 0, INT32_MAX);
    return version;
}

void writeTrackVersion(Document& document, const std::optional<TrackFileVersion>& version) {
    if (readTrackVersion(document, nullptr) == version)
        return;
    if (!version) {
        document.replaceRecords(keyVersion, {});
        return;
    }
    const Node* existing = document.record(keyVersion);
    Node record = existing ? *existing : document.newRecord(keyVersion);
    TrackFieldWriter fields(record, document.style());
    // A new record always says its major version, as every real file does.
    fields.setInteger(keyMajor, version->major, TrackFieldWriter::Base::Decimal,
                      existing ? std::optional<std::int64_t>(0) : std::nullopt);
    fields.setInteger(keyMinor, version->minor, TrackFieldWriter::Base::Decimal, 0);
    replaceFirstRecord(document, keyVersion, std::move(record));
}

void writeVersionJson(JsonWriter& json, const std::optional<TrackFileVersion>& version) {
    if (!version) {
        json.null("version");
        return;
    }
    json.beginObject("version");
    json.value("major", version->major);
    json.value("minor", version->minor);
    json.endObject();
}

std::string_view trackPlanFormatName(TrackPlanFormat format) {
    return format == TrackPlanFormat::Cs2Grid ? "cs2-grid" : "cs3-pixels";
}

void replaceFirstRecord(Document& document, std::string_view keyword, Node record) {
    const std::vector<const Node*> current = std::as_const(document).records(keyword);
    std::vector<Node> records;
    records.reserve(std::max<std::size_t>(current.size(), 1));
    records.push_back(std::move(record));
    for (std::size_t i = 1; i < current.size(); ++i)
        records.push_back(*current[i]);
    document.replaceRecords(keyword, std::move(records));
}

Node editableRecord(const Node& source, const Document& document, std::string_view keyword) {
    return isNewRecord(source) ? document.newRecord(keyword) : source;
}

void replaceRecordsIfChanged(Document& document, std::string_view keyword, std::vector<Node> records) {
    const std::vector<const Node*> current = std::as_const(document).records(keyword);
    const bool same =
        current.size() == records.size() &&
        std::equal(current.begin(), current.end(), records.begin(),
                   [](const Node* a, const Node& b) { return a->serialize() == b.serialize(); });
    if (!same)
        document.replaceRecords(keyword, std::move(records));
}

} // namespace stellwerk::cs2config
