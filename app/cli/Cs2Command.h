#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace stellwerk::cli {

// `stellwerk-cli cs2 check FILE|DIR...`: reads each file, prints every problem with its line number and
// a summary line per file. A layout folder (DIR or DIR/config with gleisbild.cs2) is checked file by
// file and then as a whole (LayoutCheck: missing pages, tiles sharing an article, tiles whose type or
// label disagrees with their article). Returns 0 when every file is a usable .cs2 file (warnings
// allowed), 1 when one is not a .cs2 file at all or cannot be read, 2 on a usage error.
//
// `stellwerk-cli cs2 json FILE`: the file's typed model as JSON on `out`, problems on `err`.
// A gleisbild.cs2 with a gleisbilder/ folder beside it gives the whole layout with every page.
//
// `stellwerk-cli cs2 format FILE [-o OUT]`: the file written back through its typed model, to OUT or
// `out`. Nothing is written when the file is not usable.
int runCs2(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err);

} // namespace stellwerk::cli
