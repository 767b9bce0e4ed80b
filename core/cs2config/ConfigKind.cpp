#include "cs2config/ConfigKind.h"

#include "cs2config/AccessoryFile.h"
#include "cs2config/RouteFile.h"
#include "cs2config/TrackPage.h"
#include "cs2config/TrackPlan.h"

#include <filesystem>
#include <string>

namespace stellwerk::cs2config {

namespace {

bool endsWith(std::string_view text, std::string_view suffix) {
    return text.size() >= suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
}

// lokomotive.cs2 has `lokomotive` records; the MS2 streams have `lok` records: with `.nr` and a
// `numloks` record for loknamen, with the loco's data for lokinfo.
ConfigKind locomotiveKind(const Document& document) {
    const std::vector<const Node*> loks = document.records("lok");
    if (loks.empty())
        return ConfigKind::Locomotives;
    if (document.record("numloks") || loks.front()->find("nr"))
        return ConfigKind::LocoNames;
    return ConfigKind::LocoInfo;
}

// The kind the header names; Unknown for a missing or unknown header.
ConfigKind kindByHeader(const Document& document, std::string_view path) {
    const bool status = endsWith(path, ".sr2");
    const std::string_view section = document.section();
    if (!document.hasHeader() && document.root().find("anzahl") && document.root().find("version"))
        return ConfigKind::LocoDbVersion;
    if (section == "lokstatus" || (section == "lokomotive" && status))
        return ConfigKind::LocomotiveStatus;
    if (section == "lokomotive")
        return locomotiveKind(document);
    if (section == AccessoryFile::section)
        return status ? ConfigKind::AccessoryStatus : ConfigKind::Accessories;
    if (section == RouteFile::section)
        return ConfigKind::Routes;
    if (section == TrackPlan::section)
        return status ? ConfigKind::TrackStatus : ConfigKind::TrackPlan;
    if (section == TrackPage::section || section == "conf")
        return ConfigKind::TrackPage;
    return ConfigKind::Unknown;
}

} // namespace

std::string_view kindName(ConfigKind kind) {
    switch (kind) {
    case ConfigKind::NotConfiguration:
        return "not a .cs2 file";
    case ConfigKind::Unknown:
        return "unknown .cs2 file";
    case ConfigKind::Locomotives:
        return "locomotives (lokomotive.cs2)";
    case ConfigKind::LocomotiveStatus:
        return "locomotive states (lokomotive.sr2)";
    case ConfigKind::LocoInfo:
        return "MS2 lokinfo stream";
    case ConfigKind::LocoNames:
        return "MS2 loknamen stream";
    case ConfigKind::LocoDbVersion:
        return "MS2 ldbver stream";
    case ConfigKind::Accessories:
        return "accessories (magnetartikel.cs2)";
    case ConfigKind::AccessoryStatus:
        return "accessory states (magnetartikel.sr2)";
    case ConfigKind::Routes:
        return "routes (fahrstrassen.cs2)";
    case ConfigKind::TrackPlan:
        return "track plan index (gleisbild.cs2)";
    case ConfigKind::TrackPage:
        return "track plan page";
    case ConfigKind::TrackStatus:
        return "track plan states (gleisbild.sr2)";
    }
    return "unknown";
}

std::optional<ConfigKind> configKindByName(std::string_view path) {
    const std::filesystem::path file{std::u8string(path.begin(), path.end())};
    const std::string name = file.filename().string();
    const std::string folder = file.parent_path().filename().string();
    static constexpr struct {
        std::string_view name;
        ConfigKind kind;
    } names[] = {
        {"lokomotive.cs2", ConfigKind::Locomotives},    {"lokomotive.sr2", ConfigKind::LocomotiveStatus},
        {"magnetartikel.cs2", ConfigKind::Accessories}, {"magnetartikel.sr2", ConfigKind::AccessoryStatus},
        {"fahrstrassen.cs2", ConfigKind::Routes},       {"gleisbild.cs2", ConfigKind::TrackPlan},
        {"gleisbild.sr2", ConfigKind::TrackStatus},
    };
    for (const auto& known : names)
        if (name == known.name)
            return known.kind;
    if (endsWith(name, ".cs2") && (folder == "gleisbilder" || name.starts_with("gbs-")))
        return ConfigKind::TrackPage;
    return std::nullopt;
}

ConfigKind recogniseConfigKind(const Document& document, std::string_view path, Diagnostics& diagnostics) {
    if (!document.isConfiguration())
        return ConfigKind::NotConfiguration;
    const ConfigKind byHeader = kindByHeader(document, path);
    if (byHeader != ConfigKind::Unknown)
        return byHeader;
    const std::optional<ConfigKind> byName = configKindByName(path);
    if (!byName)
        return ConfigKind::Unknown;
    // A header that names another section is reported by the kind's reader ("section [x] instead of ...").
    if (!document.hasHeader())
        diagnostics.warning(0, "no readable section header",
                            "read as " + std::string(kindName(*byName)) + " because of the file name");
    return *byName;
}

} // namespace stellwerk::cs2config
