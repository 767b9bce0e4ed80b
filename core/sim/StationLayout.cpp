#include "sim/StationLayout.h"

#include "cs2config/Document.h"
#include "cs2config/LayoutFolder.h"
#include "cs2config/LocomotivePicture.h"

#include <QDirIterator>
#include <QFile>
#include <charconv>
#include <fstream>
#include <system_error>

namespace stellwerk::sim {
namespace {

constexpr std::string_view pageFolder = "gleisbilder/";
constexpr std::string_view pageKeyPrefix = "gbs-";
constexpr std::uintmax_t maxFileSize = 16 * 1024 * 1024;

// The document of one file in memory, its problems reported under its name.
cs2config::Document parse(const std::string& bytes, cs2config::Diagnostics& diagnostics) {
    return cs2config::Document::parse(bytes, diagnostics);
}

std::optional<std::string> readFile(const std::filesystem::path& path, cs2config::Diagnostics& diagnostics) {
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error || size > maxFileSize) {
        diagnostics.error(0,
                          path.string() + (error ? " cannot be read: " + error.message() : " is too large"),
                          "the file is left out of the layout");
        return std::nullopt;
    }
    std::ifstream in(path, std::ios::binary);
    std::string bytes(std::size_t(size), '\0');
    in.read(bytes.data(), std::streamsize(bytes.size()));
    bytes.resize(std::size_t(in.gcount()));
    return bytes;
}

std::optional<std::int64_t> pageNumber(std::string_view key) {
    if (!key.starts_with(pageKeyPrefix) || key.size() == pageKeyPrefix.size())
        return std::nullopt;
    std::int64_t number = 0;
    const std::string_view digits = key.substr(pageKeyPrefix.size());
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), number);
    if (error != std::errc() || end != digits.data() + digits.size())
        return std::nullopt;
    return number;
}

// The .png files of a layout's icons folder (none when there is no such folder).
StationLayout::Files readPictures(const std::filesystem::path& folder, cs2config::Diagnostics& diagnostics) {
    StationLayout::Files pictures;
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error))
        return pictures;
    for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end;
         it.increment(error)) {
        if (!it->is_regular_file(error) || it->path().extension() != ".png")
            continue;
        if (it->file_size(error) > cs2config::picture::MaxBytes) {
            diagnostics.warning(0, it->path().string() + " is larger than a locomotive picture may be",
                                "the station does not serve it");
            continue;
        }
        if (auto bytes = readFile(it->path(), diagnostics))
            pictures.emplace(it->path().filename().string(), std::move(*bytes));
    }
    return pictures;
}

StationLayout::Files resourcePictures() {
    const QString root =
        QString::fromUtf8(StationLayout::demoPictures.data(), qsizetype(StationLayout::demoPictures.size()));
    StationLayout::Files pictures;
    QDirIterator it(root, {QStringLiteral("*.png")}, QDir::Files);
    while (it.hasNext()) {
        QFile file(it.next());
        if (file.open(QIODevice::ReadOnly))
            pictures.emplace(file.fileName().mid(root.size()).toStdString(), file.readAll().toStdString());
    }
    return pictures;
}

} // namespace

StationLayout::StationLayout() = default;

StationLayout StationLayout::fromFiles(Files files) {
    StationLayout layout;
    layout.files_ = std::move(files);
    layout.readModels();
    return layout;
}

StationLayout StationLayout::load(const std::filesystem::path& configDirectory,
                                  cs2config::Diagnostics& diagnostics) {
    Files files;
    std::error_code error;
    std::filesystem::recursive_directory_iterator it(configDirectory, error), end;
    if (error)
        diagnostics.error(0,
                          "layout folder " + configDirectory.string() + " cannot be read: " + error.message(),
                          "the station starts with an empty layout");
    for (; !error && it != end; it.increment(error)) {
        if (!it->is_regular_file(error))
            continue;
        const std::string path =
            std::filesystem::relative(it->path(), configDirectory, error).generic_string();
        if (auto bytes = readFile(it->path(), diagnostics))
            files.emplace(path, std::move(*bytes));
    }
    StationLayout layout = fromFiles(std::move(files));
    layout.setPictures(readPictures(cs2config::LayoutFolder::iconsDirectoryOf(configDirectory), diagnostics));
    for (const std::string& line : layout.diagnostics_)
        diagnostics.warning(0, line, "see the file named in the message");
    return layout;
}

