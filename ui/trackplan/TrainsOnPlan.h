#pragma once

#include <QString>
#include <cstdint>
#include <map>
#include <vector>

namespace stellwerk::automation {
class Dispatcher;
}

namespace stellwerk::ui {

// What the automation says about each block and connection, read once per change from its dispatcher, so
// that the plan paints from plain values (and a test can read what was painted from): which train is in a
// block or has reserved it, unknown occupants, trains at fault, and the connections of reserved ways.
class TrainsOnPlan final {
public:
    struct BlockState {
        enum class Kind : std::uint8_t { Free, Reserved, Occupied, Ghost, Fault };
        Kind kind = Kind::Free;
        std::uint32_t locId = 0; // the train in it (Occupied, Fault) or that reserved it
        QString train;           // its name
        bool operator==(const BlockState&) const = default;
    };

    static TrainsOnPlan of(const automation::Dispatcher& dispatcher);

    BlockState block(int id) const;
    // The connections reserved for a train's way, in id order.
    std::vector<int> ways() const;
    // The train whose body covers the block; 0 when none.
    std::uint32_t trainIn(int block) const;
    bool operator==(const TrainsOnPlan&) const = default;

private:
    std::map<int, BlockState> m_blocks; // those that are not free
    std::map<int, std::uint32_t> m_ways;
};

} // namespace stellwerk::ui
