#pragma once

#include "cs2config/Document.h"
#include "cs2config/LocomotiveValues.h"
#include "cs2config/Node.h"
#include "cs2config/RecordEditor.h"

#include <cstdint>
#include <initializer_list>
#include <string_view>
#include <vector>

namespace stellwerk::cs2config::loco {

// Writes typed values into a record (or a block) and touches a line only when the value it holds
// reads as something else: "0x05" stays when the value is still 5, a value that was not a number
// stays while the typed value is the fallback it was read as. A missing line is added when the
// value differs from what a missing line means, and for required keys of a new record.
class FieldWriter {
public:
    enum class Base { Decimal, Hex };
    enum class Presence { Optional, Required };

    // `fresh`: the record is new, so required keys are written even when they hold the default.
    FieldWriter(Node& record, const LineStyle& style, bool fresh, TextCoding coding = TextCoding::Plain);

    template <class T>
    void number(std::string_view key, T value, T absentMeans, Base base,
                Presence presence = Presence::Optional) {
        const Node* line = record_.find(key);
        if (readNumber(line, absentMeans).value == value && (line || !forced(presence)))
            return;
        writeNumber(key, line, static_cast<std::int64_t>(value), base);
    }
    void text(std::string_view key, std::string_view value, Presence presence = Presence::Optional);
    void direction(std::string_view key, TravelDirection direction);
    // `.typ`: the decoder's name, or `unknownText` for a decoder this program does not know.
    void decoder(std::string_view key, LocomotiveDecoder decoder, std::string_view unknownText);
    bool fresh() const { return fresh_; }

private:
    bool forced(Presence presence) const { return fresh_ && presence == Presence::Required; }
    void writeNumber(std::string_view key, const Node* line, std::int64_t value, Base base);

    Node& record_;
    RecordEditor editor_;
    bool fresh_;
    TextCoding coding_;
};

// The key to write a value under: the alternative spelling when only that one is in the record
// (".xprotokoll" in older files, ".dectyp" in CS3 files).
std::string_view keyInUse(const Node& record, std::string_view key, std::string_view alternative);

// Puts `blocks` in the places of the record's blocks whose key is one of `keys`, one for one; extra
// blocks go after the last old one (at the end of the record when there was none), old places left
// over are removed. Other lines keep their place.
void replaceBlocks(Node& record, std::initializer_list<std::string_view> keys, std::vector<Node> blocks);

// After lines were added or moved: only the record's last line may lack a line end (the file's last
// line); any other line without one gets the style's line end.
void keepFinalEnding(Node& record, const LineStyle& style);

} // namespace stellwerk::cs2config::loco
