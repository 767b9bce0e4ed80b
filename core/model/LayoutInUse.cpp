#include "model/LayoutInUse.h"

#include "cs2config/ConfigFile.h"

#include <system_error>

namespace stellwerk::model {

// One layout as it is in use: its files, the pages drawn and the graph, made once and never changed.
struct LayoutInUse::Layout {
    Origin origin = Origin::None;
    cs2config::LayoutFolder::Content content; // for the station: its download, without a folder
    std::optional<cs2config::RouteFile> routes;
    cs2config::ConfigFolderFiles stationFiles; // the station's other files, for an export
    bool hasPlan = false;
    std::shared_ptr<const TrackLayout> pages;
    std::shared_ptr<const trackgraph::TrackGraph> graph;
};

namespace {

// fahrstrassen.cs2 beside the track plan, when it is there and readable.
std::optional<cs2config::RouteFile> routesIn(const std::filesystem::path& configDirectory) {
    std::error_code error;
    const std::filesystem::path file = configDirectory / "fahrstrassen.cs2";
    if (!std::filesystem::is_regular_file(file, error))
        return std::nullopt;
    const cs2config::ConfigFile config = cs2config::ConfigFile::load(file);
    if (const cs2config::RouteFile* routes = config.model<cs2config::RouteFile>())
        return *routes;
    return std::nullopt;
}

// The downloaded form of a layout's pages, which the drawn pages are made of (a page whose file could not
// be read is there without tiles).
std::vector<station::DownloadedPage> downloadedPages(const cs2config::TrackLayout& layout) {
    std::vector<station::DownloadedPage> pages;
    for (const cs2config::TrackLayoutPage& page : layout.pages)
        pages.push_back({page.id, page.name, page.page});
    return pages;
}

// The station's pages as the pages of a layout whose files were all read.
std::vector<cs2config::TrackLayoutPage> layoutPages(const std::vector<station::DownloadedPage>& downloaded) {
    std::vector<cs2config::TrackLayoutPage> pages;
    for (const station::DownloadedPage& page : downloaded) {
        cs2config::TrackLayoutPage& read = pages.emplace_back();
        read.id = page.id;
        read.name = page.name;
        read.loaded = true;
        read.page = page.page;
    }
    return pages;
}

} // namespace

LayoutInUse::LayoutInUse(QObject* parent) : QObject(parent) {}

LayoutInUse::~LayoutInUse() = default;

std::shared_ptr<const LayoutInUse::Layout> LayoutInUse::fromStation(const station::StartupResult& result) {
    auto layout = std::make_shared<Layout>();
    layout->origin = Origin::Station;
    layout->content.layout.plan = result.trackPlan.value_or(cs2config::TrackPlan{});
    layout->content.layout.pages = layoutPages(result.pages);
    layout->content.accessories = result.accessories;
    layout->routes = result.routes;
    layout->stationFiles = cs2config::LayoutFolder::stationFiles(result.files);
    layout->hasPlan = result.trackPlan.has_value();
    derive(*layout);
    return layout;
}

std::shared_ptr<const LayoutInUse::Layout> LayoutInUse::fromFolder(cs2config::LayoutFolder::Content content) {
    auto layout = std::make_shared<Layout>();
    layout->origin = Origin::Folder;
    layout->routes = routesIn(content.configDirectory);
    layout->content = std::move(content);
    layout->hasPlan = true;
    derive(*layout);
    return layout;
}

// The pages drawn and the graph of a layout, once.
void LayoutInUse::derive(Layout& layout) {
    const cs2config::TrackLayout& files = layout.content.layout;
    layout.pages = std::make_shared<const TrackLayout>(downloadedPages(files));
    if (files.pages.empty())
        return;
    layout.graph = std::make_shared<const trackgraph::TrackGraph>(trackgraph::TrackGraph::derive(
        files, layout.content.accessories ? &*layout.content.accessories : nullptr,
        layout.routes ? &*layout.routes : nullptr));
}

const std::shared_ptr<const LayoutInUse::Layout>& LayoutInUse::inUse() const {
    return folder_ ? folder_ : station_;
}

const LayoutInUse::Layout* LayoutInUse::current() const {
    return inUse().get();
}

LayoutInUse::Origin LayoutInUse::origin() const {
    return current() ? current()->origin : Origin::None;
}

std::filesystem::path LayoutInUse::folder() const {
    return folder_ ? folder_->content.configDirectory : std::filesystem::path();
}

const cs2config::LayoutFolder::Content* LayoutInUse::folderContent() const {
    return folder_ ? &folder_->content : nullptr;
}

const cs2config::TrackLayout* LayoutInUse::files() const {
    return current() ? &current()->content.layout : nullptr;
}

const cs2config::AccessoryFile* LayoutInUse::accessories() const {
    return current() && current()->content.accessories ? &*current()->content.accessories : nullptr;
}

const cs2config::RouteFile* LayoutInUse::routes() const {
    return current() && current()->routes ? &*current()->routes : nullptr;
}

std::shared_ptr<const TrackLayout> LayoutInUse::pages() const {
    return current() ? current()->pages : nullptr;
}

std::shared_ptr<const trackgraph::TrackGraph> LayoutInUse::graph() const {
    return current() ? current()->graph : nullptr;
}

std::filesystem::path LayoutInUse::picturesFolder() const {
    return folder_ ? cs2config::LayoutFolder::iconsDirectoryOf(folder_->content.configDirectory)
                   : std::filesystem::path();
}

bool LayoutInUse::hasPlan() const {
    return current() && current()->hasPlan;
}

std::string LayoutInUse::accessoryName(std::int64_t id) const {
    if (const cs2config::AccessoryFile* file = accessories())
        for (const cs2config::Accessory& accessory : file->accessories)
            if (accessory.id == id)
                return accessory.name;
    return {};
}

std::string LayoutInUse::routeName(std::int64_t id) const {
    if (const cs2config::RouteFile* file = routes())
        for (const cs2config::Route& route : file->routes)
            if (route.id == id)
                return route.name;
    return {};
}

void LayoutInUse::useStationDownload(const station::StartupResult& result) {
    const std::shared_ptr<const Layout> before = inUse();
    station_ = fromStation(result);
    emitIfChanged(before);
}

void LayoutInUse::forgetStation() {
    const std::shared_ptr<const Layout> before = inUse();
    station_.reset();
    emitIfChanged(before);
}

std::string LayoutInUse::open(const std::filesystem::path& path) {
    cs2config::LayoutFolder::Content content = cs2config::LayoutFolder::open(path);
    if (!content.problem.empty())
        return content.problem;
    folder_ = fromFolder(std::move(content));
    emit changed();
    return {};
}

void LayoutInUse::showStation() {
    const std::shared_ptr<const Layout> before = inUse();
    folder_.reset();
    emitIfChanged(before);
}

std::string LayoutInUse::exportTo(const std::filesystem::path& folder) const {
    const Layout* layout = current();
    if (!layout || !layout->hasPlan)
        return "there is no track plan to export";
    const cs2config::TrackLayout& files = layout->content.layout;
    cs2config::ConfigFolderFiles written = cs2config::LayoutFolder::filesOf(files.plan, files.pages);
    written.merge(layout->origin == Origin::Folder
                      ? cs2config::LayoutFolder::companionFiles(layout->content.configDirectory)
                      : cs2config::ConfigFolderFiles(layout->stationFiles));
    return cs2config::LayoutFolder::write(folder, written);
}

// Every change replaces the layout object, so a different pointer is a different layout; the caller holds
// `before`, so that a new layout cannot take its address.
void LayoutInUse::emitIfChanged(const std::shared_ptr<const Layout>& before) {
    if (inUse() != before)
        emit changed();
}

} // namespace stellwerk::model
