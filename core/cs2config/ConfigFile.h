#pragma once

#include "cs2config/AccessoryFile.h"
#include "cs2config/AccessoryStatusFile.h"
#include "cs2config/ConfigKind.h"
#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"
#include "cs2config/LocomotiveFile.h"
#include "cs2config/LocomotiveStateFile.h"
#include "cs2config/Ms2LocoDatabaseVersion.h"
#include "cs2config/Ms2LocoInfo.h"
#include "cs2config/Ms2LocoNames.h"
#include "cs2config/RouteFile.h"
#include "cs2config/TrackPage.h"
#include "cs2config/TrackPlan.h"
#include "cs2config/TrackStatus.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <variant>

namespace stellwerk::cs2config {

// One configuration file read into its typed model, with every problem found on the way: the entry
// point for tools that are handed "some .cs2 file".
class ConfigFile {
public:
    // Files larger than this are refused (no station writes one; it protects the memory).
    static constexpr std::size_t maxFileSize = 64 * 1024 * 1024;

    static ConfigFile fromBytes(std::string_view bytes, const std::string& fileName);
    static ConfigFile load(const std::filesystem::path& path);

    ConfigKind kind() const { return kind_; }
    const Diagnostics& diagnostics() const { return diagnostics_; }
    const Document& document() const { return document_; }
    // True when the file could be read as a .cs2 file, possibly with warnings but without errors.
    bool usable() const { return kind_ != ConfigKind::NotConfiguration && !diagnostics_.hasErrors(); }

    // The typed model when the file is of that kind (AccessoryFile, TrackPlan, ...), else null.
    template <class Model>
    const Model* model() const {
        return std::get_if<Model>(&model_);
    }

    // "108 locomotives, 1712 functions"
    std::string summary() const;
    std::string json() const;
    // The file written back through its typed model (byte for byte the same when unchanged).
    std::string write() const;

private:
    using Model = std::variant<std::monostate, LocomotiveFile, LocomotiveStateFile, Ms2LocoInfo, Ms2LocoNames,
                               Ms2LocoDatabaseVersion, AccessoryFile, AccessoryStatusFile, RouteFile,
                               cs2config::TrackPlan, cs2config::TrackPage, TrackStatusFile>;

    ConfigFile(Diagnostics diagnostics, Document document);
    void readModel();

    Diagnostics diagnostics_;
    Document document_;
    ConfigKind kind_ = ConfigKind::NotConfiguration;
    Model model_;
};

} // namespace stellwerk::cs2config
