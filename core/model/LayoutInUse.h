#pragma once

#include "cs2config/LayoutFolder.h"
#include "cs2config/RouteFile.h"
#include "model/TrackLayout.h"
#include "station/StartupSequence.h"
#include "trackgraph/TrackGraph.h"

#include <QObject>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace stellwerk::model {

// The layout Stellwerk works with: the one the station handed over at its start-up, or a folder the user
// opened over it. One object holds its files, the pages drawn, the track graph (derived once per change)
// and its pictures folder, so that the plan, the command line and the automation all read the same
// layout and nothing else reads layout files or the start-up result. An opened folder wins over the
// station's download until the user asks for the station's plan again (showStation()); a later download
// is kept for that moment.
class LayoutInUse final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(LayoutInUse)

public:
    enum class Origin {
        None,    // no station has handed over a layout and no folder is open
        Station, // the station's download at its start-up
        Folder,  // a folder (or a single page file) the user opened
    };

    explicit LayoutInUse(QObject* parent = nullptr);
    ~LayoutInUse() override;

    Origin origin() const;
    // The opened layout's config folder (Folder), else empty.
    std::filesystem::path folder() const;
    // The opened folder as it was read: how much of it there was, what its files disagree on, each page's
    // file; null unless a folder is in use.
    const cs2config::LayoutFolder::Content* folderContent() const;
    // The typed files: the plan and its pages, the accessories, the routes (null where there is none).
    const cs2config::TrackLayout* files() const;
    const cs2config::AccessoryFile* accessories() const;
    const cs2config::RouteFile* routes() const;
    // The pages as the plan draws them; null while there is no layout. Shared, so that a view can keep
    // its page while the layout in use changes.
    std::shared_ptr<const TrackLayout> pages() const;
    // The railway the pages show; null while there is no page. Derived once when the layout changes.
    std::shared_ptr<const trackgraph::TrackGraph> graph() const;
    // Where the locomotive pictures of an opened layout are (its icons folder); empty for the station's.
    std::filesystem::path picturesFolder() const;
    // Whether there is a track plan to export.
    bool hasPlan() const;
    // The names the files give an accessory and a route (empty when they name none).
    std::string accessoryName(std::int64_t id) const;
    std::string routeName(std::int64_t id) const;

    // What a station's start-up downloaded; in use unless a folder is open.
    void useStationDownload(const station::StartupResult& result);
    // The station went away: its download is no longer in use (an open folder stays).
    void forgetStation();
    // Opens a configuration folder, its config/ folder, or a single page file (LayoutFolder::open); an
    // empty string when it is in use now, else why not (the layout in use stays as it was).
    std::string open(const std::filesystem::path& path);
    // Back to the station's download after a folder was opened (none when no station handed one over).
    void showStation();
    // Writes the layout in use as a CS2 configuration folder (LayoutFolder::write: created when missing,
    // unchanged files byte for byte); an empty string, or why it failed (nothing was changed then).
    std::string exportTo(const std::filesystem::path& folder) const;

signals:
    // Another layout is in use (opened, downloaded, back to the station's, or none).
    void changed();

private:
    struct Layout;
    static std::shared_ptr<const Layout> fromStation(const station::StartupResult& result);
    static std::shared_ptr<const Layout> fromFolder(cs2config::LayoutFolder::Content content);
    static void derive(Layout& layout);
    const std::shared_ptr<const Layout>& inUse() const;
    const Layout* current() const;
    void emitIfChanged(const std::shared_ptr<const Layout>& before);

    std::shared_ptr<const Layout> station_;
    std::shared_ptr<const Layout> folder_;
};

} // namespace stellwerk::model
