#include "HandheldCommand.h"

#include "binding/RailwayBinding.h"
#include "bus/Bus.h"
#include "connection/HandheldConnection.h"
#include "station/StartupSequence.h"

#include <QObject>
#include <QTimer>
#include <cstdio>
#include <memory>

namespace stellwerk::cli {
namespace {

using mcanhandhelds::HandheldEvent;

struct HandheldOptions {
    bool json = false;
    connection::HandheldRole role = connection::HandheldRole::Automatic;
    std::optional<int> seconds;
};

std::string hex(std::uint32_t value, int digits) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "0x%0*X", digits, unsigned(value));
    return buffer;
}

std::string_view eventName(HandheldEvent::Kind kind) {
    switch (kind) {
    case HandheldEvent::Kind::LoggedIn:
        return "login";
    case HandheldEvent::Kind::UpgradeDone:
        return "upgrade-done";
    case HandheldEvent::Kind::LocoTaken:
        return "loco-taken";
    case HandheldEvent::Kind::LocoRefused:
        return "loco-refused";
    case HandheldEvent::Kind::LocoReleased:
        return "loco-released";
    case HandheldEvent::Kind::Speed:
        return "speed";
    case HandheldEvent::Kind::Function:
        return "function";
    case HandheldEvent::Kind::Stop:
        return "stop";
    case HandheldEvent::Kind::Go:
        return "go";
    case HandheldEvent::Kind::Silent:
        return "silent";
    case HandheldEvent::Kind::Back:
        return "back";
    case HandheldEvent::Kind::Lost:
        return "lost";
    case HandheldEvent::Kind::FlashMode:
        return "boot-loader";
    case HandheldEvent::Kind::Watching:
        return "watching";
    case HandheldEvent::Kind::Renamed:
        return "renamed";
    }
    return "event";
}

// A name from the bus, printable ASCII only (a device cannot put terminal escapes on the screen).
std::string printable(const QString& text) {
    std::string shown;
    for (const QChar c : text)
        shown += c.unicode() >= 0x20 && c.unicode() < 0x7F && c != QLatin1Char('"') && c != QLatin1Char('\\')
                     ? char(c.unicode())
                     : '?';
    return shown;
}

std::string_view watchingName(mcanhandhelds::Watching why) {
    switch (why) {
    case mcanhandhelds::Watching::No:
        return "no";
    case mcanhandhelds::Watching::UntilDevicesKnown:
        return "devices-not-known-yet";
    case mcanhandhelds::Watching::CentralStation:
        return "central-station";
    case mcanhandhelds::Watching::AnotherMaster:
        return "another-master";
    case mcanhandhelds::Watching::Asked:
        return "asked";
    }
    return "unknown";
}

// What an event adds to its line: the locomotive, the speed, the function, why it only watches.
std::vector<std::pair<std::string, std::string>> details(const HandheldEvent& event) {
    std::vector<std::pair<std::string, std::string>> fields;
    if (event.kind == HandheldEvent::Kind::Watching) {
        fields.emplace_back("reason", std::string(watchingName(mcanhandhelds::Watching(event.value))));
        if (event.function)
            fields.emplace_back("node", std::to_string(event.function));
        return fields;
    }
    if (event.locId)
        fields.emplace_back("loco", hex(event.locId, 4));
    if (event.kind == HandheldEvent::Kind::Speed) {
        fields.emplace_back("speed", std::to_string(event.value));
        fields.emplace_back("direction", event.forward ? "forward" : "reverse");
    }
    if (event.kind == HandheldEvent::Kind::Function) {
        fields.emplace_back("function", std::to_string(event.function));
        fields.emplace_back("on", event.on ? "true" : "false");
    }
    return fields;
}

