#include "cs2config/ConfigFile.h"

#include "cs2config/JsonWriter.h"

#include <fstream>
#include <iterator>

namespace stellwerk::cs2config {

namespace {

std::string count(std::size_t n, std::string_view one, std::string_view many) {
    return std::to_string(n) + ' ' + std::string(n == 1 ? one : many);
}

std::string summarize(const std::monostate&) {
    return "no typed model";
}

std::string summarize(const LocomotiveFile& file) {
    return count(file.locomotives.size(), "locomotive", "locomotives") + ", " +
           count(file.functionCount(), "function", "functions");
}

std::string summarize(const LocomotiveStateFile& file) {
    return count(file.locomotives.size(), "locomotive state", "locomotive states");
}

std::string summarize(const Ms2LocoInfo& info) {
    if (!info.locomotive)
        return "no locomotive";
    return "'" + info.locomotive->name + "', " +
           count(info.locomotive->functions.size(), "function", "functions");
}

std::string summarize(const Ms2LocoNames& names) {
    std::string text = count(names.entries.size(), "name", "names");
    if (names.total)
        text += " of " + count(static_cast<std::size_t>(*names.total), "locomotive", "locomotives");
    return text;
}

std::string summarize(const Ms2LocoDatabaseVersion& version) {
    return "version " + std::to_string(version.version) + " of " + std::to_string(version.month) + "/" +
           std::to_string(version.year) + ", " +
           count(static_cast<std::size_t>(version.count), "entry", "entries");
}

std::string summarize(const AccessoryFile& file) {
    return count(file.accessories.size(), "accessory", "accessories");
}

std::string summarize(const AccessoryStatusFile& file) {
    return count(file.states.size(), "accessory state", "accessory states");
}

std::string summarize(const RouteFile& file) {
    std::size_t steps = 0;
    for (const Route& route : file.routes)
        steps += route.steps.size();
    return count(file.routes.size(), "route", "routes") + ", " + count(steps, "item", "items");
}

std::string summarize(const TrackPlan& plan) {
    std::string text = count(plan.pages.size(), "page", "pages");
    if (!plan.elements.empty())
        text += ", " + count(plan.elements.size(), "element", "elements");
    return text;
}

std::string summarize(const TrackPage& page) {
    return count(page.elements.size(), "element", "elements");
}

std::string summarize(const TrackStatusFile& status) {
    return count(status.elements.size(), "element state", "element states");
}

// Any .cs2 document as its tree of entries, for files without a typed model.
void writeEntries(JsonWriter& json, const Node& node) {
    json.beginArray("entries");
    for (const Node& child : node.children()) {
        if (!child.isEntry())
            continue;
        json.beginObject().value("key", child.key()).value("line", child.lineNumber());
        if (child.hasValue())
            json.value("value", child.value());
        if (!child.children().empty())
            writeEntries(json, child);
        json.endObject();
    }
    json.endArray();
}

std::string documentJson(const Document& document) {
    JsonWriter json;
    json.beginObject().value("section", document.section());
    writeEntries(json, document.root());
    json.endObject();
    return json.text();
}

} // namespace

ConfigFile::ConfigFile(Diagnostics diagnostics, Document document)
    : diagnostics_(std::move(diagnostics)), document_(std::move(document)) {}

ConfigFile ConfigFile::fromBytes(std::string_view bytes, const std::string& fileName) {
    Diagnostics diagnostics(fileName);
    Document document = Document::parse(bytes, diagnostics);
    ConfigFile file(std::move(diagnostics), std::move(document));
    file.kind_ = recogniseConfigKind(file.document_, fileName, file.diagnostics_);
    file.readModel();
    return file;
}

ConfigFile ConfigFile::load(const std::filesystem::path& path) {
    const std::string name = path.filename().string();
    std::error_code error;
    const auto size = std::filesystem::file_size(path, error);
    std::string problem;
    if (error)
        problem = "cannot read the file: " + error.message();
    else if (size > maxFileSize)
        problem = "the file has " + std::to_string(size) + " bytes, more than the " +
                  std::to_string(maxFileSize) + " any station writes";
    std::string bytes;
    if (problem.empty()) {
        std::ifstream in(path, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        if (in.bad())
            problem = "cannot read the file";
    }
    if (!problem.empty()) {
        Diagnostics ignored;
        ConfigFile file(Diagnostics(path.string()), Document::parse({}, ignored));
        file.diagnostics_.error(0, problem, "nothing read");
        return file;
    }
    return fromBytes(bytes, path.string());
}

void ConfigFile::readModel() {
    switch (kind_) {
    case ConfigKind::NotConfiguration:
        return;
    case ConfigKind::Unknown:
        diagnostics_.warning(0,
                             document_.hasHeader()
                                 ? "unknown section [" + std::string(document_.section()) + "]"
                                 : std::string("no section header that names the kind of file"),
                             "read as a plain .cs2 document without a typed model");
        return;
    case ConfigKind::Locomotives:
        model_ = LocomotiveFile::read(document_, diagnostics_);
        return;
    case ConfigKind::LocomotiveStatus:
        model_ = LocomotiveStateFile::read(document_, diagnostics_);
        return;
    case ConfigKind::LocoInfo:
        model_ = Ms2LocoInfo::read(document_, diagnostics_);
        return;
    case ConfigKind::LocoNames:
        model_ = Ms2LocoNames::read(document_, diagnostics_);
        return;
    case ConfigKind::LocoDbVersion:
        model_ = Ms2LocoDatabaseVersion::read(document_, diagnostics_);
        return;
    case ConfigKind::Accessories:
        model_ = AccessoryFile::read(document_, diagnostics_);
        return;
    case ConfigKind::AccessoryStatus:
        model_ = AccessoryStatusFile::read(document_, diagnostics_);
        return;
    case ConfigKind::Routes:
        model_ = RouteFile::read(document_, diagnostics_);
        return;
    case ConfigKind::TrackPlan:
        model_ = cs2config::TrackPlan::read(document_, diagnostics_);
        return;
    case ConfigKind::TrackPage:
        model_ = cs2config::TrackPage::read(document_, diagnostics_);
        return;
    case ConfigKind::TrackStatus:
        model_ = TrackStatusFile::read(document_, diagnostics_);
        return;
    }
}

std::string ConfigFile::summary() const {
    return std::string(kindName(kind_)) + ": " +
           std::visit([](const auto& model) { return summarize(model); }, model_);
}

std::string ConfigFile::json() const {
    if (std::holds_alternative<std::monostate>(model_))
        return kind_ == ConfigKind::NotConfiguration ? std::string() : documentJson(document_);
    return std::visit(
        [](const auto& model) {
            if constexpr (std::is_same_v<std::decay_t<decltype(model)>, std::monostate>)
                return std::string();
            else
                return toJson(model);
        },
        model_);
}

std::string ConfigFile::write() const {
    return std::visit(
        [this](const auto& model) {
            if constexpr (std::is_same_v<std::decay_t<decltype(model)>, std::monostate>)
                return document_.serialize();
            else
                return model.write().serialize();
        },
        model_);
}

} // namespace stellwerk::cs2config
