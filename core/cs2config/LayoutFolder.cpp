#include "cs2config/LayoutFolder.h"

#include "cs2config/ConfigFile.h"
#include "cs2config/ConfigKind.h"
#include "cs2config/ConfigStreamKeys.h"

#include <algorithm>
#include <fstream>
#include <system_error>
#include <unistd.h>

namespace stellwerk::cs2config {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view indexName = "gleisbild.cs2";
constexpr std::string_view pageFolderName = "gleisbilder";
constexpr std::string_view accessoryName = "magnetartikel.cs2";
// What a CS2 keeps beside its track plan and reads back.
constexpr std::string_view companions[] = {"magnetartikel.cs2", "lokomotive.cs2", "fahrstrassen.cs2",
                                           "magnetartikel.sr2", "lokomotive.sr2", "gleisbild.sr2"};

std::optional<std::string> readBytes(const fs::path& path) {
    std::error_code error;
    if (!fs::is_regular_file(path, error) || fs::file_size(path, error) > TrackLayout::maxFileSize || error)
        return std::nullopt;
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad())
        return std::nullopt;
    return bytes;
}

// Read through ConfigFile, so that the folder and `cs2 check` agree on what the file is.
std::optional<AccessoryFile> readAccessories(const fs::path& configDirectory) {
    const std::optional<std::string> bytes = readBytes(configDirectory / accessoryName);
    if (!bytes)
        return std::nullopt;
    const ConfigFile file = ConfigFile::fromBytes(*bytes, std::string{accessoryName});
    if (const AccessoryFile* accessories = file.model<AccessoryFile>())
        return *accessories;
    return std::nullopt;
}

bool isTrackPlanKey(const std::string& key) {
    return key == "gbs" || key.starts_with("gbs-");
}

// Writes every file below `directory`; an empty string or what failed.
std::string writeTree(const fs::path& directory, const ConfigFolderFiles& files) {
    std::error_code error;
    for (const auto& [name, bytes] : files) {
        const fs::path path = directory / fs::path(std::u8string(name.begin(), name.end()));
        fs::create_directories(path.parent_path(), error);
        if (error)
            return "cannot create " + path.parent_path().string() + ": " + error.message();
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), std::streamsize(bytes.size()));
        out.close();
        if (!out)
            return "cannot write " + path.string();
    }
    return {};
}

// Puts `fresh` where `target` is; the old `target` (if any) is removed only after the swap worked.
std::string swapInto(const fs::path& fresh, const fs::path& target) {
    std::error_code error;
    const fs::path old = target.string() + ".old-" + std::to_string(::getpid());
    const bool hadOld = fs::exists(target, error);
    if (hadOld) {
        fs::rename(target, old, error);
        if (error)
            return "cannot move the old " + target.string() + " aside: " + error.message();
    }
    fs::rename(fresh, target, error);
    if (error) {
        if (hadOld)
            fs::rename(old, target, error);
        return "cannot put the new files into " + target.string();
    }
    if (hadOld)
        fs::remove_all(old, error);
    return {};
}

} // namespace

fs::path LayoutFolder::configDirectoryOf(const fs::path& folder) {
    std::error_code error;
    if (fs::is_regular_file(folder / indexName, error))
        return folder;
    const fs::path config = folder / "config";
    if (fs::is_regular_file(config / indexName, error) || !TrackLayout::pageFiles(config).empty())
        return config;
    if (!TrackLayout::pageFiles(folder).empty())
        return folder;
    if (folder.filename() == pageFolderName && !TrackLayout::pageFiles(folder.parent_path()).empty())
        return folder.parent_path();
    return config;
}

std::filesystem::path LayoutFolder::iconsDirectoryOf(const std::filesystem::path& configDirectory) {
    return (configDirectory / ".." / "icons").lexically_normal();
}

