#pragma once

#include "cs2config/LocomotiveFile.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::cs2config {

// What a person sets for one function key in the locomotive editor.
struct FunctionSetting {
    int number = 0; // 0 = F0
    int icon = 0;   // ..typ: the number of the icon file; 0 = no icon
    FunctionTrigger trigger = FunctionTrigger::Latching;
    int duration = 0; // for Timed: the time as the station writes it (at least 1)

    friend bool operator==(const FunctionSetting&, const FunctionSetting&) = default;
};

// The part of a locomotive a person edits: name, decoder, address and function keys.
struct LocomotiveSettings {
    std::string name;
    LocomotiveDecoder decoder = LocomotiveDecoder::Mm2Prg;
    std::uint32_t address = 1;              // MM2/DCC/SX1 address, or the SID of an mfx decoder
    std::vector<FunctionSetting> functions; // only the keys to set; keys not listed stay as they are

    // The settings of a locomotive as the file holds it (every function it has).
    static LocomotiveSettings of(const Locomotive& locomotive);
};

// Why the editor refused a change; the UI turns it into a sentence in the user's language.
struct EditProblem {
    enum class Kind : std::uint8_t {
        EmptyName,          // the name is empty (or only spaces)
        NameHasBreak,       // a line break would end the `.name` line
        NameInUse,          // `other` already has this name
        NoDecoder,          // no decoder type, or one Stellwerk cannot write
        AddressOutOfRange,  // outside `minimum`..`maximum` for the decoder
        AddressInUse,       // `other` already uses this protocol address
        FunctionNumber,     // `function` is not F0..F31
        IconOutOfRange,     // the icon of `function` is outside `minimum`..`maximum`
        DurationOutOfRange, // the time of timed `function` is outside `minimum`..`maximum`
        NoSuchLocomotive,   // the index names no locomotive
    };

    Kind kind = Kind::EmptyName;
    int function = -1;
    std::int64_t minimum = 0;
    std::int64_t maximum = 0;
    std::string other; // the name of the locomotive the value collides with

    // The problem in English, for logs and the command line.
    std::string describe() const;
};

// The addresses a decoder type allows (MM with DIL switches 1-80, programmable MM2 1-255, DCC 1-10239,
// mfx SID 1-16383, SX1 0-111); nullopt for a decoder without a known range.
struct AddressRange {
    std::uint32_t minimum = 1;
    std::uint32_t maximum = 1;
};
std::optional<AddressRange> addressRange(LocomotiveDecoder decoder);

// The Loc-ID (`.uid`) of a locomotive with this decoder and address (mfx: 0x4000 + SID).
std::optional<std::uint32_t> locIdOf(LocomotiveDecoder decoder, std::uint32_t address);

// Changes lokomotive.cs2 the way a person edits it at the station: checks each change first (ranges,
// names and addresses in use), then writes only the values that changed into the locomotive's record,
// so that every other line, record and unknown key of the file comes back byte for byte.
class LocomotiveEditor {
public:
    static constexpr int MaxIcon = 511;
    // The highest address any decoder type allows (the mfx SID, see addressRange()): the editor's address
    // field goes this far and the editor explains what the chosen decoder allows.
    static constexpr std::uint32_t MaxAddress = 0x3FFF;
    static constexpr int MaxDuration = 255;
    static constexpr int MaxFunctions = 32;

    LocomotiveEditor() = default;
    explicit LocomotiveEditor(LocomotiveFile file) : file_(std::move(file)) {}

    const LocomotiveFile& file() const { return file_; }
    const std::vector<Locomotive>& locomotives() const { return file_.locomotives; }
    // True once a change was applied and not yet saved.
    bool modified() const { return modified_; }
    void markSaved() { modified_ = false; }

    // The first problem of these settings for the locomotive at `index` (nullopt: a new locomotive),
    // or nullopt when they can be applied. The address is checked only when it or the decoder changes,
    // so that a file's own odd value does not block renaming.
    std::optional<EditProblem> check(const LocomotiveSettings& settings,
                                     std::optional<std::size_t> index = std::nullopt) const;
    // Checks and applies; the problem when refused (nothing changed then).
    std::optional<EditProblem> apply(std::size_t index, const LocomotiveSettings& settings);
    // Checks and appends a new locomotive record; its index, or the problem.
    std::optional<EditProblem> add(const LocomotiveSettings& settings, std::size_t* index = nullptr);
    bool remove(std::size_t index);
    // Adds an mfx decoder that was just bound to `sid`, named "mfx <uid>" unless a locomotive with
    // this mfx UID is already in the file (then its SID is updated). Returns its index.
    std::size_t addBoundDecoder(std::uint32_t mfxUid, std::uint16_t sid);
    // The lowest SID above every SID the file's mfx locomotives use.
    std::uint16_t nextFreeSid() const;

    // The file's bytes with every applied change.
    std::string bytes() const { return file_.write().serialize(); }
    // Writes <folder>/config/lokomotive.cs2 atomically (a temporary file, then renamed); the error
    // in English when that failed (the old file is then untouched).
    std::optional<std::string> save(const std::filesystem::path& folder);

private:
    std::optional<EditProblem> checkName(const std::string& name, std::optional<std::size_t> index) const;
    std::optional<EditProblem> checkAddress(const LocomotiveSettings& settings,
                                            std::optional<std::size_t> index) const;
    static std::optional<EditProblem> checkFunctions(const std::vector<FunctionSetting>& functions);
    static void write(Locomotive& locomotive, const LocomotiveSettings& settings);

    LocomotiveFile file_;
    bool modified_ = false;
};

} // namespace stellwerk::cs2config
