#include "ro/Exchange.h"

namespace stellwerk::ro {

std::string Outcome::text() const {
    switch (kind) {
    case Kind::Done:
        return reissued ? "done (read again after a lost answer: change flags may be lost)" : "done";
    case Kind::ConfirmedByDuplicate:
        return "done (confirmed by the module's duplicate job id)";
    case Kind::InvalidCommand:
        return "invalid command (0xFE)";
    case Kind::NoAnswer:
        return "no answer";
    case Kind::JobIdsExhausted:
        return "the module reported every fresh job id as a duplicate (0xFD): another master on it?";
    }
    return "?";
}

Exchange::Exchange(Request request, std::function<std::uint8_t()> freshJob, Limits limits)
    : request_(request), freshJob_(std::move(freshJob)), limits_(limits) {}

Step Exchange::answered(const Answer& answer) {
    if (const auto* ok = std::get_if<OkAnswer>(&answer))
        return onOk(*ok);
    if (const auto* duplicate = std::get_if<DuplicateJobAnswer>(&answer))
        return onDuplicate(*duplicate);
    // 0xFE carries no job id: with one request in flight, it is this one's.
    return finish(Outcome{Outcome::Kind::InvalidCommand});
}

Step Exchange::timedOut() {
    if (transmissions_ > limits_.retries)
        return finish(Outcome{Outcome::Kind::NoAnswer});
    return resend(false);
}

Step Exchange::onOk(const OkAnswer& ok) const {
    if (ok.job != request_.job)
        return Step{}; // an answer to an earlier, timed-out request (or another master's)
    return finish(Outcome{Outcome::Kind::Done, request_.isWrite() ? 0 : ok.value, reissued_});
}

Step Exchange::onDuplicate(const DuplicateJobAnswer& duplicate) {
    if (duplicate.job != request_.job)
        return Step{};
    if (transmissions_ <= 1) {
        // The first copy was refused: the module still remembers this id from someone else.
        if (resyncs_++ >= limits_.resyncs)
            return finish(Outcome{Outcome::Kind::JobIdsExhausted});
        return resend(true);
    }
    if (request_.isWrite())
        return finish(Outcome{Outcome::Kind::ConfirmedByDuplicate});
    if (duplicate.dataBytes >= byteCount(request_.width))
        return finish(
            Outcome{Outcome::Kind::ConfirmedByDuplicate, duplicate.value & maxValue(request_.width)});
    reissued_ = true; // the data went with the lost answer: read again
    return resend(true);
}

Step Exchange::resend(bool freshJob) {
    if (freshJob) {
        request_.job = freshJob_();
        transmissions_ = 0;
    }
    return Step{Step::Kind::Send, std::nullopt};
}

Step Exchange::finish(Outcome outcome) {
    return Step{Step::Kind::Finish, outcome};
}

} // namespace stellwerk::ro
