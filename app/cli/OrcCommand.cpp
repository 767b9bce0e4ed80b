#include "OrcCommand.h"

#include "CliNumber.h"
#include "bus/Bus.h"
#include "orccentral/OrcSession.h"

#include <QTimer>
#include <charconv>
#include <cstdio>
#include <memory>

namespace stellwerk::cli {
namespace {

using orccentral::OrcDevice;
using orccentral::OrcSession;

struct OrcJob {
    bool json = false;
    std::optional<int> seconds;
    std::string action; // find, switch, watch
    std::uint16_t target = 0;
    std::uint8_t position = 0;
};

const char* Usage = "orc: takes [--json] [--seconds N] and find, switch TARGET POS or watch";

Expected<OrcJob, std::string> readAction(OrcJob job, const std::vector<std::string>& words) {
    job.action = words.empty() ? "" : words[0];
    if ((job.action == "find" || job.action == "watch") && words.size() == 1)
        return job;
    if (job.action == "switch" && words.size() == 3) {
        const auto target = parseNumber(words[1], 0xFFFF);
        const auto position = parseNumber(words[2], 0xFF);
        if (!target || !position)
            return std::string("orc switch: TARGET is a Ziel-Id 0..0xFFFF, POS 0..255");
        job.target = std::uint16_t(*target);
        job.position = std::uint8_t(*position);
        return job;
    }
    return std::string(Usage);
}

Expected<OrcJob, std::string> parse(const std::vector<std::string>& arguments) {
    OrcJob job;
    std::size_t i = 0;
    for (; i < arguments.size() && arguments[i].starts_with("--"); ++i) {
        const std::string& word = arguments[i];
        if (word == "--json") {
            job.json = true;
        } else if (word == "--seconds" && i + 1 < arguments.size() &&
                   parseNumber(arguments[i + 1], 86400).value_or(0) > 0) {
            job.seconds = int(*parseNumber(arguments[++i], 86400));
        } else {
            return "orc: unknown option '" + word + "'; " + Usage;
        }
    }
    return readAction(job, std::vector<std::string>(arguments.begin() + std::ptrdiff_t(i), arguments.end()));
}

const char* stateName(OrcDevice::State state) {
    switch (state) {
    case OrcDevice::State::Assigning:
        return "assigning";
    case OrcDevice::State::Online:
        return "online";
    case OrcDevice::State::Offline:
        return "offline";
    case OrcDevice::State::Unassigned:
        return "unassigned";
    }
    return "?";
}

const char* typeName(std::uint8_t type) {
    static const char* const names[] = {"system", "loco", "can-decoder", "can-encoder"};
    return type < 4 ? names[type] : "legacy";
}

// The central on its own view of the station's bus (ORC beside the CS2), living as long as the command.
class OrcRun final : public QObject {
public:
    OrcRun(StationClient& client, const OrcJob& job, std::ostream& out)
        : QObject(&client), client_(client), job_(job), out_(out) {
        bus_ = std::make_unique<bus::Bus>(client.transport(), busreading::BusProfile::openRailCan(),
                                          QStringLiteral("ORC"), this);
        session_ = std::make_unique<OrcSession>(*bus_, OrcSession::Settings{}, this);
        if (job_.action == "find")
            find();
        else if (job_.action == "switch")
            switchOutputs();
        else
            watch();
    }

private:
    void find() {
        session_->start();
        QTimer::singleShot(job_.seconds.value_or(1) * 1000, this, [this] {
            int answered = 0;
            for (const OrcDevice& device : session_->devices()) {
                printDevice(device);
                answered += device.state == OrcDevice::State::Online ? 1 : 0;
            }
            if (!job_.json)
                out_ << answered << " device(s) answered\n";
            client_.finish(answered ? Acknowledged : NotAcknowledged);
        });
    }

