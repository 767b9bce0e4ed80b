#include "cs2config/AccessoryType.h"

#include <array>

namespace stellwerk::cs2config {

namespace {

// Where the numbers come from (the protocol document lists the types but not their sizes):
// - One address, positions 0/1 (red/round, green/straight): every turnout and two-aspect signal; the
//   corpus magnetartikel.cs2 files give them consecutive ids.
// - Two addresses: dreiwegweiche and the HP012 signals. GBert's magnetartikel.cs2 numbers its
//   urc_lichtsignal_HP012_SH01 articles 7, 9, 11, ...; TrainControl's has dreiwegweiche 5 followed by 7;
//   TrainControl's route reader (CS2File.parseRoutes) switches id+1 for positions 2 and 3; JCS
//   (fransjacobs/model-railway, AccessoryBean) treats more than two states as a second address.
// - Positions of the HP012 family: Hp0=0, Hp1=1, Hp0+Sh1=2, Hp2=3 (JCS SignalValue); TrainControl's
//   formsignal_HP012 articles and 28 route steps use 0, 1 and 3, never 2. dreiwegweiche takes 0, 1, 2.
// - Single output: std_rot, std_gruen and the uncouplers use one output of an address; the document says
//   `.ungerade` matters for "articles with one aspect", and TrainControl's file pairs uncouplers 29/29b on
//   one id with `.ungerade=1` on the second (the field notes' gleisbild `.artikel = 2 * id + 1`).
//   Positions 0 and 1 are both accepted for them.
// - digitaldrehscheibe: the 7686/7687 turntable decoder listens on keyboard 15, addresses 225-240
//   (h0-modellbahner.de, "Programmierung einer Märklin-Drehscheibe 7686/7687"), 32 outputs, matching the
//   gleisbild tiles drehscheibe_dig_0..31 of document 8.3.5; TrainControl's file has one at 225.
// - Not confirmed by a real file (confirmed = false): K84 outputs (one address switched on/off per output),
//   "DKW 2 Antriebe" (two drives), drehscheibe_alt and schiebebuehne (K84-driven, four gleisbild tiles
//   *_0.._3 in document 8.3.5, so four positions on two addresses), entkupplungsgleis_1 and the signal
//   types that no corpus file uses, which are sized like their confirmed relatives.
constexpr std::uint32_t twoWay = 0b11;
constexpr std::uint32_t threeWay = 0b111;
constexpr std::uint32_t hp012 = 0b1011;
constexpr std::uint32_t fourWay = 0b1111;
constexpr std::uint32_t turntable = 0xFFFFFFFFU;

constexpr AccessoryTypeInfo single(std::string_view key, std::string_view description, bool confirmed) {
    return {key, description, 1, 1, twoWay, true, confirmed};
}

constexpr AccessoryTypeInfo plain(std::string_view key, std::string_view description, bool confirmed) {
    return {key, description, 1, 2, twoWay, false, confirmed};
}

constexpr std::array types = {
    plain("std_rot_gruen", "standard red/green", true),
    single("std_rot", "standard red only", true),
    single("std_gruen", "standard green only", false),
    single("entkupplungsgleis", "uncoupling track", true),
    single("entkupplungsgleis_1", "uncoupling track, gauge 1", false),
    plain("rechtsweiche", "right turnout", true),
    plain("linksweiche", "left turnout", true),
    plain("y_weiche", "Y turnout", false),
    plain("k84_ausgang", "K84 output (off/on)", false),
    AccessoryTypeInfo{"k84_doppelausgang", "K84 double output", 2, 2, twoWay, false, false},
    AccessoryTypeInfo{"dreiwegweiche", "three-way turnout", 2, 3, threeWay, false, true},
    AccessoryTypeInfo{"DKW 2 Antriebe", "double slip, two drives", 2, 4, fourWay, false, false},
    plain("DKW 1 Antrieb", "double slip, one drive", false),
    plain("lichtsignal_HP01", "light signal Hp0/Hp1", true),
    plain("lichtsignal_HP02", "light signal Hp0/Hp2", false),
    AccessoryTypeInfo{"lichtsignal_HP012", "light signal Hp0/Hp1/Hp2", 2, 3, hp012, false, false},
    AccessoryTypeInfo{"lichtsignal_HP012_SH01", "light signal Hp0/Hp1/Hp2/Sh1", 2, 4, fourWay, false, false},
    plain("lichtsignal_SH01", "light signal Sh0/Sh1", true),
    plain("formsignal_HP01", "semaphore Hp0/Hp1", false),
    plain("formsignal_HP02", "semaphore Hp0/Hp2", false),
    AccessoryTypeInfo{"formsignal_HP012", "semaphore Hp0/Hp1/Hp2", 2, 3, hp012, false, true},
    AccessoryTypeInfo{"formsignal_HP012_SH01", "semaphore Hp0/Hp1/Hp2/Sh1", 2, 4, fourWay, false, false},
    plain("formsignal_SH01", "semaphore Sh0/Sh1", false),
    plain("urc_lichtsignal_HP01", "light signal Hp0/Hp1 (URC)", true),
    AccessoryTypeInfo{"urc_lichtsignal_HP012", "light signal Hp0/Hp1/Hp2 (URC)", 2, 3, hp012, false, false},
    AccessoryTypeInfo{"urc_lichtsignal_HP012_SH01", "light signal Hp0/Hp1/Hp2/Sh1 (URC)", 2, 4, fourWay,
                      false, true},
    plain("urc_lichtsignal_SH01", "light signal Sh0/Sh1 (URC)", false),
    AccessoryTypeInfo{"schiebebuehne", "transfer table", 2, 4, fourWay, false, false},
    AccessoryTypeInfo{"drehscheibe_alt", "turntable, old (K84)", 2, 4, fourWay, false, false},
    AccessoryTypeInfo{"digitaldrehscheibe", "digital turntable 7686/7687", 16, 32, turntable, false, true},
};

} // namespace

std::span<const AccessoryTypeInfo> accessoryTypes() {
    return types;
}

const AccessoryTypeInfo* findAccessoryType(std::string_view key) {
    for (const AccessoryTypeInfo& type : types)
        if (type.key == key)
            return &type;
    return nullptr;
}

} // namespace stellwerk::cs2config
