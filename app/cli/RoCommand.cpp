#include "RoCommand.h"

#include "CliNumber.h"
#include "RoCli.h"
#include "bus/Bus.h"
#include "romodule/RoModuleSession.h"

#include <QTimer>
#include <charconv>
#include <cstdio>
#include <memory>
#include <utility>

namespace stellwerk::cli {
namespace {

using romodule::RoModuleSession;

struct RoJob {
    ro::FrameIds ids;
    bool haveIds = false;
    bool json = false;
    int timeoutMs = 100;
    std::string action; // read, write, switch, watch
    std::uint16_t address = 0;
    ro::Width width = ro::Width::Word;
    std::uint32_t value = 0; // write: the value; switch: the relay
    bool on = false;
    std::optional<int> seconds;
};

const char* Usage = "ro: takes --module req=ID,resp=ID[,std] [--json] [--timeout MS] and read ADDRESS WIDTH, "
                    "write ADDRESS WIDTH VALUE, switch RELAY on|off or watch [--seconds N]";

// The action and its operands after the options.
Expected<RoJob, std::string> readAction(RoJob job, const std::vector<std::string>& words) {
    const auto count = words.size();
    job.action = count ? words[0] : "";
    if ((job.action == "read" && count == 3) || (job.action == "write" && count == 4)) {
        const auto address = parseNumber(words[1], 0xFFFF);
        if (!address || !ro::widthFromName(words[2], job.width))
            return std::string("ro ") + job.action + ": ADDRESS is 0..0xFFFF, WIDTH bit, byte, word or long";
        job.address = std::uint16_t(*address);
        const auto value =
            count == 4 ? parseNumber(words[3], ro::maxValue(job.width)) : std::optional<std::uint32_t>(0);
        if (!value)
            return "ro write: VALUE " + words[3] + " does not fit a " + std::string(ro::widthName(job.width));
        job.value = *value;
        return job;
    }
    if (job.action == "switch" && count == 3 && (words[2] == "on" || words[2] == "off")) {
        const auto relay = parseNumber(words[1], 16);
        if (!relay || *relay == 0)
            return std::string("ro switch: RELAY is 1..16");
        job.value = *relay;
        job.on = words[2] == "on";
        return job;
    }
    if (job.action == "watch" && count == 3 && words[1] == "--seconds" &&
        parseNumber(words[2], 86400).value_or(0) > 0)
        job.seconds = int(*parseNumber(words[2], 86400));
    if (job.action == "watch" && (count == 1 || job.seconds))
        return job;
    return std::string(Usage);
}

Expected<RoJob, std::string> parse(const std::vector<std::string>& arguments) {
    RoJob job;
    std::size_t i = 0;
    for (; i < arguments.size() && arguments[i].starts_with("--"); ++i) {
        const std::string& word = arguments[i];
        const bool hasValue = i + 1 < arguments.size();
        if (word == "--json") {
            job.json = true;
        } else if (word == "--module" && hasValue) {
            const auto ids = parseRoModule(arguments[++i]);
            if (!ids)
                return "ro: " + ids.error();
            job.ids = *ids, job.haveIds = true;
        } else if (word == "--timeout" && hasValue && parseNumber(arguments[i + 1], 10000).value_or(0) > 0) {
            job.timeoutMs = int(*parseNumber(arguments[++i], 10000));
        } else if (word == "--seconds" && hasValue && parseNumber(arguments[i + 1], 86400).value_or(0) > 0) {
            job.seconds = int(*parseNumber(arguments[++i], 86400));
        } else {
            return "ro: unknown option '" + word + "'; " + Usage;
        }
    }
    if (!job.haveIds)
        return std::string("ro: --module req=ID,resp=ID[,std] is missing");
    return readAction(job, std::vector<std::string>(arguments.begin() + std::ptrdiff_t(i), arguments.end()));
}

int exitOf(const ro::Outcome& outcome) {
    if (outcome.succeeded())
        return Acknowledged;
    return outcome.kind == ro::Outcome::Kind::NoAnswer ? NotAcknowledged : RefusedByModule;
}

// The module's session on its own view of the station's bus (whose profile names the module), living as
// long as the command.
class RoRun final : public QObject {
public:
    RoRun(StationClient& client, const RoJob& job, std::ostream& out, std::ostream& err)
        : QObject(&client), client_(client), job_(job), out_(out) {
        ro::RoProfile profile = ro::RoProfile::simulator(0);
        profile.name = "RO module";
        profile.ids = job.ids;
        busreading::BusProfile busProfile = busreading::BusProfile::centralStation();
        busProfile.addRoModule(job.ids);
        bus_ = std::make_unique<bus::Bus>(client.transport(), busProfile, QStringLiteral("RO"), this);
        romodule::SessionTiming timing;
        timing.answerTimeout = std::chrono::milliseconds(job.timeoutMs);
        session_ = std::make_unique<RoModuleSession>(*bus_, profile, timing, this);
        if (const QString problem = session_->problem(); !problem.isEmpty()) {
            err << "stellwerk-cli: " << problem.toStdString() << '\n';
            QTimer::singleShot(0, &client, [&client] { client.finish(UsageError); });
            return;
        }
        begin();
    }

private:
    void begin() {
        if (job_.action == "read")
            request(session_->read(job_.address, job_.width));
        else if (job_.action == "write")
            request(session_->write(job_.address, job_.width, job_.value));
        else if (job_.action == "switch")
            switchRelay();
        else
            watch();
    }

