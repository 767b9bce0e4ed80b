#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"
#include "cs2config/Locomotive.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::cs2config {

// lokomotive.cs2 (document 8.1): the file version, the mfx registration counter and every
// locomotive. Built on the Document it was read from, so that writing it back changes only the
// lines of values that changed.
struct LocomotiveFile {
    // The `version` record (8.1.1; current CS2 files: 0.3).
    struct Version {
        int major = 0;
        int minor = 3;
    };

    Document document = Document::create("lokomotive");
    std::optional<Version> version;
    std::optional<std::int64_t> session; // `session .id`: the mfx registration counter (1..65536)
    std::vector<Locomotive> locomotives; // every `lokomotive` record in file order, empty ones too
    // A CS3-native loco file (`.dectyp`, "#20" escapes in names): names are unescaped when read and
    // escaped again when written.
    bool cs3Native = false;

    static LocomotiveFile read(const Document& document, Diagnostics& diagnostics);
    // The document with every value written back; unchanged values keep their lines byte for byte.
    Document write() const;

    // The locomotive with this uid (the first one when the file has duplicates), or null.
    const Locomotive* find(std::uint32_t uid) const;
    std::size_t functionCount() const;
};

// The file as JSON for `stellwerk-cli cs2 json`.
std::string toJson(const LocomotiveFile& file);

} // namespace stellwerk::cs2config
