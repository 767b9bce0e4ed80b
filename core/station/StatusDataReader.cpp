#include "station/StatusDataReader.h"

#include "cs2/Request.h"

namespace stellwerk::station {

StatusDataReader::StatusDataReader(CommandTracker& tracker, QObject* parent)
    : QObject(parent), tracker_(tracker) {}

void StatusDataReader::read(const cs2::DeviceIdentity& device, Done done) {
    Job job;
    job.device.identity = device;
    job.done = std::move(done);
    queue_.push_back(std::move(job));
    if (!active_)
        startNext();
}

void StatusDataReader::feedPacket(const cs2::StatusDataConfig& packet, std::uint16_t hash) {
    if (active_ && packet.form == cs2::StatusDataConfig::Form::Packet)
        packets_.add(hash, packet.packet);
}

void StatusDataReader::startNext() {
    if (queue_.empty())
        return;
    active_ = std::move(queue_.front());
    queue_.pop_front();
    requestIndex();
}

void StatusDataReader::requestIndex() {
    packets_.clear();
    cs2::StatusDataConfig request;
    request.device = active_->device.identity.uid;
    request.index = active_->index;
    CommandPolicy policy = policy_;
    policy.silenceMeansTrouble = false; // a device that has no status data stays silent
    tracker_.send(
        cs2::request(request), [this](const CommandResult& r) { indexAnswered(r); }, policy);
}

void StatusDataReader::indexAnswered(const CommandResult& result) {
    Job& job = *active_;
    if (result.succeeded()) {
        store(packets_.assemble());
    } else {
        job.problems << QStringLiteral("device 0x%1: status data index %2: %3")
                            .arg(job.device.identity.uid, 8, 16, QLatin1Char('0'))
                            .arg(job.index)
                            .arg(QLatin1String(commandStatusName(result.status)));
    }
    const auto* summary = job.device.summary ? &*job.device.summary : nullptr;
    const int last = summary ? summary->readingCount + summary->configCount : 0;
    if (!summary || job.index >= last) {
        finishJob();
        return;
    }
    ++job.index;
    requestIndex();
}

void StatusDataReader::store(std::span<const std::uint8_t> bytes) {
    Job& job = *active_;
    const auto index = job.index;
    const std::uint8_t readings = job.device.summary ? job.device.summary->readingCount : 0;
    bool parsed = false;
    if (index == 0) {
        job.device.summary = parseDeviceSummary(bytes);
        parsed = job.device.summary.has_value();
    } else if (index <= readings) {
        auto reading = parseReadingChannel(index, bytes);
        if ((parsed = reading.has_value()))
            job.device.readings.push_back(std::move(*reading));
    } else {
        auto config = parseConfigChannel(index, bytes);
        if ((parsed = config.has_value()))
            job.device.configs.push_back(std::move(*config));
    }
    if (!parsed)
        job.problems << QStringLiteral("device 0x%1: status data index %2: %3 bytes are too short; ignored")
                            .arg(job.device.identity.uid, 8, 16, QLatin1Char('0'))
                            .arg(index)
                            .arg(bytes.size());
}

void StatusDataReader::finishJob() {
    Job job = std::move(*active_);
    active_.reset();
    packets_.clear();
    if (job.done)
        job.done(job.device, job.problems);
    if (!active_)
        startNext();
}

} // namespace stellwerk::station