StationLayout StationLayout::demo() {
    const QString root = QString::fromUtf8(demoResource.data(), qsizetype(demoResource.size()));
    Files files;
    QDirIterator it(root, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        QFile file(it.next());
        if (file.open(QIODevice::ReadOnly))
            files.emplace(file.fileName().mid(root.size()).toStdString(), file.readAll().toStdString());
    }
    StationLayout layout = fromFiles(std::move(files));
    layout.setPictures(resourcePictures());
    if (layout.files_.empty())
        layout.diagnostics_.insert(layout.diagnostics_.begin(),
                                   "the demo layout resource " + std::string(demoResource) +
                                       " is missing (resources/demo-layout is not built into this program); "
                                       "the simulated station has no locomotives, accessories or track plan");
    return layout;
}

void StationLayout::note(const cs2config::Diagnostics& diagnostics) {
    for (const cs2config::Diagnostic& item : diagnostics.items())
        diagnostics_.push_back(diagnostics.format(item));
}

void StationLayout::readModels() {
    auto read = [this](std::string_view path, auto reader) {
        cs2config::Diagnostics diagnostics{std::string(path)};
        const auto file = files_.find(path);
        if (file == files_.end()) {
            diagnostics_.push_back(std::string(path) + ": missing; the station serves no such file");
            return;
        }
        reader(parse(file->second, diagnostics), diagnostics);
        note(diagnostics);
    };
    read(locomotivesPath, [this](const cs2config::Document& d, cs2config::Diagnostics& diagnostics) {
        locomotives_ = cs2config::LocomotiveFile::read(d, diagnostics);
    });
    read(accessoriesPath, [this](const cs2config::Document& d, cs2config::Diagnostics& diagnostics) {
        accessories_ = cs2config::AccessoryFile::read(d, diagnostics);
    });
    read(routesPath, [this](const cs2config::Document& d, cs2config::Diagnostics& diagnostics) {
        routes_ = cs2config::RouteFile::read(d, diagnostics);
    });
    readTrackPlan();
}

void StationLayout::readTrackPlan() {
    trackPlan_.diagnostics.setFileName(std::string(trackPlanPath));
    const auto index = files_.find(trackPlanPath);
    if (index == files_.end()) {
        diagnostics_.push_back(std::string(trackPlanPath) + ": missing; the station serves no track plan");
        return;
    }
    trackPlan_.plan =
        cs2config::TrackPlan::read(parse(index->second, trackPlan_.diagnostics), trackPlan_.diagnostics);
    for (const cs2config::TrackPageEntry& entry : trackPlan_.plan.pages) {
        cs2config::TrackLayoutPage page;
        page.id = entry.id;
        page.name = entry.name;
        const std::string path = std::string(pageFolder) + entry.name + ".cs2";
        page.diagnostics.setFileName(path);
        page.file = std::filesystem::path(path);
        if (const auto bytes = files_.find(path); bytes != files_.end()) {
            page.page = cs2config::TrackPage::read(parse(bytes->second, page.diagnostics), page.diagnostics);
            page.loaded = true;
        } else {
            page.diagnostics.warning(0, "page " + std::to_string(entry.id) + " has no file " + path,
                                     "the page is served as missing");
        }
        note(page.diagnostics);
        trackPlan_.pages.push_back(std::move(page));
    }
    note(trackPlan_.diagnostics);
}

std::optional<std::string> StationLayout::pathForKey(std::string_view key) const {
    if (key == "loks")
        return std::string(locomotivesPath);
    if (key == "mags")
        return std::string(accessoriesPath);
    if (key == "fs")
        return std::string(routesPath);
    if (key == "gbs")
        return std::string(trackPlanPath);
    if (const auto number = pageNumber(key))
        if (const cs2config::TrackLayoutPage* found = page(*number); found && found->loaded)
            return found->file.generic_string();
    return std::nullopt;
}

std::optional<std::string> StationLayout::fileForKey(std::string_view key) const {
    const auto path = pathForKey(key);
    return path ? fileForPath(*path) : std::nullopt;
}

std::optional<std::string> StationLayout::pictureFor(std::string_view fileName) const {
    const auto picture = pictures_.find(fileName);
    if (picture == pictures_.end())
        return std::nullopt;
    return picture->second;
}

std::optional<std::string> StationLayout::fileForPath(std::string_view path) const {
    const auto file = files_.find(path);
    if (file == files_.end())
        return std::nullopt;
    return file->second;
}

const cs2config::TrackLayoutPage* StationLayout::page(std::int64_t id) const {
    for (const cs2config::TrackLayoutPage& page : trackPlan_.pages)
        if (page.id == id)
            return &page;
    return nullptr;
}

} // namespace stellwerk::sim
