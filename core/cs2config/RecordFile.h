#pragma once

#include "cs2config/AccessoryRecordSupport.h"
#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"
#include "cs2config/JsonWriter.h"
#include "cs2config/Node.h"

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

// The skeleton that magnetartikel.cs2, magnetartikel.sr2 and fahrstrassen.cs2 share: a version record and
// records of one keyword read into typed items, written back in their places, found by id, shown as JSON.
// Each file model states what differs in one RecordFileKind; the functions here do the rest.
namespace stellwerk::cs2config::accessories {

// What one kind of record file is made of. `File` has static `section` and `recordKeyword`, a `document`
// and `versionMajor`/`versionMinor`; `items` names its vector of typed items.
template <class File, class Item>
struct RecordFileKind {
    std::vector<Item> File::*items;
    std::string_view readAs;    // "read as <readAs>" when the file has another section header
    std::string_view fileName;  // the JSON's "file"
    std::string_view jsonItems; // the JSON key of the items' array
    Item (*read)(const Node& record, OnceReporter& reporter);
    Node (*write)(const Item& item, const Document& document);
    void (*writeJson)(JsonWriter& json, const Item& item);
};

// Reads the version record and hands every `keyword` record to `read`, in file order; other records and
// lines outside any record are reported once.
template <class Read>
FileVersion readRecords(const Document& document, std::string_view keyword, OnceReporter& reporter,
                        Read read) {
    const FileVersion version = readVersion(document, reporter);
    for (const Node& node : document.topLevel()) {
        if (!node.isEntry())
            continue;
        if (node.level() > 0)
            reporter.strayLine(node);
        else if (node.key() == keyword)
            read(node);
        else if (node.key() != "version")
            reporter.unknownRecord(node);
    }
    return version;
}

// The document with its version record updated and its `keyword` records replaced by `write(item, document)`
// of each item, in order.
template <class Item, class Write>
Document writeRecords(const Document& document, const FileVersion& version, std::string_view keyword,
                      const std::vector<Item>& items, Write write) {
    Document out = document;
    writeVersion(out, version);
    std::vector<Node> records;
    records.reserve(items.size());
    for (const Item& item : items)
        records.push_back(write(item, out));
    out.replaceRecords(keyword, std::move(records));
    return out;
}

// The model of `document`: its section checked, its version and every record of the kind's keyword read;
// the file-specific checks over all items are left to the caller.
template <class File, class Item>
File readRecordFile(const RecordFileKind<File, Item>& kind, const Document& document,
                    Diagnostics& diagnostics) {
    File file;
    file.document = document;
    checkSection(document, File::section, kind.readAs, diagnostics);
    OnceReporter reporter(diagnostics);
    const FileVersion version = readRecords(document, File::recordKeyword, reporter, [&](const Node& record) {
        (file.*kind.items).push_back(kind.read(record, reporter));
    });
    file.versionMajor = version.major;
    file.versionMinor = version.minor;
    return file;
}

// The file's source document with each item's record updated; unchanged items keep their bytes.
template <class File, class Item>
Document writeRecordFile(const RecordFileKind<File, Item>& kind, const File& file) {
    return writeRecords(file.document, {file.versionMajor, file.versionMinor}, File::recordKeyword,
                        file.*kind.items, kind.write);
}

// {"file", "version", <jsonItems>: [...]} for `stellwerk-cli cs2 json`.
template <class File, class Item>
std::string recordFileJson(const RecordFileKind<File, Item>& kind, const File& file) {
    JsonWriter json;
    json.beginObject();
    json.value("file", kind.fileName);
    writeVersionJson(json, {file.versionMajor, file.versionMinor});
    json.beginArray(kind.jsonItems);
    for (const Item& item : file.*kind.items)
        kind.writeJson(json, item);
    json.endArray();
    json.endObject();
    return json.text();
}

// The first item with this `.id`, or null.
template <class Item>
const Item* findById(const std::vector<Item>& items, std::int64_t id) {
    for (const Item& item : items)
        if (item.id == id)
            return &item;
    return nullptr;
}

// The line of the first item of each id; `repeated(item, firstLine)` is called for every later item with
// an id seen before, in file order.
template <class Item, class Repeated>
std::map<std::int64_t, int> firstLineOfEachId(const std::vector<Item>& items, Repeated repeated) {
    std::map<std::int64_t, int> firstLine;
    for (const Item& item : items) {
        const auto [first, inserted] = firstLine.emplace(item.id, item.lineNumber());
        if (!inserted)
            repeated(item, first->second);
    }
    return firstLine;
}

} // namespace stellwerk::cs2config::accessories