    void request(RoModuleSession::RequestId) {
        connect(session_.get(), &RoModuleSession::requestFinished, this,
                [this](RoModuleSession::RequestId, const ro::Outcome& outcome) {
                    print(outcome, job_.action == "read" ? std::optional(outcome.value) : std::nullopt);
                    client_.finish(exitOf(outcome));
                });
    }

    void print(const ro::Outcome& outcome, std::optional<std::uint32_t> value) {
        const int digits = 2 * int(std::max(1u, ro::byteCount(job_.width)));
        const std::string valueText = hexNumber(value.value_or(job_.value), digits);
        if (job_.json)
            out_ << "{\"command\":\"" << job_.action << "\",\"address\":\"" << hexNumber(job_.address, 4)
                 << "\",\"width\":\"" << ro::widthName(job_.width) << "\",\"value\":\"" << valueText
                 << "\",\"answered\":" << (outcome.kind == ro::Outcome::Kind::NoAnswer ? "false" : "true")
                 << ",\"outcome\":\"" << outcome.text() << "\"}\n";
        else
            out_ << job_.action << " address=" << hexNumber(job_.address, 4)
                 << " width=" << ro::widthName(job_.width) << " value=" << valueText << ": " << outcome.text()
                 << '\n';
    }

    void switchRelay() {
        const std::uint32_t bit = 1u << (job_.value - 1);
        const auto done = [this](std::uint32_t relays, const std::string& outcome, int status) {
            if (std::exchange(finished_, true))
                return;
            if (job_.json)
                out_ << "{\"command\":\"switch\",\"relay\":" << job_.value
                     << ",\"on\":" << (job_.on ? "true" : "false") << ",\"relays\":\"" << hexNumber(relays, 4)
                     << "\",\"outcome\":\"" << outcome << "\"}\n";
            else
                out_ << "switch relay=" << job_.value << (job_.on ? " on" : " off") << ": " << outcome
                     << " relays=" << hexNumber(relays, 4) << '\n';
            client_.finish(status);
        };
        connect(session_.get(), &RoModuleSession::outputsChanged, this,
                [this, bit, done](std::uint32_t relays) {
                    if (asked_) {
                        if (((relays & bit) != 0) == job_.on)
                            done(relays, "done", Acknowledged);
                        return;
                    }
                    asked_ = session_->setOutput(int(job_.value), job_.on); // the relays are read: now switch
                    if (!asked_)
                        done(relays, "refused", UsageError);
                });
        connect(session_.get(), &RoModuleSession::outputsFailed, this,
                [this, done](std::uint32_t, const QString& why) {
                    done(session_->outputs().value_or(0), why.toStdString(), NotAcknowledged);
                });
        connect(session_.get(), &RoModuleSession::stateChanged, this, [done](RoModuleSession::State state) {
            if (state == RoModuleSession::State::Offline)
                done(0, "no answer", NotAcknowledged);
        });
        session_->start();
    }

    void watch() {
        connect(session_.get(), &RoModuleSession::stateChanged, this, [this](RoModuleSession::State state) {
            answered_ = answered_ || state == RoModuleSession::State::Online;
            const char* name = state == RoModuleSession::State::Online ? "online" : "offline";
            out_ << (job_.json ? "{\"event\":\"" + std::string(name) + "\"}" : std::string(name))
                 << std::endl;
        });
        connect(session_.get(), &RoModuleSession::inputsChanged, this,
                [this](std::uint32_t inputs, std::uint32_t changed) {
                    if (job_.json)
                        out_ << "{\"event\":\"inputs\",\"inputs\":\"" << hexNumber(inputs, 4)
                             << "\",\"changed\":\"" << hexNumber(changed, 4) << "\"}" << std::endl;
                    else
                        out_ << "inputs=" << hexNumber(inputs, 4) << " changed=" << hexNumber(changed, 4)
                             << std::endl;
                });
        client_.finishOnInterrupt(Acknowledged);
        session_->start();
        if (job_.seconds)
            QTimer::singleShot(*job_.seconds * 1000, this,
                               [this] { client_.finish(answered_ ? Acknowledged : NotAcknowledged); });
    }

    StationClient& client_;
    RoJob job_;
    std::ostream& out_;
    std::unique_ptr<bus::Bus> bus_;
    std::unique_ptr<RoModuleSession> session_;
    bool asked_ = false;
    bool answered_ = false;
    bool finished_ = false;
};

} // namespace

std::optional<ParsedJob> parseRoCommand(const std::string& command, const std::vector<std::string>& arguments,
                                        std::ostream& out, std::ostream& err) {
    if (command != "ro")
        return std::nullopt;
    const auto job = parse(arguments);
    if (!job)
        return ParsedJob(job.error());
    auto start = [job = *job, &out, &err](StationClient& client) { new RoRun(client, job, out, err); };
    return ParsedJob(StationJob{std::move(start), std::nullopt});
}

} // namespace stellwerk::cli
