#include "cs2config/Ms2LocoInfo.h"

#include "cs2config/JsonWriter.h"
#include "cs2config/LocomotiveFieldWriter.h"
#include "cs2config/LocomotiveJson.h"
#include "cs2config/LocomotiveKeys.h"
#include "cs2config/LocomotiveRecord.h"
#include "cs2config/LocomotiveSections.h"
#include "cs2config/LocomotiveValues.h"

namespace stellwerk::cs2config {

namespace key = locokey;

LineStyle ms2LineStyle() {
    return LineStyle{"  ", "\n"};
}

Ms2LocoInfo Ms2LocoInfo::read(const Document& document, Diagnostics& diagnostics) {
    Ms2LocoInfo info;
    info.document = document;
    loco::Findings findings;
    loco::checkSection(document, {key::section}, diagnostics);
    loco::noteUnknownRecords(document, {key::lok}, findings);
    if (const Node* record = loco::singleRecord(document, key::lok, diagnostics))
        info.locomotive =
            LocomotiveRecordReader(diagnostics, findings, loco::TextCoding::Plain).read(*record);
    else
        diagnostics.error(0, "lokinfo without a 'lok' record", "no locomotive read");
    findings.report(diagnostics);
    return info;
}

Ms2LocoInfo Ms2LocoInfo::from(const Locomotive& locomotive) {
    Ms2LocoInfo info;
    Locomotive& copy = info.locomotive.emplace(locomotive);
    copy.source = Node();
    for (Function& function : copy.functions)
        function.source = Node();
    if (copy.mfxAddress)
        copy.mfxAddress->source = Node();
    copy.traction.clear();
    copy.cvRows.clear();
    return info;
}

Document Ms2LocoInfo::write() const {
    Document out = document;
    const Document& source = document;
    std::vector<Node> records;
    if (locomotive)
        records.push_back(
            LocomotiveRecordWriter(out.style(), LocomotiveRecordKind::LokInfo, loco::TextCoding::Plain)
                .write(*locomotive));
    // A second `lok` record (not read) stays as it was.
    const std::vector<const Node*> existing = source.records(key::lok);
    for (std::size_t i = 1; i < existing.size(); ++i)
        records.push_back(*existing[i]);
    out.replaceRecords(key::lok, std::move(records));
    return out;
}

std::string toJson(const Ms2LocoInfo& info) {
    JsonWriter json;
    json.beginObject().value("kind", "lokinfo");
    if (info.locomotive)
        writeLocomotiveJson(json, "locomotive", *info.locomotive);
    else
        json.null("locomotive");
    json.endObject();
    return json.text();
}

} // namespace stellwerk::cs2config
