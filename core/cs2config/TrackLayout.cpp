#include "cs2config/TrackLayout.h"

#include "cs2config/ConfigKind.h"
#include "cs2config/Text.h"

#include <algorithm>
#include <fstream>
#include <system_error>

namespace stellwerk::cs2config {

namespace {

constexpr std::string_view pageDirectory = "gleisbilder";
constexpr std::string_view pageExtension = ".cs2";
constexpr std::string_view missingProblem = "is missing";

bool usableFileName(std::string_view name) {
    if (name.empty() || name == "." || name == "..")
        return false;
    for (char c : name)
        if (c == '/' || c == '\\' || static_cast<unsigned char>(c) < 0x20 || c == 0x7F)
            return false;
    return true;
}

// The bytes of a file, or why there are none.
struct FileContent {
    std::optional<std::string> bytes;
    std::string problem;
};

FileContent readFile(const std::filesystem::path& path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
        return {std::nullopt, std::string(missingProblem)};
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error)
        return {std::nullopt, "cannot be read (" + error.message() + ")"};
    if (size > TrackLayout::maxFileSize)
        return {std::nullopt, "is larger than " + std::to_string(TrackLayout::maxFileSize) + " bytes"};
    std::ifstream in(path, std::ios::binary);
    std::string bytes(static_cast<std::size_t>(size), '\0');
    if (!in.read(bytes.data(), static_cast<std::streamsize>(bytes.size())) && !in.eof())
        return {std::nullopt, "cannot be read"};
    bytes.resize(static_cast<std::size_t>(in.gcount()));
    return {std::move(bytes), {}};
}

std::string displayName(std::string_view pageName) {
    return std::string(pageDirectory) + "/" + std::string(pageName) + std::string(pageExtension);
}

// The kind rules of `cs2 check`: a file without a readable header is read as what its name says, and
// the warning says so. Index and pages are read as such whatever they hold; their readers report a
// header that names another section.
void noteKind(const Document& document, Diagnostics& diagnostics) {
    recogniseConfigKind(document, diagnostics.fileName(), diagnostics);
}

// Reads `page.file` into `page`; a file that cannot be read is reported in the index's diagnostics.
TrackLayoutPage readPage(TrackLayoutPage page, const TrackPageEntry& entry, Diagnostics& indexDiagnostics) {
    const FileContent content = readFile(page.file);
    if (!content.bytes) {
        page.missing = content.problem == missingProblem;
        indexDiagnostics.warning(entry.line(),
                                 "page file " + quoteForMessage(displayName(entry.name), 80) + " of page " +
                                     std::to_string(entry.id) + " " + content.problem,
                                 "the page is left empty");
        return page;
    }
    const Document document = Document::parse(*content.bytes, page.diagnostics);
    noteKind(document, page.diagnostics);
    page.page = TrackPage::read(document, page.diagnostics);
    page.loaded = true;
    return page;
}

TrackLayoutPage loadPage(const std::filesystem::path& directory, const TrackPageEntry& entry,
                         Diagnostics& indexDiagnostics) {
    TrackLayoutPage page;
    page.id = entry.id;
    page.name = entry.name;
    page.diagnostics.setFileName(displayName(entry.name));
    const std::optional<std::filesystem::path> file = trackPageFile(directory, entry.name);
    if (!file) {
        if (!entry.name.empty()) // a page without a name is reported by the index reader
            indexDiagnostics.warning(entry.line(),
                                     "page name " + quoteForMessage(entry.name) + " cannot be a file name",
                                     "its page file is not looked up; the page is left empty");
        return page;
    }
    page.file = *file;
    return readPage(std::move(page), entry, indexDiagnostics);
}

// The file's name without ".cs2", as the page's name in an index made up for it.
std::string pageNameOf(const std::filesystem::path& file) {
    const std::u8string stem = file.stem().u8string();
    return std::string(stem.begin(), stem.end());
}

// An index listing `names` as pages 0, 1, 2...: written like a new one when the layout is exported.
TrackPlan madeUpIndex(const std::vector<std::string>& names) {
    TrackPlan plan;
    for (std::size_t i = 0; i < names.size(); ++i)
        plan.pages.push_back({std::int64_t(i), names[i], {}});
    return plan;
}

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

// "2 - Bottom" before "10 - Hafen": runs of digits compare by their value, everything else bytewise.
bool inNameOrder(std::string_view a, std::string_view b) {
    std::size_t i = 0, j = 0;
    while (i < a.size() && j < b.size()) {
        if (isDigit(a[i]) && isDigit(b[j])) {
            const std::size_t startA = i, startB = j;
            while (i < a.size() && isDigit(a[i]))
                ++i;
            while (j < b.size() && isDigit(b[j]))
                ++j;
            std::string_view numberA = a.substr(startA, i - startA), numberB = b.substr(startB, j - startB);
            numberA.remove_prefix(std::min(numberA.find_first_not_of('0'), numberA.size()));
            numberB.remove_prefix(std::min(numberB.find_first_not_of('0'), numberB.size()));
            if (numberA.size() != numberB.size())
                return numberA.size() < numberB.size();
            if (numberA != numberB)
                return numberA < numberB;
            continue;
        }
        if (a[i] != b[j])
            return static_cast<unsigned char>(a[i]) < static_cast<unsigned char>(b[j]);
        ++i;
        ++j;
    }
    return a.size() - i < b.size() - j;
}

void writeDiagnosticsJson(JsonWriter& json, const Diagnostics& diagnostics) {
    json.beginArray("diagnostics");
    for (const Diagnostic& diagnostic : diagnostics.items())
        json.value(std::string_view(), diagnostics.format(diagnostic));
    json.endArray();
}

} // namespace

