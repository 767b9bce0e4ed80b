#pragma once

#include "cs2/LocId.h"
#include "cs2/Messages.h"
#include "station/StationUpdates.h"

#include <QObject>
#include <chrono>
#include <cstdint>
#include <optional>

class QTimer;

namespace stellwerk::station {
class StationSession;
struct CommandResult;
} // namespace stellwerk::station

namespace stellwerk::model {

// Which CV of which decoder (document 3.7/3.8): the decoder by its Loc-ID, the CV number and, for mfx
// only, the index.
struct CvTarget {
    cs2::LocId decoder;
    std::uint16_t cv = 1;
    std::uint8_t index = 0;
};

enum class ProgrammingTrack : std::uint8_t { Programming, Main };

// One CV to write, with where and how (DCC modes; bit mode: the value is 1111DBBB, see bitValue).
struct CvWrite {
    CvTarget target;
    std::uint8_t value = 0;
    ProgrammingTrack track = ProgrammingTrack::Programming;
    cs2::DccProgrammingMode mode = cs2::DccProgrammingMode::Direct;

    // The value byte of DCC bit programming: 1111DBBB (D: the bit's value, BBB: its position 0..7).
    static std::uint8_t bitValue(int position, bool on);
};

// What a programming command did; the UI turns it into a sentence in the user's language.
struct ProgrammingResult {
    enum class Task : std::uint8_t { Discovery, Bind, Verify, ReadCv, WriteCv };
    enum class Outcome : std::uint8_t {
        Done,     // carried out (a read value, a written CV, a bound or verified decoder, a found decoder)
        NotFound, // discovery ended without a decoder
        Refused,  // the station answered that it could not do it (no value, not written, wrong SID)
        NoAnswer, // no answer in time
        NotSent,  // the station is not connected
        Invalid,  // refused before sending: see `problem`
        Busy,     // another programming command still runs (the station takes one at a time)
    };
    // Why a request was not sent (Outcome::Invalid).
    enum class Problem : std::uint8_t {
        None,
        NotProgrammable,      // not an MM2, DCC, mfx or SX1 decoder
        Mm2CannotBeRead,      // 3.7: MM2 locomotives cannot be read
        CvOutOfRange,         // `minimum`..`maximum`
        IndexOutOfRange,      // mfx CV index outside `minimum`..`maximum`
        IndexNotMfx,          // a CV index for a decoder that is not mfx
        ProgrammingTrackOnly, // SX1 (and MM2) are written on the programming track only
        ModeNotDcc,           // DCC programming modes for another protocol
        ReservedMode,         // DCC mode 0b11
        BitValueForm,         // bit mode wants 1111DBBB
        NoSid,                // bind/verify with SID 0
    };

    Task task = Task::ReadCv;
    Outcome outcome = Outcome::Done;
    Problem problem = Problem::None;
    int minimum = 0;
    int maximum = 0;
    CvTarget target;                   // ReadCv / WriteCv
    std::optional<std::uint8_t> value; // the value read, or written
    bool verified = false;             // WriteCv: the station read the value back (3.8 result bit 7)
    std::uint32_t mfxUid = 0;          // Discovery / Bind / Verify
    std::uint16_t sid = 0;             // Bind / Verify
    std::optional<std::uint8_t> ask;   // Discovery / Verify: quality of the decoder's answer

    bool succeeded() const { return outcome == Outcome::Done; }
};

// The decoder programming a CS2 offers (document chapter 3): mfx discovery (with its search steps as
// progress), bind and verify, and CV read and write for DCC, mfx, MM2 and SX1 within the ranges the
// document gives. The station takes one programming command at a time and queues none, so neither does
// this: a second request while one runs is answered Busy. Requests the document rules out (reading an
// MM2 decoder, a CV index for DCC) are refused before anything is sent.
class Programmer final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(Programmer)

public:
    // The steps of a full mfx search (ranges 1..32, document 3.1).
    static constexpr int DiscoverySteps = 32;
    // The limits a person may enter, checked again before anything is sent (document 3.7, 3.8): the
    // Programming page takes its ranges from here.
    static constexpr cs2::Protocol Protocols[] = {cs2::Protocol::Mfx, cs2::Protocol::Dcc, cs2::Protocol::Mm2,
                                                  cs2::Protocol::Sx1}; // the programmable ones
    static constexpr int MaxAddress = 0x3FFF; // the widest loco address range (mfx and DCC: 14 bits)
    static constexpr int MaxSid = 0x3FFF;     // an mfx SID is a 14-bit address
    static constexpr int MaxCv = 1023; // the 10-bit CV field; the document's "1024" cannot be expressed
    static constexpr int MaxMm2Cv = 256;
    static constexpr int MaxIndex = 63; // mfx CV index (reading from 0, writing from 1)
    static constexpr int MaxValue = 255;
    static constexpr int MaxBit = 7;

    struct Settings {
        std::chrono::milliseconds answerTimeout{5000};     // reading a CV on the programming track takes time
        std::chrono::milliseconds discoveryTimeout{20000}; // silence during a search
    };

    explicit Programmer(station::StationSession& session, QObject* parent = nullptr);
    Programmer(station::StationSession& session, Settings settings, QObject* parent = nullptr);
    ~Programmer() override;

    bool busy() const { return task_.has_value(); }

    // Each returns false (and reports finished with Busy or Invalid) when the request is not sent.
    bool discover();
    bool bind(std::uint32_t mfxUid, std::uint16_t sid);
    bool verify(std::uint32_t mfxUid, std::uint16_t sid);
    bool readCv(const CvTarget& target);
    bool writeCv(const CvWrite& write);

    // Nullopt when the document allows the request, else why not (result with Outcome::Invalid).
    static std::optional<ProgrammingResult> checkRead(const CvTarget& target);
    static std::optional<ProgrammingResult> checkWrite(const CvWrite& write);

signals:
    // A search step the station reported: `range` of DiscoverySteps bits of the UID are known.
    void discoveryProgress(int range, quint32 uidSoFar);
    void finished(const stellwerk::model::ProgrammingResult& result);

private:
    bool start(ProgrammingResult::Task task);
    bool registration(ProgrammingResult::Task task, std::uint32_t mfxUid, std::uint16_t sid,
                      const cs2::Message& message);
    void request(const cs2::Message& message, ProgrammingResult result);
    void answered(ProgrammingResult result, const station::CommandResult& command);
    void observe(const station::StationUpdates& updates);
    void discoveryAnswer(const cs2::LocoDiscovery& answer);
    void discoveryTimedOut();
    void finish(const ProgrammingResult& result);
    bool refuse(ProgrammingResult result);

    station::StationSession& session_;
    Settings settings_;
    QTimer* discoveryTimer_;
    std::optional<ProgrammingResult::Task> task_;
};

} // namespace stellwerk::model

Q_DECLARE_METATYPE(stellwerk::model::ProgrammingResult)