LayoutFolder::Content LayoutFolder::open(const fs::path& path) {
    std::error_code error;
    if (fs::is_regular_file(path, error))
        return path.filename() == indexName ? open(path.parent_path()) : openPageFile(path);
    Content content;
    if (!fs::is_directory(path, error)) {
        content.problem = "the folder " + path.string() + " does not exist";
        return content;
    }
    content.configDirectory = configDirectoryOf(path);
    const fs::path index = content.configDirectory / indexName;
    if (fs::is_regular_file(index, error)) {
        content.layout = TrackLayout::load(index);
    } else if (!TrackLayout::pageFiles(content.configDirectory).empty()) {
        content.extent = Extent::PagesOnly;
        content.layout = TrackLayout::loadPages(content.configDirectory);
    } else {
        content.problem =
            "there is no track plan (config/gleisbild.cs2, or pages in config/gleisbilder/) in " +
            path.string();
        return content;
    }
    if (content.layout.diagnostics.hasErrors() && content.layout.pages.empty()) {
        content.problem = content.layout.diagnostics.formatAll();
        return content;
    }
    checkAgainstAccessories(content);
    return content;
}

LayoutFolder::Content LayoutFolder::openPageFile(const fs::path& file) {
    Content content;
    content.extent = Extent::SinglePage;
    content.layout = TrackLayout::loadPageFile(file);
    content.configDirectory = content.layout.directory;
    const TrackLayoutPage& page = content.layout.pages.front();
    if (!page.loaded) {
        content.problem = content.layout.diagnostics.formatAll();
        return content;
    }
    Diagnostics kindNotes; // the page's own diagnostics have the header's warnings already
    const ConfigKind kind = recogniseConfigKind(page.page.document, file.filename().string(), kindNotes);
    if (kind != ConfigKind::TrackPage) {
        content.problem =
            file.string() + " is not a page of a track plan (it holds " + std::string(kindName(kind)) + ")";
        return content;
    }
    checkAgainstAccessories(content);
    return content;
}

// The names of the articles from magnetartikel.cs2 beside the plan, and what LayoutCheck finds.
void LayoutFolder::checkAgainstAccessories(Content& content) {
    content.accessories = readAccessories(content.configDirectory);
    content.findings =
        LayoutCheck(content.layout, content.accessories ? &*content.accessories : nullptr).run();
}

std::vector<std::string> LayoutFolder::presentFiles(const Content& content) {
    std::vector<std::string> names;
    if (content.extent == Extent::Folder)
        names.emplace_back(indexName);
    for (const TrackLayoutPage& page : content.layout.pages)
        if (!page.file.empty() && !page.missing &&
            std::find(names.begin(), names.end(), page.diagnostics.fileName()) == names.end())
            names.push_back(page.diagnostics.fileName());
    std::error_code error;
    for (const std::string_view name : companions)
        if (fs::is_regular_file(content.configDirectory / name, error))
            names.emplace_back(name);
    return names;
}

ConfigFolderFiles LayoutFolder::filesOf(const TrackPlan& plan, const std::vector<TrackLayoutPage>& pages) {
    ConfigFolderFiles files;
    files[std::string{indexName}] = plan.write().serialize();
    for (const TrackLayoutPage& page : pages)
        if (const std::optional<fs::path> file = trackPageFile("", page.name))
            files[file->generic_string()] = page.page.write().serialize();
    return files;
}

ConfigFolderFiles LayoutFolder::stationFiles(const std::map<std::string, std::string>& files) {
    ConfigFolderFiles result;
    for (const auto& [key, bytes] : files)
        if (const std::string name = fileNameForKey(key); !name.empty() && !isTrackPlanKey(key))
            result[name] = bytes;
    return result;
}

ConfigFolderFiles LayoutFolder::companionFiles(const fs::path& configDirectory) {
    ConfigFolderFiles result;
    for (const std::string_view name : companions)
        if (std::optional<std::string> bytes = readBytes(configDirectory / name))
            result[std::string{name}] = std::move(*bytes);
    return result;
}

std::string LayoutFolder::write(const fs::path& folder, const ConfigFolderFiles& files) {
    std::error_code error;
    fs::create_directories(folder, error);
    if (error)
        return "cannot create the folder " + folder.string() + ": " + error.message();
    const fs::path target = folder / "config";
    const fs::path fresh = folder / (".config.new-" + std::to_string(::getpid()));
    fs::remove_all(fresh, error);
    if (std::string problem = writeTree(fresh, files); !problem.empty()) {
        fs::remove_all(fresh, error);
        return problem;
    }
    if (std::string problem = swapInto(fresh, target); !problem.empty()) {
        fs::remove_all(fresh, error);
        return problem;
    }
    return {};
}

} // namespace stellwerk::cs2config
