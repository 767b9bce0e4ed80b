#include "DriveCommands.h"

#include "LocArgument.h"

#include <functional>
#include <ostream>

namespace stellwerk::cli {
namespace {

using Arguments = std::vector<std::string>;

// One command to send, how to name it in the result line, and what the answer (or the answer to a
// follow-up query) adds to that line.
struct Order {
    cs2::MessageBody body;
    std::string description;
    std::function<std::string(const cs2::Message& answer)> outcome = [](const cs2::Message&) {
        return std::string();
    };
    std::optional<cs2::MessageBody> query = std::nullopt; // asked after the acknowledgement, for `outcome`
};

std::string failureText(const station::CommandResult& result) {
    switch (result.status) {
    case station::CommandResult::Status::Rejected:
        return "rejected by the station";
    case station::CommandResult::Status::TimedOut:
        return "no acknowledgement after " + std::to_string(result.attempts) + " attempt(s)";
    case station::CommandResult::Status::NotSent:
        return "not sent (the transport refused the frame)";
    default:
        return station::commandStatusName(result.status);
    }
}

cs2::Message request(const cs2::MessageBody& body) {
    return cs2::Message{0, false, 0, body};
}

void reportSuccess(StationClient& client, const Order& order, const std::optional<cs2::Message>& answer,
                   std::ostream& out) {
    out << "ok: " << order.description << (answer ? order.outcome(*answer) : "") << " (acknowledged)\n";
    client.finish(Acknowledged);
}

void sendOrder(StationClient& client, const Order& order, std::ostream& out, std::ostream& err) {
    client.session().request(
        request(order.body), [order, &out, &err, &client](const station::CommandResult& result) {
            if (!result.succeeded()) {
                err << "error: " << order.description << ": " << failureText(result) << '\n';
                return client.finish(NotAcknowledged);
            }
            if (!order.query)
                return reportSuccess(client, order, result.answer, out);
            client.session().request(
                request(*order.query), [order, &out, &client](const station::CommandResult& asked) {
                    reportSuccess(client, order, asked.succeeded() ? asked.answer : std::nullopt, out);
                });
        });
}

StationJob acknowledged(Order order, std::ostream& out, std::ostream& err) {
    auto start = [order = std::move(order), &out, &err](StationClient& client) {
        sendOrder(client, order, out, err);
    };
    return {std::move(start), std::chrono::milliseconds(10000)};
}

ParsedJob usage(const std::string& synopsis) {
    return std::string("usage: stellwerk-cli --station URL " + synopsis);
}

ParsedJob speed(const Arguments& a, std::ostream& out, std::ostream& err) {
    if (a.size() != 2)
        return usage("speed LOC 0-1000");
    const auto loco = parseLocomotive(a[0]);
    const auto value = parseSpeed(a[1]);
    if (!loco || !value)
        return !loco ? loco.error() : value.error();
    return acknowledged(
        {cs2::LocoSpeed{*loco, *value}, "loco " + locomotiveText(*loco) + " speed " + std::to_string(*value)},
        out, err);
}

ParsedJob direction(const Arguments& a, std::ostream& out, std::ostream& err) {
    if (a.size() != 2)
        return usage("direction LOC forward|backward|toggle");
    const auto loco = parseLocomotive(a[0]);
    const auto value = parseDirection(a[1]);
    if (!loco || !value)
        return !loco ? loco.error() : value.error();
    Order order{cs2::LocoDirection{*loco, std::uint8_t(*value)},
                "loco " + locomotiveText(*loco) + " direction " +
                    std::string(directionText(std::uint8_t(*value)))};
    if (*value == cs2::Direction::Toggle) { // the answer echoes "toggle": ask where the loco now goes
        order.query = cs2::LocoDirection{*loco, std::nullopt};
        order.outcome = [](const cs2::Message& answer) {
            const auto* confirmed = std::get_if<cs2::LocoDirection>(&answer.body);
            return confirmed && confirmed->direction
                       ? " -> " + std::string(directionText(*confirmed->direction))
                       : std::string();
        };
    }
    return acknowledged(std::move(order), out, err);
}

ParsedJob function(const Arguments& a, std::ostream& out, std::ostream& err) {
    if (a.size() != 3)
        return usage("function LOC 0-31 on|off");
    const auto loco = parseLocomotive(a[0]);
    const auto number = parseFunctionNumber(a[1]);
    const auto on = parseOnOff(a[2]);
    if (!loco || !number || !on)
        return !loco ? loco.error() : !number ? number.error() : on.error();
    return acknowledged(
        {cs2::LocoFunction{*loco, *number, std::uint8_t(*on ? 1 : 0), std::nullopt},
         "loco " + locomotiveText(*loco) + " function " + std::to_string(*number) + (*on ? " on" : " off")},
        out, err);
}

ParsedJob switchAccessory(const Arguments& a, std::ostream& out, std::ostream& err) {
    if (a.size() != 2)
        return usage("switch ADDR POSITION");
    const auto article = parseAccessory(a[0]);
    const auto position = parsePosition(a[1]);
    if (!article || !position)
        return !article ? article.error() : position.error();
    // Current 1 with DLC 6: the station switches the output off after its default time (4.1).
    return acknowledged({cs2::AccessorySwitch{*article, *position, 1, std::nullopt},
                         "accessory " + accessoryText(*article) + " position " + std::to_string(*position)},
                        out, err);
}

ParsedJob power(const std::string& command, const Arguments& a, std::ostream& out, std::ostream& err) {
    if (a.size() > 1)
        return usage(command + " [UID]");
    std::uint32_t target = 0; // every station
    if (!a.empty()) {
        const auto uid = parseUid(a[0]);
        if (!uid)
            return uid.error();
        target = *uid;
    }
    const std::string description = "system " + command + (a.empty() ? "" : " " + a[0]);
    if (command == "stop")
        return acknowledged({cs2::SystemStop{target}, description}, out, err);
    if (command == "go")
        return acknowledged({cs2::SystemGo{target}, description}, out, err);
    return acknowledged({cs2::SystemHalt{target}, description}, out, err);
}

} // namespace

std::optional<ParsedJob> parseDriveCommand(const std::string& command, const Arguments& arguments,
                                           std::ostream& out, std::ostream& err) {
    if (command == "speed")
        return speed(arguments, out, err);
    if (command == "direction")
        return direction(arguments, out, err);
    if (command == "function")
        return function(arguments, out, err);
    if (command == "switch")
        return switchAccessory(arguments, out, err);
    if (command == "stop" || command == "go" || command == "halt")
        return power(command, arguments, out, err);
    return std::nullopt;
}

} // namespace stellwerk::cli
