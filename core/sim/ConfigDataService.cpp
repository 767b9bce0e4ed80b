#include "sim/ConfigDataService.h"

#include "cs2config/ConfigStreamSender.h"
#include "cs2config/Ms2LocoInfo.h"
#include "cs2config/Ms2LocoNames.h"
#include "sim/StationStatusFiles.h"

namespace stellwerk::sim {
namespace {

constexpr std::size_t MaxNameBytes = cs2config::ConfigRequest::MaxLocoNameLength;

std::string locoNames(const cs2config::LocomotiveFile& file, cs2config::RequestRange range) {
    cs2config::Ms2LocoNames names;
    const auto& locos = file.locomotives;
    for (unsigned i = range.first; i < locos.size() && i < std::size_t(range.first) + range.count; ++i)
        names.entries.push_back({int(i), locos[i].name, {}});
    names.total = int(locos.size());
    return names.write().serialize();
}

std::string accessoryInfo(const cs2config::AccessoryFile& file, cs2config::RequestRange range) {
    std::vector<cs2config::Accessory> chosen;
    for (const cs2config::Accessory& accessory : file.accessories)
        if (accessory.id >= std::int64_t(range.first) && chosen.size() < range.count)
            chosen.push_back(accessory);
    return cs2config::writeAccessoryInfo(chosen).serialize();
}

} // namespace

bool ConfigDataService::handle(const cs2::Message& m, Outbox& out) {
    if (!std::holds_alternative<cs2::ConfigDataRequest>(m.body))
        return false;
    const auto collected = collector_.feed(m);
    if (!collected || collected->response)
        return true;
    const auto contents = contentsFor(collected->request);
    if (contents)
        out.add(cs2config::answerFrames(collected->request, *contents, collected->hash));
    else
        out.add(collected->request.frames(collected->hash, true)); // acknowledged, no stream
    return true;
}

std::optional<std::string> ConfigDataService::contentsFor(const cs2config::ConfigRequest& request) const {
    if (auto file = layout_.fileForKey(request.key()))
        return file;
    if (auto stream = ms2Stream(request))
        return stream;
    return statusFile(request.key());
}

std::optional<std::string> ConfigDataService::ms2Stream(const cs2config::ConfigRequest& request) const {
    const std::string& key = request.key();
    if (key == "loknamen" && request.range())
        return locoNames(layout_.locomotives(), *request.range());
    if (key == "maginfo" && request.range())
        return accessoryInfo(layout_.accessories(), *request.range());
    if (key != "lokinfo")
        return std::nullopt;
    for (const cs2config::Locomotive& loco : layout_.locomotives().locomotives)
        if (!loco.name.empty() &&
            loco.name.substr(0, MaxNameBytes) == request.qualifier().substr(0, MaxNameBytes))
            return cs2config::Ms2LocoInfo::from(loco).write().serialize();
    return std::nullopt;
}

std::optional<std::string> ConfigDataService::statusFile(std::string_view key) const {
    if (key == "lokstat" || key == "loksstat")
        return locomotiveStatusFile(layout_, state_);
    if (key == "magstat")
        return accessoryStatusFile(layout_, state_);
    return std::nullopt;
}

} // namespace stellwerk::sim
