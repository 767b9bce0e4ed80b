#include "cs2config/AccessoryFile.h"

#include "cs2config/AccessoryAddressCheck.h"
#include "cs2config/AccessoryRecordSupport.h"
#include "cs2config/JsonWriter.h"
#include "cs2config/RecordEditor.h"
#include "cs2config/RecordFile.h"
#include "cs2config/Text.h"

namespace stellwerk::cs2config {

namespace {

using accessories::OnceReporter;
using accessories::RecordReader;
using accessories::RecordWriter;
using accessories::writeOptional;

constexpr std::string_view recordName = "artikel record";

std::string positionList(const AccessoryTypeInfo& type) {
    std::string list;
    for (int position = 0; position < 32; ++position) {
        if (!type.acceptsPosition(position))
            continue;
        list += list.empty() ? "" : ", ";
        list += std::to_string(position);
    }
    return list;
}

void checkType(const Accessory& accessory, OnceReporter& reporter) {
    Diagnostics& diagnostics = reporter.diagnostics();
    if (!accessory.source.find("typ")) {
        diagnostics.warning(accessory.lineNumber(), "artikel without .typ", "kept; taken as one address");
        return;
    }
    const AccessoryTypeInfo* type = accessory.typeInfo();
    if (!type) {
        reporter.once("type " + accessory.type, accessory.source.find("typ")->lineNumber(),
                      "unknown accessory type " + quoteForMessage(accessory.type),
                      "kept; taken as one address; reported once for the whole file");
        return;
    }
    if (type->acceptsPosition(accessory.position))
        return;
    const Node* line = accessory.source.find("stellung");
    diagnostics.warning(line ? line->lineNumber() : accessory.lineNumber(),
                        "position " + std::to_string(accessory.position) + " of accessory " +
                            std::to_string(accessory.id) + " is not one of the positions of " +
                            std::string(type->key) + " (" + positionList(*type) + ")",
                        "kept");
}

void checkProtocol(const Accessory& accessory, OnceReporter& reporter) {
    if (accessory.protocol.empty() || accessory.protocol == "mm2" || accessory.protocol == "dcc")
        return;
    reporter.once("dectyp " + accessory.protocol, accessory.source.find("dectyp")->lineNumber(),
                  "unknown decoder protocol .dectyp=" + quoteForMessage(accessory.protocol),
                  "kept; reported once for the whole file");
}

Accessory readAccessory(const Node& record, OnceReporter& reporter) {
    reporter.checkKeys(record, "artikel records",
                       {"id", "name", "typ", "stellung", "schaltzeit", "ungerade", "decoder", "dectyp"});
    RecordReader reader(record, recordName, reporter.diagnostics());
    Accessory accessory;
    accessory.source = record;
    accessory.id = reader.required("id");
    accessory.name = reader.text("name");
    accessory.type = reader.keyword("typ");
    accessory.position = reader.integer("stellung", 0);
    accessory.switchTimeMs = reader.optionalInteger("schaltzeit");
    accessory.secondOutput = reader.integer("ungerade", 0) != 0;
    accessory.decoder = reader.keyword("decoder");
    accessory.protocol = reader.keyword("dectyp");
    checkType(accessory, reporter);
    checkProtocol(accessory, reporter);
    return accessory;
}

Node writeRecord(const Accessory& accessory, const Document& document) {
    Node record = accessories::recordFrom(accessory.source, document, AccessoryFile::recordKeyword);
    RecordWriter writer(record, accessory.source, document.style());
    writer.required("id", accessory.id);
    writer.optionalText("name", accessory.name);
    writer.optionalKeyword("typ", accessory.type);
    writer.integer("stellung", accessory.position, 0);
    writer.optionalInteger("schaltzeit", accessory.switchTimeMs);
    writer.flag("ungerade", accessory.secondOutput);
    writer.optionalKeyword("decoder", accessory.decoder);
    writer.optionalKeyword("dectyp", accessory.protocol);
    return record;
}

void writeAccessoryJson(JsonWriter& json, const Accessory& accessory) {
    const AccessoryTypeInfo* type = accessory.typeInfo();
    json.beginObject();
    json.value("line", accessory.lineNumber());
    json.value("id", accessory.id);
    json.value("name", accessory.name);
    json.value("type", accessory.type);
    json.value("knownType", type != nullptr);
    json.value("addresses", accessory.addressCount());
    if (type)
        json.value("positions", type->positions);
    else
        json.null("positions");
    json.value("position", accessory.position);
    writeOptional(json, "switchTimeMs", accessory.switchTimeMs);
    json.value("secondOutput", accessory.secondOutput);
    json.value("decoder", accessory.decoder);
    json.value("protocol", accessory.protocol);
    json.endObject();
}

constexpr accessories::RecordFileKind<AccessoryFile, Accessory> kind{.items = &AccessoryFile::accessories,
                                                                     .readAs = "accessories",
                                                                     .fileName = "magnetartikel.cs2",
                                                                     .jsonItems = "accessories",
                                                                     .read = readAccessory,
                                                                     .write = writeRecord,
                                                                     .writeJson = writeAccessoryJson};

} // namespace

int Accessory::addressCount() const {
    const AccessoryTypeInfo* info = typeInfo();
    return info ? info->addresses : 1;
}

AccessoryFile AccessoryFile::read(const Document& document, Diagnostics& diagnostics) {
    AccessoryFile file = accessories::readRecordFile(kind, document, diagnostics);
    checkAccessoryAddresses(file.accessories, diagnostics);
    return file;
}

Document AccessoryFile::write() const {
    return accessories::writeRecordFile(kind, *this);
}

Document writeAccessoryInfo(const std::vector<Accessory>& accessories, LineStyle style) {
    Document out = Document::create(AccessoryFile::section, std::move(style));
    std::vector<Node> records;
    records.reserve(accessories.size());
    for (const Accessory& accessory : accessories) {
        Node record = out.newRecord(AccessoryFile::recordKeyword);
        RecordEditor editor(record, out.style());
        editor.setInteger("id", accessory.id);
        editor.setOptionalText("name", accessory.name);
        editor.setOptionalText("typ", accessory.type);
        if (accessory.switchTimeMs)
            editor.setInteger("schaltzeit", *accessory.switchTimeMs);
        editor.setOptionalText("dectyp", accessory.protocol);
        records.push_back(std::move(record));
    }
    out.replaceRecords(AccessoryFile::recordKeyword, std::move(records));
    return out;
}

std::string toJson(const AccessoryFile& file) {
    return accessories::recordFileJson(kind, file);
}

} // namespace stellwerk::cs2config
