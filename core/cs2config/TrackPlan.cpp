#include "cs2config/TrackPlan.h"

#include "cs2config/Text.h"
#include "cs2config/TrackFields.h"
#include "cs2config/Values.h"

#include <map>

namespace stellwerk::cs2config {

namespace {

constexpr std::string_view recordVersion = "version";
constexpr std::string_view recordSize = "groesse";
constexpr std::string_view recordLastUsed = "zuletztBenutzt";
constexpr std::string_view keyWidth = "width";
constexpr std::string_view keyHeight = "height";
constexpr std::string_view keyName = "name";
constexpr std::string_view keyPage = "seite"; // the document's key for the last used page
constexpr std::string_view keyId = "id";
constexpr std::int64_t maxTiles = 256; // a position byte counts 0..255

constexpr std::string_view knownRecords[] = {recordVersion, recordSize, recordLastUsed,
                                             TrackPageEntry::keyword, TrackElement::keyword};
constexpr std::string_view singleRecords[] = {recordVersion, recordSize, recordLastUsed};
constexpr std::string_view sizeKeys[] = {keyWidth, keyHeight};
constexpr std::string_view lastUsedKeys[] = {keyName, keyPage};
constexpr std::string_view pageKeys[] = {keyId, keyName};

std::optional<TrackGridSize> readSize(const Document& document, Diagnostics* diagnostics) {
    const Node* record = document.record(recordSize);
    if (!record)
        return std::nullopt;
    const TrackFieldReader fields(*record, "groesse", diagnostics);
    return TrackGridSize{fields.optionalInteger(keyWidth, 1, maxTiles),
                         fields.optionalInteger(keyHeight, 1, maxTiles)};
}

std::optional<std::string> readLastUsed(const Document& document) {
    const Node* record = document.record(recordLastUsed);
    if (!record)
        return std::nullopt;
    const TrackFieldReader fields(*record, "zuletztBenutzt", nullptr);
    return fields.text(fields.has(keyName) || !fields.has(keyPage) ? keyName : keyPage);
}

TrackPageEntry readPage(const Node& record, Diagnostics* diagnostics) {
    const TrackFieldReader fields(record, "page", diagnostics);
    TrackPageEntry page;
    page.id = fields.integer(keyId, 0, 0, INT32_MAX);
    page.name = fields.text(keyName);
    page.source = record;
    return page;
}

// Reads the `seite` records and reports pages without a name and pages sharing an id or a name.
class PageListReader {
public:
    explicit PageListReader(Diagnostics& diagnostics) : diagnostics_(diagnostics) {}

    std::vector<TrackPageEntry> read(const std::vector<const Node*>& records) {
        std::vector<TrackPageEntry> pages;
        pages.reserve(records.size());
        for (const Node* record : records) {
            checkRecordKeys(*record, pageKeys, "page", unknownKeys_, diagnostics_);
            pages.push_back(readPage(*record, &diagnostics_));
            check(pages.back());
        }
        return pages;
    }

private:
    void check(const TrackPageEntry& page) {
        if (page.name.empty()) {
            diagnostics_.warning(page.line(), "page " + std::to_string(page.id) + " without .name",
                                 "kept; it has no page file to load");
        } else if (const auto [other, added] = names_.emplace(page.name, page.line()); !added) {
            diagnostics_.warning(page.line(),
                                 "second page named " + quoteForMessage(page.name) + " (also line " +
                                     std::to_string(other->second) + ")",
                                 "both are kept; they share one page file");
        }
        if (const auto [other, added] = ids_.emplace(page.id, page.line()); !added)
            diagnostics_.warning(
                page.line(),
                "second page with id " + std::to_string(page.id) + " (also line " +
                    std::to_string(other->second) + ")" +
                    (findField(page.source, keyId) ? "" : "; a page without .id counts as 0"),
                "both are kept");
    }

