#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace stellwerk::cli {

// `stellwerk-cli layout graph DIR [--json]`: the railway the track plan of a layout folder (DIR holding
// config/, or config/ itself) shows, derived by trackgraph::TrackGraph with the folder's magnetartikel.cs2
// and fahrstrassen.cs2: its blocks, the connections between them and the problems of the drawing, as text
// or one JSON document. Returns 0 when the graph was derived (problems allowed), 1 when the folder has no
// usable track plan, 2 on a usage error.
int runLayout(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err);

} // namespace stellwerk::cli
