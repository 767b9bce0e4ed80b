#include "sim/FeedbackService.h"

#include <algorithm>

namespace stellwerk::sim {
namespace {

constexpr std::uint16_t ContactsPerModule = 16;

std::uint32_t key(std::uint16_t device, std::uint16_t contact) {
    return std::uint32_t(device) << 16 | contact;
}

std::uint16_t since(std::chrono::steady_clock::time_point then) {
    using namespace std::chrono;
    const auto ticks = duration_cast<milliseconds>(steady_clock::now() - then).count() / 10;
    return std::uint16_t(std::clamp<long long>(ticks, 0, 0xFFFF));
}

} // namespace

bool FeedbackService::handle(const cs2::Message& m, Outbox& out) {
    if (const auto* request = std::get_if<cs2::S88Poll>(&m.body))
        return poll(*request, m, out), true;
    if (const auto* request = std::get_if<cs2::S88Event>(&m.body))
        return query(*request, m, out), true;
    return false;
}

void FeedbackService::change(std::uint16_t device, std::uint16_t contact, bool occupied, Outbox& out) {
    ContactState& state = state_.contacts[key(device, contact)];
    const bool known = state.changedAt != std::chrono::steady_clock::time_point{};
    if (known && state.occupied == occupied)
        return;
    cs2::S88Change change{std::uint8_t(state.occupied), std::uint8_t(occupied),
                          known ? since(state.changedAt) : std::uint16_t(0)};
    state = {occupied, std::chrono::steady_clock::now()};
    out.respond(cs2::S88Event{device, contact, std::nullopt, std::nullopt, change});
}

// 5.1: one answer per module: contact 1 of a module is the highest bit of its state word.
void FeedbackService::poll(const cs2::S88Poll& request, const cs2::Message& m, Outbox& out) {
    if (!request.moduleCount || !identity_.isOurDevice(request.device))
        return;
    for (std::uint8_t module = 1; module <= *request.moduleCount; ++module) {
        std::uint16_t bits = 0;
        for (std::uint16_t i = 0; i < ContactsPerModule; ++i)
            if (occupied(0, std::uint16_t((module - 1) * ContactsPerModule + i + 1)))
                bits |= std::uint16_t(0x8000 >> i);
        out.respond(cs2::S88Poll{request.device, std::nullopt, module, bits}, m.prio);
    }
}

// 5.2: a query (DLC 4) or registration (DLC 5, DLC 7 for a block of contacts) is answered with the
// contact's state in the DLC 8 form.
void FeedbackService::query(const cs2::S88Event& request, const cs2::Message& m, Outbox& out) {
    if (request.change)
        return; // an event from another feedback device
    const std::uint16_t last = request.lastContact.value_or(request.contact);
    if (last < request.contact || last - request.contact >= MaxContactsPerQuery)
        return;
    for (std::uint32_t contact = request.contact; contact <= last; ++contact)
        out.respond(answer(request.device, std::uint16_t(contact)), m.prio);
}

cs2::S88Event FeedbackService::answer(std::uint16_t device, std::uint16_t contact) const {
    const auto it = state_.contacts.find(key(device, contact));
    const bool state = it != state_.contacts.end() && it->second.occupied;
    const std::uint16_t time = it != state_.contacts.end() ? since(it->second.changedAt) : 0;
    return {device, contact, std::nullopt, std::nullopt,
            cs2::S88Change{std::uint8_t(state), std::uint8_t(state), time}};
}

bool FeedbackService::occupied(std::uint16_t device, std::uint16_t contact) const {
    const auto it = state_.contacts.find(key(device, contact));
    return it != state_.contacts.end() && it->second.occupied;
}

} // namespace stellwerk::sim