    Diagnostics& diagnostics_;
    ReportOnce unknownKeys_;
    std::map<std::int64_t, int> ids_;
    std::map<std::string, int, std::less<>> names_;
};

void checkSingleRecordKeys(const Document& document, Diagnostics& diagnostics) {
    ReportOnce unknownKeys;
    if (const Node* size = document.record(recordSize))
        checkRecordKeys(*size, sizeKeys, "groesse", unknownKeys, diagnostics);
    if (const Node* lastUsed = document.record(recordLastUsed))
        checkRecordKeys(*lastUsed, lastUsedKeys, "zuletztBenutzt", unknownKeys, diagnostics);
}

void checkLastUsed(const TrackPlan& plan, Diagnostics& diagnostics) {
    if (!plan.lastUsedPage || plan.lastUsed())
        return;
    const Node* record = plan.document.record(recordLastUsed);
    diagnostics.warning(record ? record->lineNumber() : 0,
                        "last used page " + quoteForMessage(*plan.lastUsedPage) + " is not in the page list",
                        "kept; no page is shown first");
}

void writeSize(Document& document, const std::optional<TrackGridSize>& size) {
    const std::optional<TrackGridSize> before = readSize(document, nullptr);
    if (before == size)
        return;
    if (!size) {
        document.replaceRecords(recordSize, {});
        return;
    }
    const Node* existing = document.record(recordSize);
    Node record = existing ? *existing : document.newRecord(recordSize);
    TrackFieldWriter fields(record, document.style());
    const auto update = [&fields](std::string_view key, std::optional<std::int64_t> value,
                                  std::optional<std::int64_t> old) {
        if (value == old)
            return;
        if (value)
            fields.setInteger(key, *value);
        else
            fields.remove(key);
    };
    update(keyWidth, size->width, before ? before->width : std::nullopt);
    update(keyHeight, size->height, before ? before->height : std::nullopt);
    replaceFirstRecord(document, recordSize, std::move(record));
}

void writeLastUsed(Document& document, const std::optional<std::string>& name) {
    if (readLastUsed(document) == name)
        return;
    if (!name) {
        document.replaceRecords(recordLastUsed, {});
        return;
    }
    const Node* existing = document.record(recordLastUsed);
    Node record = existing ? *existing : document.newRecord(recordLastUsed);
    const bool documentKey = existing && !findField(*existing, keyName) && findField(*existing, keyPage);
    TrackFieldWriter(record, document.style()).setText(documentKey ? keyPage : keyName, *name);
    replaceFirstRecord(document, recordLastUsed, std::move(record));
}

Node writePage(const TrackPageEntry& page, const Document& document) {
    const bool added = isNewRecord(page.source);
    Node record = editableRecord(page.source, document, TrackPageEntry::keyword);
    const TrackPageEntry before = readPage(record, nullptr);
    TrackFieldWriter fields(record, document.style());
    if (page.id != before.id)
        fields.setInteger(keyId, page.id, TrackFieldWriter::Base::Decimal, 0);
    if (added || page.name != before.name)
        fields.setText(keyName, page.name);
    return record;
}

} // namespace

TrackPlan TrackPlan::read(const Document& document, Diagnostics& diagnostics) {
    TrackPlan plan;
    plan.document = document;
    plan.format = checkTrackSection(document, section, "the track plan index", diagnostics);
    if (plan.format == TrackPlanFormat::Cs3Pixels) {
        plan.version = std::nullopt;
        plan.size = std::nullopt;
        return plan;
    }
    checkRecords(document, knownRecords, singleRecords, diagnostics);
    checkSingleRecordKeys(document, diagnostics);
    plan.version = readTrackVersion(document, &diagnostics);
    plan.size = readSize(document, &diagnostics);
    plan.lastUsedPage = readLastUsed(document);
    plan.pages = PageListReader(diagnostics).read(document.records(TrackPageEntry::keyword));
    plan.elements = TrackElementReader(diagnostics).read(document.records(TrackElement::keyword));
    checkLastUsed(plan, diagnostics);
    return plan;
}

Document TrackPlan::write() const {
    Document out = document;
    if (format == TrackPlanFormat::Cs3Pixels)
        return out;
    writeTrackVersion(out, version);
    writeSize(out, size);
    writeLastUsed(out, lastUsedPage);
    writeRecordsIfChanged(out, TrackPageEntry::keyword, pages,
                          [&](const TrackPageEntry& page) { return writePage(page, out); });
    const TrackElementWriter writer(out);
    writeRecordsIfChanged(out, TrackElement::keyword, elements,
                          [&](const TrackElement& element) { return writer.write(element); });
    return out;
}

const TrackPageEntry* TrackPlan::pageWithId(std::int64_t id) const {
    for (const TrackPageEntry& page : pages)
        if (page.id == id)
            return &page;
    return nullptr;
}

const TrackPageEntry* TrackPlan::pageNamed(std::string_view name) const {
    for (const TrackPageEntry& page : pages)
        if (page.name == name)
            return &page;
    return nullptr;
}

const TrackPageEntry* TrackPlan::lastUsed() const {
    if (!lastUsedPage)
        return nullptr;
    if (const TrackPageEntry* named = pageNamed(*lastUsedPage))
        return named;
    const std::optional<std::int64_t> number = parseInteger(*lastUsedPage);
    return number ? pageWithId(*number) : nullptr;
}

std::string toJson(const TrackPlan& plan) {
    JsonWriter json;
    writeJson(json, plan);
    return json.text();
}

void writeJson(JsonWriter& json, const TrackPlan& plan, std::string_view key) {
    json.beginObject(key);
    json.value("section", plan.document.section());
    json.value("format", trackPlanFormatName(plan.format));
    writeVersionJson(json, plan.version);
    if (plan.size) {
        json.beginObject("size");
        plan.size->width ? json.value("width", *plan.size->width) : json.null("width");
        plan.size->height ? json.value("height", *plan.size->height) : json.null("height");
        json.endObject();
    } else {
        json.null("size");
    }
    plan.lastUsedPage ? json.value("lastUsedPage", *plan.lastUsedPage) : json.null("lastUsedPage");
    json.beginArray("pages");
    for (const TrackPageEntry& page : plan.pages) {
        json.beginObject();
        json.value("line", page.line());
        json.value("id", page.id);
        json.value("name", page.name);
        json.endObject();
    }
    json.endArray();
    json.beginArray("elements");
    for (const TrackElement& element : plan.elements)
        writeJson(json, element);
    json.endArray();
    json.endObject();
}

} // namespace stellwerk::cs2config
