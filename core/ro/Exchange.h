#pragma once

#include "ro/Messages.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace stellwerk::ro {

// How one request to a module ended (notes B3.3).
struct Outcome {
    enum class Kind : std::uint8_t {
        Done,                 // an OK with our job id (a read's data in `value`)
        ConfirmedByDuplicate, // a retransmission earned 0xFD: the first copy was executed, its answer lost
        InvalidCommand,       // 0xFE: the module refused the request; not retried
        NoAnswer,             // no answer after the retries: the module is taken as offline
        JobIdsExhausted,      // 0xFD to every fresh job id: another master keeps using ours
    };
    Kind kind = Kind::Done;
    std::uint32_t value = 0;
    // A read was sent again with a new job id after 0xFD without data: any read-to-clear flags that the
    // lost answer carried are gone (notes B3.3, R14).
    bool reissued = false;

    bool succeeded() const { return kind == Kind::Done || kind == Kind::ConfirmedByDuplicate; }
    std::string text() const;
};

// What to do after an answer or a timeout.
struct Step {
    enum class Kind : std::uint8_t {
        Wait,  // the answer was someone else's or an earlier one (stale): keep waiting
        Send,  // send request() (again): same job id after a timeout, a fresh one after a resync
        Finish // the request is over: see outcome
    };
    Kind kind = Kind::Wait;
    std::optional<Outcome> outcome;
};

// One request to an RO module from the first transmission to its outcome: the stop-and-wait rules of the
// notes (B3.3), since the document gives no timeouts and its answers carry no address and 0xFE not even a
// job id. A timeout resends with the same job id, so that 0xFD can tell a lost request from a lost answer;
// 0xFD on a first transmission means the module remembers the id from someone else, so a fresh one is
// taken. Pure: the caller owns the timer, the wire and the job counter (`freshJob`).
class Exchange {
public:
    struct Limits {
        int retries = 2; // transmissions after the first, on timeouts
        int resyncs = 2; // fresh job ids after 0xFD on a first transmission
    };

    Exchange(Request request, std::function<std::uint8_t()> freshJob, Limits limits);

    const Request& request() const { return request_; }
    // The request is (about to be) on the wire: count the transmission.
    void sent() { ++transmissions_; }
    int transmissions() const { return transmissions_; }
    Step answered(const Answer& answer);
    Step timedOut();

private:
    Step onOk(const OkAnswer& ok) const;
    Step onDuplicate(const DuplicateJobAnswer& duplicate);
    Step resend(bool freshJob);
    static Step finish(Outcome outcome);

    Request request_;
    std::function<std::uint8_t()> freshJob_;
    Limits limits_;
    int transmissions_ = 0; // of the current job id
    int resyncs_ = 0;
    bool reissued_ = false;
};

} // namespace stellwerk::ro