    void printDevice(const OrcDevice& device) {
        if (job_.json)
            out_ << "{\"event\":\"device\",\"uid\":\"" << hexNumber(device.uid, 8) << "\",\"busId\":\""
                 << hexNumber(device.busId, 4) << "\",\"type\":\"" << typeName(device.type)
                 << "\",\"version\":\"" << hexNumber(device.version, 4) << "\",\"state\":\""
                 << stateName(device.state) << "\"}" << std::endl;
        else
            out_ << "device uid=" << hexNumber(device.uid, 8) << " busId=" << hexNumber(device.busId, 4)
                 << " type=" << typeName(device.type) << " version=" << hexNumber(device.version, 4) << ' '
                 << stateName(device.state) << std::endl;
    }

    void switchOutputs() {
        connect(session_.get(), &OrcSession::switchReported, this,
                [this](std::uint16_t target, std::uint8_t position, OrcSession::SwitchResult result) {
                    if (target != job_.target)
                        return;
                    const bool confirmed = result == OrcSession::SwitchResult::Confirmed;
                    const char* outcome = confirmed ? "confirmed" : "sent, unconfirmed";
                    if (job_.json)
                        out_ << "{\"command\":\"switch\",\"target\":\"" << hexNumber(target, 4)
                             << "\",\"position\":\"" << hexNumber(position, 2)
                             << "\",\"answered\":" << (confirmed ? "true" : "false") << ",\"outcome\":\""
                             << outcome << "\"}\n";
                    else
                        out_ << "switch target=" << hexNumber(target, 4)
                             << " position=" << hexNumber(position, 2) << ": " << outcome << '\n';
                    client_.finish(confirmed ? Acknowledged : NotAcknowledged);
                });
        session_->switchOutputs(job_.target, job_.position);
    }

    void watch() {
        connect(session_.get(), &OrcSession::deviceChanged, this, [this](std::uint32_t uid) {
            if (const OrcDevice* device = session_->device(uid)) {
                answered_ = answered_ || device->state == OrcDevice::State::Online;
                printDevice(*device);
            }
        });
        connect(session_.get(), &OrcSession::inputsChanged, this,
                [this](std::uint16_t encoder, std::uint32_t inputs, std::uint32_t changed) {
                    if (job_.json)
                        out_ << "{\"event\":\"inputs\",\"encoder\":\"" << hexNumber(encoder, 4)
                             << "\",\"inputs\":\"" << hexNumber(inputs, 8) << "\",\"changed\":\""
                             << hexNumber(changed, 8) << "\"}" << std::endl;
                    else
                        out_ << "inputs encoder=" << hexNumber(encoder, 4)
                             << " inputs=" << hexNumber(inputs, 8) << " changed=" << hexNumber(changed, 8)
                             << std::endl;
                });
        connect(session_.get(), &OrcSession::overloadChanged, this,
                [this](std::uint16_t busId, std::uint8_t port, std::uint8_t kind) {
                    out_ << (job_.json ? "{\"event\":\"overload\",\"busId\":\"" : "overload busId=")
                         << hexNumber(busId, 4) << (job_.json ? "\",\"port\":" : " port=") << int(port)
                         << (job_.json ? ",\"kind\":" : " kind=") << int(kind) << (job_.json ? "}" : "")
                         << std::endl;
                });
        client_.finishOnInterrupt(Acknowledged);
        session_->start();
        if (job_.seconds)
            QTimer::singleShot(*job_.seconds * 1000, this,
                               [this] { client_.finish(answered_ ? Acknowledged : NotAcknowledged); });
    }

    StationClient& client_;
    OrcJob job_;
    std::ostream& out_;
    std::unique_ptr<bus::Bus> bus_;
    std::unique_ptr<OrcSession> session_;
    bool answered_ = false;
};

} // namespace

std::optional<ParsedJob> parseOrcCommand(const std::string& command,
                                         const std::vector<std::string>& arguments, std::ostream& out,
                                         std::ostream&) {
    if (command != "orc")
        return std::nullopt;
    const auto job = parse(arguments);
    if (!job)
        return ParsedJob(job.error());
    auto start = [job = job.value(), &out](StationClient& client) { new OrcRun(client, job, out); };
    return ParsedJob(StationJob{std::move(start), std::nullopt});
}

} // namespace stellwerk::cli
