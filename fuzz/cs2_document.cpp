// The .cs2 document parser and each typed reader (lokomotive, magnetartikel, fahrstrassen, gleisbild,
// pages, .sr2 status files, the MS2 streams), chosen by the file's header as `stellwerk-cli cs2` does.
// Invariants: any bytes parse into a document that writes back byte for byte; a usable file writes
// back through its typed model byte for byte (`cs2 format` of an unchanged file changes nothing); its
// JSON (`cs2 json`) is valid and its summary is UTF-8.
#include "FuzzSupport.h"
#include "cs2config/ConfigFile.h"

using namespace stellwerk;
using namespace stellwerk::cs2config;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 64 * 1024)
        return -1;
    fuzz::FuzzInput input(data, size);
    // The name only matters for its extension: .sr2 selects the status readers.
    const std::string fileName = (input.byte() & 1) ? "fuzz.sr2" : "fuzz.cs2";
    const std::string_view bytes = input.restText();

    // The file keeps the document its readers saw (Document::parse): checked here, not parsed twice.
    const ConfigFile file = ConfigFile::fromBytes(bytes, fileName);
    fuzz::check(file.document().serialize() == bytes, "a document does not write back byte for byte");
    if (!file.usable())
        return 0;
    const std::string written = file.write();
    fuzz::check(written == bytes, "an unchanged file changes when written through its model", written);
    const std::string json = file.json();
    fuzz::check(fuzz::isJsonDocument(json, true), "cs2 json wrote invalid JSON", json);
    fuzz::check(isValidUtf8(file.summary()), "the summary is not UTF-8", file.summary());
    return 0;
}