std::string eventLine(const HandheldEvent& event, bool json) {
    const std::string name = printable(event.name);
    const auto fields = details(event);
    std::string line;
    if (json) {
        line = "{\"event\":\"" + std::string(eventName(event.kind)) + "\"";
        if (event.uid)
            line += ",\"uid\":\"" + hex(event.uid, 8) + "\"";
        line += ",\"name\":\"" + name + "\"";
        for (const auto& [key, value] : fields)
            line +=
                ",\"" + key + "\":" +
                (key == "speed" || key == "function" || key == "on" || key == "node" ? value
                                                                                     : "\"" + value + "\"");
        return line + "}";
    }
    line = std::string(eventName(event.kind));
    if (event.uid)
        line += " " + hex(event.uid, 8);
    if (!name.empty())
        line += " \"" + name + "\"";
    for (const auto& [key, value] : fields)
        line += " " + key + "=" + value;
    return line;
}

// The master, the railway it drives (bound by the RailwayBinding) and the start-up that loads the railway,
// living as long as the command.
class HandheldRun final : public QObject {
public:
    HandheldRun(StationClient& client, const HandheldOptions& options, std::ostream& out, std::ostream& err)
        : QObject(&client), out_(out), err_(err) {
        connection::HandheldSettings settings;
        settings.role = options.role;
        handhelds_ = std::make_unique<connection::HandheldConnection>(client.bus(), settings, this);
        connect(&handhelds_->master(), &mcanhandhelds::HandheldMaster::event, this,
                [this, json = options.json](const HandheldEvent& event) {
                    out_ << eventLine(event, json) << std::endl;
                });
        railways_ = std::make_unique<binding::RailwayBinding>();
        railways_->sessionStarted(client.session(), &handhelds_->master());
        startup_ = std::make_unique<station::StartupSequence>(client.session());
        connect(startup_.get(), &station::StartupSequence::problem, this,
                [this](const QString& message) { err_ << "note: " << message.toStdString() << '\n'; });
        connect(startup_.get(), &station::StartupSequence::ready, this,
                [this](const station::StartupResult& result) {
                    railways_->configurationLoaded(result);
                    handhelds_->devicesListed(result.devices);
                    const mcanhandhelds::HandheldMaster& master = handhelds_->master();
                    err_ << (master.isMaster()
                                 ? std::string("Stellwerk is the handhelds' master; Ctrl+C ends\n")
                                 : "watching the handhelds only (" +
                                       std::string(watchingName(master.watching())) + "); Ctrl+C ends\n");
                });
        startup_->start();
    }
    ~HandheldRun() override {
        startup_.reset(); // before the railway: the start-up feeds it
        railways_.reset();
    }

private:
    std::ostream& out_;
    std::ostream& err_;
    std::unique_ptr<connection::HandheldConnection> handhelds_;
    std::unique_ptr<binding::RailwayBinding> railways_;
    std::unique_ptr<station::StartupSequence> startup_;
};

ParsedJob handhelds(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
    HandheldOptions options;
    for (std::size_t i = 0; i < arguments.size(); ++i) {
        const std::string& word = arguments[i];
        if (word == "--json")
            options.json = true;
        else if (word == "--master")
            options.role = connection::HandheldRole::Master;
        else if (word == "--watch")
            options.role = connection::HandheldRole::Watch;
        else if (word == "--seconds" && i + 1 < arguments.size() && std::atoi(arguments[i + 1].c_str()) > 0)
            options.seconds = std::atoi(arguments[++i].c_str());
        else
            return "handhelds: unknown argument '" + word +
                   "' (takes --json, --master, --watch, --seconds N)";
    }
    auto start = [options, &out, &err](StationClient& client) {
        client.finishOnInterrupt(Acknowledged); // Ctrl+C: stop answering; the handhelds log in again later
        new HandheldRun(client, options, out, err);
        if (options.seconds)
            QTimer::singleShot(*options.seconds * 1000, &client, [&client] { client.finish(Acknowledged); });
    };
    return StationJob{std::move(start), std::nullopt};
}

} // namespace

std::optional<ParsedJob> parseHandheldCommand(const std::string& command,
                                              const std::vector<std::string>& arguments, std::ostream& out,
                                              std::ostream& err) {
    if (command != "handhelds")
        return std::nullopt;
    return handhelds(arguments, out, err);
}

} // namespace stellwerk::cli
