#include "cs2config/TrackPage.h"

#include <algorithm>

namespace stellwerk::cs2config {

namespace {

constexpr std::string_view knownRecords[] = {"version", TrackElement::keyword};
constexpr std::string_view singleRecords[] = {"version"};

} // namespace

TrackPage TrackPage::read(const Document& document, Diagnostics& diagnostics) {
    TrackPage page;
    page.document = document;
    page.format = checkTrackSection(document, section, "a track plan page", diagnostics);
    if (page.format == TrackPlanFormat::Cs3Pixels) {
        page.version = std::nullopt;
        return page;
    }
    checkRecords(document, knownRecords, singleRecords, diagnostics);
    page.version = readTrackVersion(document, &diagnostics);
    page.elements = TrackElementReader(diagnostics).read(document.records(TrackElement::keyword));
    return page;
}

Document TrackPage::write() const {
    Document out = document;
    if (format == TrackPlanFormat::Cs3Pixels)
        return out;
    writeTrackVersion(out, version);
    const TrackElementWriter writer(out);
    writeRecordsIfChanged(out, TrackElement::keyword, elements,
                          [&](const TrackElement& element) { return writer.write(element); });
    return out;
}

std::optional<TrackArea> TrackPage::area() const {
    if (elements.empty())
        return std::nullopt;
    const TrackPosition& first = elements.front().position;
    TrackArea area{first.column, first.row, first.column, first.row};
    for (const TrackElement& element : elements) {
        area.left = std::min<int>(area.left, element.position.column);
        area.top = std::min<int>(area.top, element.position.row);
        area.right = std::max<int>(area.right, element.position.column);
        area.bottom = std::max<int>(area.bottom, element.position.row);
    }
    return area;
}

std::string toJson(const TrackPage& page) {
    JsonWriter json;
    writeJson(json, page);
    return json.text();
}

void writeJson(JsonWriter& json, const TrackPage& page, std::string_view key) {
    json.beginObject(key);
    json.value("section", page.document.section());
    json.value("format", trackPlanFormatName(page.format));
    writeVersionJson(json, page.version);
    if (const std::optional<TrackArea> area = page.area()) {
        json.beginObject("area");
        json.value("left", area->left);
        json.value("top", area->top);
        json.value("right", area->right);
        json.value("bottom", area->bottom);
        json.value("columns", area->columns());
        json.value("rows", area->rows());
        json.endObject();
    } else {
        json.null("area");
    }
    json.beginArray("elements");
    for (const TrackElement& element : page.elements)
        writeJson(json, element);
    json.endArray();
    json.endObject();
}

} // namespace stellwerk::cs2config
