#include "cs2config/TrackElement.h"

#include "cs2config/Text.h"
#include "cs2config/TrackFields.h"
#include "cs2config/TrackFile.h"
#include "cs2config/Values.h"

#include <cstdint>
#include <map>

namespace stellwerk::cs2config {

namespace {

constexpr std::string_view keyId = "id";
constexpr std::string_view keyType = "typ";
constexpr std::string_view keyRotation = "drehung";
constexpr std::string_view keyArticle = "artikel";
constexpr std::string_view keyText = "text";
constexpr std::string_view keyDeviceId = "deviceId";
constexpr std::string_view keyState = "zustand";
constexpr std::string_view knownKeys[] = {keyId,   keyType,     keyRotation, keyArticle,
                                          keyText, keyDeviceId, keyState};
constexpr std::string_view textType = "text";

std::string describe(const TrackPosition& position) {
    return "page " + std::to_string(position.page) + ", column " + std::to_string(position.column) +
           ", row " + std::to_string(position.row);
}

TrackPosition readPosition(const TrackFieldReader& fields) {
    const std::optional<std::int64_t> id =
        fields.optionalInteger(keyId, INT64_MIN, INT64_MAX, "placed at column 0, row 0");
    if (!id)
        return {};
    if (const std::optional<TrackPosition> position = TrackPosition::fromId(*id))
        return *position;
    const std::string number = *id < 0 ? formatDecimal(*id) : formatHex(static_cast<std::uint64_t>(*id));
    fields.warn(keyId, "element .id " + number + " is outside 0x0..0xffffff (page, row, column)",
                "placed at column 0, row 0; the line is kept as it is");
    return {};
}

TrackElement readElement(const Node& record, Diagnostics* diagnostics) {
    const TrackFieldReader fields(record, "element", diagnostics);
    TrackElement element;
    element.position = readPosition(fields);
    element.type = fields.word(keyType);
    element.rotation = static_cast<int>(fields.integer(keyRotation, 0, 0, 3));
    element.article = fields.integer(keyArticle, -1, -1, INT32_MAX);
    element.text = fields.text(keyText);
    element.deviceId = fields.integer(keyDeviceId, 0, 0, UINT32_MAX);
    element.state = fields.integer(keyState, 0, 0, INT32_MAX);
    element.source = record;
    return element;
}

void reportType(const TrackElement& element, ReportOnce& unknownTypes, Diagnostics& diagnostics) {
    if (element.type.empty()) {
        if (element.text.empty())
            diagnostics.warning(element.line(), "element without .typ and without .text",
                                "kept; shown as an empty text tile");
        return;
    }
    if (!findTrackElementType(element.type) && unknownTypes.first(element.type))
        diagnostics.warning(element.line(),
                            "unknown element type " + quoteForMessage(element.type) +
                                " (not a CS2/CS3 type we know; reported once)",
                            "kept unchanged; shown as an unknown tile");
}

} // namespace

const TrackElementType* TrackElement::elementType() const {
    return findTrackElementType(type.empty() ? textType : std::string_view(type));
}

TrackCategory TrackElement::category() const {
    const TrackElementType* known = elementType();
    return known ? known->category : TrackCategory::Unknown;
}

ArticleLink TrackElement::articleLink() const {
    const TrackElementType* known = elementType();
    return known ? known->article : ArticleLink::None;
}

std::optional<std::int64_t> TrackElement::accessoryId() const {
    if (!hasArticle() || articleLink() != ArticleLink::Accessory)
        return std::nullopt;
    return article / 2;
}

bool TrackElement::switchable() const {
    const TrackElementType* known = elementType();
    return known && known->switchable();
}

std::vector<TrackElement> TrackElementReader::read(const std::vector<const Node*>& records) {
    ReportOnce unknownKeys;
    ReportOnce unknownTypes;
    std::vector<TrackElement> elements;
    elements.reserve(records.size());
    for (const Node* record : records) {
        checkRecordKeys(*record, knownKeys, "element", unknownKeys, diagnostics_);
        elements.push_back(readElement(*record, &diagnostics_));
        reportType(elements.back(), unknownTypes, diagnostics_);
    }
    reportMissingIds(elements);
    reportSharedPositions(elements);
    return elements;
}

TrackElement TrackElementReader::decode(const Node& record) {
    return readElement(record, nullptr);
}

void TrackElementReader::reportMissingIds(const std::vector<TrackElement>& elements) {
    const TrackElement* first = nullptr;
    std::size_t count = 0;
    for (const TrackElement& element : elements) {
        if (findField(element.source, keyId))
            continue;
        if (!first)
            first = &element;
        ++count;
    }
    if (first)
        diagnostics_.warning(first->line(),
                             std::to_string(count) +
                                 " element(s) without .id, the first one here (reported once)",
                             "placed at page 0, column 0, row 0 as a CS2 does");
}

void TrackElementReader::reportSharedPositions(const std::vector<TrackElement>& elements) {
    std::map<std::uint32_t, int> lines;
    for (const TrackElement& element : elements) {
        if (!findField(element.source, keyId))
            continue; // reported as missing .id
        const auto [place, added] = lines.emplace(element.position.toId(), element.line());
        if (!added)
            diagnostics_.warning(element.line(),
                                 "two elements at " + describe(element.position) + " (also line " +
                                     std::to_string(place->second) + ")",
                                 "both are kept; the later one is drawn on top");
    }
}

Node TrackElementWriter::write(const TrackElement& element) const {
    using Base = TrackFieldWriter::Base;
    const bool added = isNewRecord(element.source);
    Node record = editableRecord(element.source, document_, TrackElement::keyword);
    const TrackElement before = TrackElementReader::decode(record);
    TrackFieldWriter fields(record, document_.style());
    // A CS2 writes `.id` first, and leaves it out at the origin.
    if (element.position != before.position)
        fields.setIntegerFirst(keyId, element.position.toId(), Base::Hex, 0);
    if (element.type != before.type)
        fields.setOptionalText(keyType, element.type);
    if (element.rotation != before.rotation)
        fields.setInteger(keyRotation, element.rotation, Base::Decimal, 0);
    // A CS2 writes `.artikel` on every element, -1 included.
    if (added || element.article != before.article)
        fields.setInteger(keyArticle, element.article, Base::Decimal,
                          added ? std::nullopt : std::optional<std::int64_t>(-1));
    if (element.text != before.text)
        fields.setOptionalText(keyText, element.text);
    if (element.deviceId != before.deviceId)
        fields.setInteger(keyDeviceId, element.deviceId, Base::Hex, 0);
    if (element.state != before.state)
        fields.setInteger(keyState, element.state, Base::Decimal, 0);
    return record;
}

void writeJson(JsonWriter& json, const TrackElement& element) {
    json.beginObject();
    json.value("line", element.line());
    json.value("page", int{element.position.page});
    // x = column, y = row, as `stellwerk-cli cs2 json` promises and renderers use them.
    json.value("x", int{element.position.column});
    json.value("y", int{element.position.row});
    json.value("id", formatHex(element.position.toId()));
    if (element.type.empty())
        json.null("type");
    else
        json.value("type", element.type);
    json.value("category", trackCategoryName(element.category()));
    json.value("switchable", element.switchable());
    json.value("rotation", element.rotation);
    json.value("article", element.article);
    json.value("articleLink", articleLinkName(element.articleLink()));
    json.value("text", element.text);
    json.value("deviceId", element.deviceId);
    json.value("state", element.state);
    json.endObject();
}

} // namespace stellwerk::cs2config
