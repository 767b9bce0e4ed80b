#include "cs2config/LocomotiveJson.h"

#include "cs2config/LocomotiveFile.h"
#include "cs2config/LocomotiveSections.h"
#include "cs2config/Values.h"

namespace stellwerk::cs2config {

namespace {

void writeFunctions(JsonWriter& json, const std::vector<Function>& functions) {
    json.beginArray("functions");
    for (const Function& function : functions) {
        json.beginObject()
            .value("number", function.number)
            .value("icon", function.icon)
            .value("trigger", triggerName(function.trigger()))
            .value("duration", function.duration)
            .value("value", function.value)
            .endObject();
    }
    json.endArray();
}

void writeTraction(JsonWriter& json, const Locomotive& locomotive) {
    if (locomotive.inTraction == Locomotive::noTraction)
        json.null("inTraction");
    else
        json.value("inTraction", formatHex(locomotive.inTraction));
    json.beginArray("traction");
    for (const TractionMember& member : locomotive.traction)
        json.beginObject().value("uid", formatHex(member.uid)).value("name", member.name).endObject();
    json.endArray();
}

void writeCvRows(JsonWriter& json, const std::vector<CvRow>& rows) {
    json.beginArray("cvRows");
    for (const CvRow& row : rows)
        json.beginObject()
            .value("cv", row.cv)
            .value("name", row.name)
            .value("value", row.value)
            .value("mask", row.mask)
            .endObject();
    json.endArray();
}

void writeMfxAddress(JsonWriter& json, const std::optional<MfxAddress>& mfx) {
    if (!mfx) {
        json.null("mfxAddress");
        return;
    }
    json.beginObject("mfxAddress")
        .value("target", mfx->target)
        .value("name", mfx->name)
        .value("address", mfx->address)
        .value("acceleration", mfx->acceleration)
        .value("speedTable", mfx->speedTable)
        .value("volume", mfx->volume)
        .value("functionCount", mfx->functionCount)
        .value("functions", mfx->functions)
        .endObject();
}

} // namespace

std::string_view directionName(TravelDirection direction) {
    switch (direction) {
    case TravelDirection::Forward:
        return "forward";
    case TravelDirection::Backward:
        return "backward";
    case TravelDirection::Unknown:
        break;
    }
    return "unknown";
}

std::string_view triggerName(FunctionTrigger trigger) {
    switch (trigger) {
    case FunctionTrigger::Latching:
        return "latching";
    case FunctionTrigger::Momentary:
        return "momentary";
    case FunctionTrigger::Timed:
        return "timed";
    case FunctionTrigger::Unknown:
        break;
    }
    return "unknown";
}

void writeLocomotiveJson(JsonWriter& json, std::string_view key, const Locomotive& locomotive) {
    json.beginObject(key)
        .value("line", locomotive.source.lineNumber())
        .value("empty", locomotive.isEmpty())
        .value("uid", formatHex(locomotive.uid))
        .value("name", locomotive.name)
        .value("previousName", locomotive.previousName)
        .value("address", std::int64_t{locomotive.address})
        .value("decoder", locomotive.decoderTypeText())
        .value("sid", formatHex(locomotive.sid))
        .value("mfxUid", formatHex(locomotive.mfxUid))
        .value("icon", locomotive.icon)
        .value("symbol", locomotive.symbol)
        .value("acceleration", locomotive.acceleration)
        .value("braking", locomotive.braking)
        .value("volume", locomotive.volume)
        .value("programmingMask", locomotive.programmingMask)
        .value("velocity", locomotive.velocity)
        .value("direction", directionName(locomotive.direction))
        .value("tachoMax", locomotive.tachoMax)
        .value("vMax", locomotive.vMax)
        .value("vMin", locomotive.vMin)
        .value("extendedProtocol", locomotive.extendedProtocol)
        .value("mfxType", locomotive.mfxType);
    writeTraction(json, locomotive);
    writeFunctions(json, locomotive.functions);
    writeCvRows(json, locomotive.cvRows);
    writeMfxAddress(json, locomotive.mfxAddress);
    json.endObject();
}

std::string toJson(const LocomotiveFile& file) {
    JsonWriter json;
    json.beginObject().value("kind", "lokomotive.cs2").value("cs3Native", file.cs3Native);
    loco::writeVersionJson(json, file.version);
    if (file.session)
        json.value("session", *file.session);
    else
        json.null("session");
    json.value("locomotiveCount", static_cast<std::int64_t>(file.locomotives.size()))
        .value("functionCount", static_cast<std::int64_t>(file.functionCount()));
    json.beginArray("locomotives");
    for (const Locomotive& locomotive : file.locomotives)
        writeLocomotiveJson(json, {}, locomotive);
    json.endArray().endObject();
    return json.text();
}

} // namespace stellwerk::cs2config