std::optional<std::filesystem::path> trackPageFile(const std::filesystem::path& directory,
                                                   std::string_view pageName) {
    if (!usableFileName(pageName))
        return std::nullopt;
    std::u8string fileName(pageName.begin(), pageName.end());
    fileName.append(pageExtension.begin(), pageExtension.end());
    return directory / std::filesystem::path(pageDirectory) / std::filesystem::path(fileName);
}

std::string trackPageStreamKey(std::int64_t pageId) {
    return "gbs-" + std::to_string(pageId);
}

TrackLayout TrackLayout::load(const std::filesystem::path& indexFile) {
    TrackLayout layout;
    layout.directory = indexFile.parent_path();
    layout.diagnostics.setFileName(indexFile.filename().string());
    const FileContent content = readFile(indexFile);
    if (!content.bytes) {
        layout.diagnostics.error(0, "track plan index " + indexFile.string() + " " + content.problem,
                                 "no pages are loaded");
        return layout;
    }
    const Document document = Document::parse(*content.bytes, layout.diagnostics);
    noteKind(document, layout.diagnostics);
    layout.plan = TrackPlan::read(document, layout.diagnostics);
    layout.pages.reserve(layout.plan.pages.size());
    for (const TrackPageEntry& entry : layout.plan.pages)
        layout.pages.push_back(loadPage(layout.directory, entry, layout.diagnostics));
    return layout;
}

TrackLayout TrackLayout::loadPages(const std::filesystem::path& directory) {
    TrackLayout layout;
    layout.directory = directory;
    layout.diagnostics.setFileName("gleisbild.cs2");
    const std::vector<std::filesystem::path> files = pageFiles(directory);
    std::vector<std::string> names;
    for (const std::filesystem::path& file : files)
        names.push_back(pageNameOf(file));
    layout.plan = madeUpIndex(names);
    layout.diagnostics.warning(0, "the track plan index is missing",
                               "the " + std::to_string(files.size()) + " page file(s) in " +
                                   std::string(pageDirectory) +
                                   "/ are shown in the order of their names, numbered from 0");
    for (const TrackPageEntry& entry : layout.plan.pages)
        layout.pages.push_back(loadPage(directory, entry, layout.diagnostics));
    return layout;
}

TrackLayout TrackLayout::loadPageFile(const std::filesystem::path& pageFile) {
    TrackLayout layout;
    const std::filesystem::path folder = pageFile.parent_path();
    layout.directory = folder.filename() == pageDirectory ? folder.parent_path() : folder;
    layout.diagnostics.setFileName("gleisbild.cs2");
    layout.plan = madeUpIndex({pageNameOf(pageFile)});
    const TrackPageEntry& entry = layout.plan.pages.front();
    TrackLayoutPage page;
    page.name = entry.name;
    page.file = pageFile;
    page.diagnostics.setFileName(displayName(entry.name));
    layout.pages.push_back(readPage(std::move(page), entry, layout.diagnostics));
    return layout;
}

std::vector<std::filesystem::path> TrackLayout::pageFiles(const std::filesystem::path& directory) {
    std::vector<std::filesystem::path> files;
    std::error_code error;
    for (std::filesystem::directory_iterator it(directory / pageDirectory, error), end; !error && it != end;
         it.increment(error))
        if (it->path().extension() == pageExtension && it->is_regular_file(error))
            files.push_back(it->path());
    std::sort(files.begin(), files.end(),
              [](const auto& a, const auto& b) { return inNameOrder(pageNameOf(a), pageNameOf(b)); });
    return files;
}

std::string toJson(const TrackLayout& layout) {
    JsonWriter json;
    json.beginObject();
    json.value("directory", layout.directory.string());
    writeJson(json, layout.plan, "index");
    writeDiagnosticsJson(json, layout.diagnostics);
    json.beginArray("pages");
    for (const TrackLayoutPage& page : layout.pages) {
        json.beginObject();
        json.value("id", page.id);
        json.value("name", page.name);
        json.value("file", page.file.string());
        json.value("loaded", page.loaded);
        if (page.loaded)
            writeJson(json, page.page, "page");
        else
            json.null("page");
        writeDiagnosticsJson(json, page.diagnostics);
        json.endObject();
    }
    json.endArray();
    json.endObject();
    return json.text();
}

} // namespace stellwerk::cs2config
