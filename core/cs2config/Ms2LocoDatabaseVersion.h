#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"

#include <string>

namespace stellwerk::cs2config {

// The MS2 stream "ldbver" (document 8.8): which version of the loco database the station holds.
// It has no section header and no record: four `.key=value` lines, in the document's example with
// trailing spaces (read as numbers all the same). The parser's "no [section] header" warning is
// expected for this stream.
struct Ms2LocoDatabaseVersion {
    Document document = emptyDocument();
    int version = 0; // .version
    int month = 0;   // .monat
    int year = 0;    // .jahr, as sent (10 = 2010)
    int count = 0;   // .anzahl: locomotives in the database

    static Ms2LocoDatabaseVersion read(const Document& document, Diagnostics& diagnostics);
    Document write() const;

private:
    // The four lines with 0, in the stream's style (no header, no indent).
    static Document emptyDocument();
};

std::string toJson(const Ms2LocoDatabaseVersion& version);

} // namespace stellwerk::cs2config
