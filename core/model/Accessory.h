#pragma once

#include "cs2/LocId.h"
#include "cs2config/AccessoryFile.h"

#include <QString>
#include <cstdint>
#include <optional>

namespace stellwerk::model {

// Where one position of an accessory goes on the wire: the decoder address and its output.
struct AccessoryOutput {
    cs2::LocId address;
    std::uint8_t output = 0; // the position byte of command 0x0B
};

// A turnout, signal, uncoupler or turntable of the station's keyboard (magnetartikel.cs2) and the
// position the station last confirmed. Knows how its positions map onto its decoder addresses: an
// article with two addresses (three-way turnout, Hp0/1/2 signal) puts positions 2 and 3 on the second
// address, as the CS2 route files and TrainControl do (see cs2config/AccessoryType.cpp).
class Accessory {
public:
    Accessory() = default;
    static Accessory fromFile(const cs2config::Accessory& record);

    std::int64_t id() const { return id_; } // the 1-based keyboard number
    const QString& name() const { return name_; }
    const QString& type() const { return type_; }
    const cs2config::AccessoryTypeInfo* typeInfo() const { return cs2config::findAccessoryType(typeKey_); }
    int positionCount() const;
    int addressCount() const { return addresses_; }
    bool isDcc() const { return dcc_; }
    std::optional<std::int64_t> switchTimeMs() const { return switchTimeMs_; }
    bool acceptsPosition(int position) const;

    int position() const { return position_; }
    // Whether the bus showed the position since the model's state was last lost (the CS2 has no query
    // for it: after a reconnect it stays "not reported" until the accessory is switched or reported).
    bool isPositionReported() const { return positionReported_; }
    // Returns true when the position changed or became reported.
    bool confirmPosition(int position);
    // The station can no longer be heard: the position becomes "not reported" (and stays as it was).
    void forgetReported() { positionReported_ = false; }

    // The address and output that show `position`; nullopt when the article does not have it.
    std::optional<AccessoryOutput> outputFor(int position) const;
    // The wire address of the n-th address of the article (0-based).
    std::optional<cs2::LocId> address(int n) const;
    // The position an output of the n-th address stands for.
    int positionOf(int addressIndex, std::uint8_t output) const;

private:
    std::int64_t id_ = 0;
    QString name_;
    QString type_;
    std::string typeKey_;
    int addresses_ = 1;
    bool dcc_ = false;
    std::optional<std::int64_t> switchTimeMs_;
    int position_ = 0;
    bool positionReported_ = false;
};

} // namespace stellwerk::model
