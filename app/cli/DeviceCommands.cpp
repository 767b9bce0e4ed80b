#include "DeviceCommands.h"

#include "LocArgument.h"

#include <QTimer>
#include <cstdio>
#include <deque>
#include <memory>
#include <ostream>

namespace stellwerk::cli {
namespace {

// How long devices have to answer a ping.
constexpr std::chrono::milliseconds PingWindow{700};

std::string hex(std::uint32_t value, int digits) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "0x%0*X", digits, unsigned(value));
    return buffer;
}

std::string deviceLine(const cs2::DeviceIdentity& device) {
    return hex(device.uid, 8) + "  version " + std::to_string(device.versionMajor) + "." +
           std::to_string(device.versionMinor) + "  type " + hex(device.deviceType, 4) + "  " +
           std::string(cs2::deviceTypeName(device.deviceType));
}

std::string readingLine(const station::ReadingChannel& reading, std::uint16_t raw) {
    char value[32];
    std::snprintf(value, sizeof value, "%.*f", reading.decimals(), reading.scaled(raw));
    return "  " + reading.name + ": " + value + " " + reading.unit;
}

// Pings and, after the answers had time to arrive, hands the devices that answered to `then`.
void findDevices(StationClient& client, std::function<void(const std::vector<cs2::DeviceIdentity>&)> then) {
    client.session().ping();
    QTimer::singleShot(PingWindow, &client, [&client, then = std::move(then)] {
        std::vector<cs2::DeviceIdentity> devices;
        for (const auto& device : client.session().devices().devices())
            devices.push_back(device.identity);
        then(devices);
    });
}

StationJob ping(std::ostream& out, std::ostream& err) {
    auto start = [&out, &err](StationClient& client) {
        findDevices(client, [&](const std::vector<cs2::DeviceIdentity>& devices) {
            for (const auto& device : devices)
                out << deviceLine(device) << '\n';
            if (devices.empty())
                err << "error: no device answered the ping within " << PingWindow.count() << " ms\n";
            client.finish(devices.empty() ? NotAcknowledged : Acknowledged);
        });
    };
    return {std::move(start), std::chrono::milliseconds(5000)};
}

// Reads the status data of devices one after the other and polls each of their readings once. A device
// that answered the ping without status data (a PC program on the bus) is named and passed over; asked
// for by its UID, it is an error.
class StatusReport {
public:
    StatusReport(StationClient& client, std::ostream& out, std::ostream& err)
        : client_(client), out_(out), err_(err) {}

    void start(const std::vector<cs2::DeviceIdentity>& devices, bool asked) {
        devices_.assign(devices.begin(), devices.end());
        asked_ = asked;
        if (devices_.empty()) {
            err_ << "error: no device answered the ping within " << PingWindow.count() << " ms\n";
            return client_.finish(NotAcknowledged);
        }
        nextDevice();
    }

private:
    void nextDevice() {
        if (devices_.empty()) {
            if (described_ == 0 && !asked_)
                err_ << "error: no device that answered the ping has status data\n";
            return client_.finish(failed_ || described_ == 0 ? NotAcknowledged : Acknowledged);
        }
        const cs2::DeviceIdentity device = devices_.front();
        devices_.pop_front();
        client_.session().statusData().read(
            device, [this](const station::DeviceDescription& description, const QStringList& problems) {
                described(description, problems);
            });
    }

    void described(const station::DeviceDescription& description, const QStringList& problems) {
        if (!description.summary && !asked_)
            return withoutStatusData(description.identity);
        device_ = description;
        out_ << hex(description.identity.uid, 8);
        if (description.summary)
            out_ << " " << description.summary->name << " (" << description.summary->article << ", serial "
                 << description.summary->serial << ")";
        out_ << '\n';
        for (const QString& problem : problems)
            err_ << "error: " << hex(description.identity.uid, 8) << ": " << problem.toStdString() << '\n';
        failed_ = failed_ || !problems.isEmpty() || !description.summary;
        described_ += description.summary ? 1 : 0;
        reading_ = 0;
        pollNext();
    }

    // Not every device on the bus has status data: PC programs and some gateways answer the ping only.
    void withoutStatusData(const cs2::DeviceIdentity& device) {
        out_ << hex(device.uid, 8) << " " << cs2::deviceTypeName(device.deviceType) << ", type "
             << hex(device.deviceType, 4) << ": no status data\n";
        nextDevice();
    }

    void pollNext() {
        if (reading_ >= device_.readings.size())
            return nextDevice();
        const station::ReadingChannel& reading = device_.readings[reading_++];
        const cs2::Message request{0, false, 0,
                                   cs2::SystemStatus{device_.identity.uid, reading.channel, {}, {}}};
        client_.session().request(
            request, [this, reading](const station::CommandResult& result) { polled(reading, result); });
    }

    void polled(const station::ReadingChannel& reading, const station::CommandResult& result) {
        const auto* status = result.answer ? std::get_if<cs2::SystemStatus>(&result.answer->body) : nullptr;
        if (result.succeeded() && status && status->value) {
            out_ << readingLine(reading, *status->value) << '\n';
        } else {
            out_ << "  " << reading.name << ": no value (" << station::commandStatusName(result.status)
                 << ")\n";
            failed_ = true;
        }
        pollNext();
    }

    StationClient& client_;
    std::ostream& out_;
    std::ostream& err_;
    std::deque<cs2::DeviceIdentity> devices_;
    station::DeviceDescription device_;
    std::size_t reading_ = 0;
    std::size_t described_ = 0; // devices whose status data was read
    bool asked_ = false;        // one device asked for by its UID
    bool failed_ = false;
};

ParsedJob status(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
    if (arguments.size() > 1)
        return std::string("usage: stellwerk-cli --station URL status [UID]");
    std::optional<std::uint32_t> uid;
    if (!arguments.empty()) {
        const auto parsed = parseUid(arguments[0]);
        if (!parsed)
            return parsed.error();
        uid = *parsed;
    }
    auto start = [uid, &out, &err, report = std::shared_ptr<StatusReport>()](StationClient& client) mutable {
        report = std::make_shared<StatusReport>(client, out, err);
        if (uid)
            return report->start({cs2::DeviceIdentity{*uid, 0, 0, 0}}, true);
        findDevices(client, [report](const std::vector<cs2::DeviceIdentity>& devices) {
            report->start(devices, false);
        });
    };
    return StationJob{std::move(start), std::chrono::milliseconds(30000)};
}

} // namespace

std::optional<ParsedJob> parseDeviceCommand(const std::string& command,
                                            const std::vector<std::string>& arguments, std::ostream& out,
                                            std::ostream& err) {
    if (command == "ping") {
        if (!arguments.empty())
            return ParsedJob(std::string("usage: stellwerk-cli --station URL ping"));
        return ParsedJob(ping(out, err));
    }
    if (command == "status")
        return status(arguments, out, err);
    return std::nullopt;
}

} // namespace stellwerk::cli
