#include "cs2config/LocomotiveEditor.h"

#include "cs2config/Values.h"

#include <algorithm>
#include <fstream>
#include <system_error>

namespace stellwerk::cs2config {

namespace {

constexpr std::uint32_t MfxBase = 0x4000;
constexpr std::uint32_t Sx1Base = 0x0800;
constexpr std::uint32_t DccBase = 0xC000;

std::string trimmedName(const std::string& name) {
    return std::string(trimmed(name));
}

// The protocol family whose addresses must not be used twice (MM2 and MM share the MM2 track format).
int addressFamily(LocomotiveDecoder decoder) {
    switch (decoder) {
    case LocomotiveDecoder::Mm2Prg:
    case LocomotiveDecoder::Mm2Dil8:
    case LocomotiveDecoder::MmPrg:
    case LocomotiveDecoder::Mmm2Lok:
        return 1;
    case LocomotiveDecoder::Dcc:
        return 2;
    case LocomotiveDecoder::Mfx:
        return 3;
    case LocomotiveDecoder::Sx1:
        return 4;
    default:
        return 0;
    }
}

std::string hex(std::uint32_t value) {
    static constexpr char digits[] = "0123456789abcdef";
    std::string text;
    do {
        text.insert(text.begin(), digits[value & 0xF]);
        value >>= 4;
    } while (value != 0);
    return text;
}

} // namespace

std::optional<AddressRange> addressRange(LocomotiveDecoder decoder) {
    switch (decoder) {
    case LocomotiveDecoder::Mm2Dil8: // four three-way DIL switch pairs: 80 addresses
    case LocomotiveDecoder::MmPrg:
        return AddressRange{1, 80};
    case LocomotiveDecoder::Mm2Prg:
    case LocomotiveDecoder::Mmm2Lok:
        return AddressRange{1, 255};
    case LocomotiveDecoder::Dcc:
        return AddressRange{1, 10239};
    case LocomotiveDecoder::Mfx:
        return AddressRange{1, 0x3FFF};
    case LocomotiveDecoder::Sx1:
        return AddressRange{0, 111};
    default:
        return std::nullopt;
    }
}

std::optional<std::uint32_t> locIdOf(LocomotiveDecoder decoder, std::uint32_t address) {
    switch (addressFamily(decoder)) {
    case 1:
        return address;
    case 2:
        return DccBase + address;
    case 3:
        return MfxBase + address;
    case 4:
        return Sx1Base + address;
    default:
        return std::nullopt;
    }
}

LocomotiveSettings LocomotiveSettings::of(const Locomotive& locomotive) {
    LocomotiveSettings settings;
    settings.name = locomotive.name;
    settings.decoder = locomotive.decoder;
    settings.address = locomotive.decoder == LocomotiveDecoder::Mfx && locomotive.sid != 0
                           ? locomotive.sid
                           : locomotive.address;
    for (const Function& function : locomotive.functions)
        if (function.number >= 0)
            settings.functions.push_back(
                {function.number, function.icon, function.trigger(), function.timedValue()});
    return settings;
}

std::string EditProblem::describe() const {
    const std::string range = std::to_string(minimum) + "-" + std::to_string(maximum);
    const std::string key = "F" + std::to_string(function);
    switch (kind) {
    case Kind::EmptyName:
        return "the name is empty";
    case Kind::NameHasBreak:
        return "the name contains a line break";
    case Kind::NameInUse:
        return "the name is already used by another locomotive";
    case Kind::NoDecoder:
        return "choose a decoder type";
    case Kind::AddressOutOfRange:
        return "the address must be " + range;
    case Kind::AddressInUse:
        return "the address is already used by '" + other + "'";
    case Kind::FunctionNumber:
        return key + " is not a function key (F0-F31)";
    case Kind::IconOutOfRange:
        return "the icon of " + key + " must be " + range;
    case Kind::DurationOutOfRange:
        return "the time of " + key + " must be " + range;
    case Kind::NoSuchLocomotive:
        return "no such locomotive";
    }
    return "invalid";
}

std::optional<EditProblem> LocomotiveEditor::check(const LocomotiveSettings& settings,
                                                   std::optional<std::size_t> index) const {
    if (index && *index >= file_.locomotives.size())
        return EditProblem{EditProblem::Kind::NoSuchLocomotive, -1, 0, 0, {}};
    if (auto problem = checkName(settings.name, index))
        return problem;
    if (!addressRange(settings.decoder))
        return EditProblem{EditProblem::Kind::NoDecoder, -1, 0, 0, {}};
    if (auto problem = checkAddress(settings, index))
        return problem;
    return checkFunctions(settings.functions);
}

std::optional<EditProblem> LocomotiveEditor::checkName(const std::string& name,
                                                       std::optional<std::size_t> index) const {
    const std::string wanted = trimmedName(name);
    if (wanted.empty())
        return EditProblem{EditProblem::Kind::EmptyName, -1, 0, 0, {}};
    if (wanted.find_first_of("\r\n") != std::string::npos)
        return EditProblem{EditProblem::Kind::NameHasBreak, -1, 0, 0, {}};
    for (std::size_t i = 0; i < file_.locomotives.size(); ++i)
        if (i != index && file_.locomotives[i].name == wanted)
            return EditProblem{EditProblem::Kind::NameInUse, -1, 0, 0, wanted};
    return std::nullopt;
}

std::optional<EditProblem> LocomotiveEditor::checkAddress(const LocomotiveSettings& settings,
                                                          std::optional<std::size_t> index) const {
    if (index) {
        const LocomotiveSettings before = LocomotiveSettings::of(file_.locomotives[*index]);
        if (before.decoder == settings.decoder && before.address == settings.address)
            return std::nullopt;
    }
    const AddressRange range = *addressRange(settings.decoder);
    if (settings.address < range.minimum || settings.address > range.maximum)
        return EditProblem{EditProblem::Kind::AddressOutOfRange, -1, range.minimum, range.maximum, {}};
    const std::optional<std::uint32_t> uid = locIdOf(settings.decoder, settings.address);
    for (std::size_t i = 0; i < file_.locomotives.size(); ++i) {
        const Locomotive& other = file_.locomotives[i];
        if (i != index && !other.isEmpty() &&
            addressFamily(other.decoder) == addressFamily(settings.decoder) &&
            locIdOf(other.decoder, LocomotiveSettings::of(other).address) == uid)
            return EditProblem{EditProblem::Kind::AddressInUse, -1, 0, 0, other.name};
    }
    return std::nullopt;
}

std::optional<EditProblem> LocomotiveEditor::checkFunctions(const std::vector<FunctionSetting>& functions) {
    for (const FunctionSetting& f : functions) {
        if (f.number < 0 || f.number >= MaxFunctions)
            return EditProblem{EditProblem::Kind::FunctionNumber, f.number, 0, MaxFunctions - 1, {}};
        if (f.icon < 0 || f.icon > MaxIcon)
            return EditProblem{EditProblem::Kind::IconOutOfRange, f.number, 0, MaxIcon, {}};
        if (f.trigger == FunctionTrigger::Timed && (f.duration < 1 || f.duration > MaxDuration))
            return EditProblem{EditProblem::Kind::DurationOutOfRange, f.number, 1, MaxDuration, {}};
    }
    return std::nullopt;
}

std::optional<EditProblem> LocomotiveEditor::apply(std::size_t index, const LocomotiveSettings& settings) {
    if (auto problem = check(settings, index))
        return problem;
    Locomotive& locomotive = file_.locomotives[index];
    const LocomotiveSettings before = LocomotiveSettings::of(locomotive);
    const auto unchanged = [&before](const FunctionSetting& f) {
        const bool emptyKey = f.icon == 0 && f.trigger == FunctionTrigger::Latching;
        const auto known = std::ranges::find(before.functions, f.number, &FunctionSetting::number);
        return known == before.functions.end() ? emptyKey : *known == f;
    };
    if (before.name == trimmedName(settings.name) && before.decoder == settings.decoder &&
        before.address == settings.address && std::ranges::all_of(settings.functions, unchanged))
        return std::nullopt; // nothing changed: the file stays as it was
    write(locomotive, settings);
    modified_ = true;
    return std::nullopt;
}

std::optional<EditProblem> LocomotiveEditor::add(const LocomotiveSettings& settings, std::size_t* index) {
    if (auto problem = check(settings))
        return problem;
    Locomotive locomotive;
    locomotive.direction = TravelDirection::Forward;
    write(locomotive, settings);
    file_.locomotives.push_back(std::move(locomotive));
    if (index)
        *index = file_.locomotives.size() - 1;
    modified_ = true;
    return std::nullopt;
}

bool LocomotiveEditor::remove(std::size_t index) {
    if (index >= file_.locomotives.size())
        return false;
    file_.locomotives.erase(file_.locomotives.begin() + std::ptrdiff_t(index));
    modified_ = true;
    return true;
}

std::size_t LocomotiveEditor::addBoundDecoder(std::uint32_t mfxUid, std::uint16_t sid) {
    modified_ = true;
    for (std::size_t i = 0; i < file_.locomotives.size(); ++i) {
        Locomotive& known = file_.locomotives[i];
        if (known.decoder == LocomotiveDecoder::Mfx && known.mfxUid == mfxUid) {
            known.sid = sid;
            known.address = sid;
            known.uid = MfxBase + sid;
            return i;
        }
    }
    Locomotive locomotive;
    locomotive.name = "mfx " + hex(mfxUid);
    locomotive.decoder = LocomotiveDecoder::Mfx;
    locomotive.sid = sid;
    locomotive.address = sid;
    locomotive.uid = MfxBase + sid;
    locomotive.mfxUid = mfxUid;
    locomotive.functions.push_back(Function{0, 1, 0, 0, {}}); // F0: the light, as every mfx decoder has
    file_.locomotives.push_back(std::move(locomotive));
    return file_.locomotives.size() - 1;
}

std::uint16_t LocomotiveEditor::nextFreeSid() const {
    std::uint32_t highest = 0;
    for (const Locomotive& locomotive : file_.locomotives)
        if (locomotive.decoder == LocomotiveDecoder::Mfx)
            highest = std::max(highest, locomotive.sid);
    return std::uint16_t(std::min<std::uint32_t>(highest + 1, 0x3FFF));
}

void LocomotiveEditor::write(Locomotive& locomotive, const LocomotiveSettings& settings) {
    locomotive.name = trimmedName(settings.name);
    if (locomotive.decoder != settings.decoder ||
        LocomotiveSettings::of(locomotive).address != settings.address) {
        locomotive.decoder = settings.decoder;
        locomotive.address = settings.address;
        if (settings.decoder == LocomotiveDecoder::Mfx)
            locomotive.sid = settings.address;
        locomotive.uid = locIdOf(settings.decoder, settings.address).value_or(locomotive.uid);
    }
    bool added = false;
    for (const FunctionSetting& setting : settings.functions) {
        Function* function = locomotive.function(setting.number);
        if (!function) {
            if (setting.icon == 0 && setting.trigger == FunctionTrigger::Latching)
                continue; // an empty key needs no block
            function = &locomotive.functions.emplace_back();
            function->number = setting.number;
            added = true;
        }
        function->icon = setting.icon;
        // Unknown keeps a `..dauer` this program does not understand as it is.
        if (setting.trigger != FunctionTrigger::Unknown &&
            (function->trigger() != setting.trigger || function->timedValue() != setting.duration))
            function->setTrigger(setting.trigger, setting.duration);
    }
    if (added) // a new key goes to its place among the others
        std::ranges::stable_sort(locomotive.functions, {}, &Function::number);
}

std::optional<std::string> LocomotiveEditor::save(const std::filesystem::path& folder) {
    std::error_code error;
    const std::filesystem::path config = folder / "config";
    std::filesystem::create_directories(config, error);
    if (error)
        return "cannot create " + config.string() + ": " + error.message();
    const std::filesystem::path target = config / "lokomotive.cs2";
    const std::filesystem::path temporary = config / "lokomotive.cs2.new";
    {
        const std::string data = bytes();
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(data.data(), std::streamsize(data.size()));
        out.flush();
        if (!out) {
            std::filesystem::remove(temporary, error);
            return "cannot write " + temporary.string();
        }
    }
    std::filesystem::rename(temporary, target, error);
    if (error) {
        const std::string message = "cannot replace " + target.string() + ": " + error.message();
        std::filesystem::remove(temporary, error);
        return message;
    }
    modified_ = false;
    return std::nullopt;
}

} // namespace stellwerk::cs2config
