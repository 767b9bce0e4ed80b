#include "LayoutCommand.h"

#include "model/LayoutInUse.h"
#include "trackgraph/GraphReport.h"

#include <algorithm>
#include <ostream>

namespace stellwerk::cli {

namespace {

constexpr const char* Usage = "usage: stellwerk-cli layout graph DIR [--json]\n";

int usageError(std::ostream& err, const std::string& problem) {
    err << "stellwerk-cli layout: " << problem << "\n" << Usage;
    return 2;
}

bool anyPageRead(const cs2config::TrackLayout& layout) {
    return std::any_of(layout.pages.begin(), layout.pages.end(),
                       [](const cs2config::TrackLayoutPage& page) { return page.loaded; });
}

// The graph of the layout in use once the folder is opened (its plan, accessories and routes).
int runGraph(const std::string& folder, bool json, std::ostream& out, std::ostream& err) {
    model::LayoutInUse layout;
    if (const std::string problem = layout.open(folder); !problem.empty()) {
        err << "stellwerk-cli layout graph: " << problem << "\n";
        return 1;
    }
    if (!anyPageRead(*layout.files())) {
        err << "stellwerk-cli layout graph: no page of the track plan in " << layout.folder().string()
            << " could be read\n";
        return 1;
    }
    out << (json ? trackgraph::toJson(*layout.graph()) : trackgraph::describeGraph(*layout.graph()));
    return 0;
}

} // namespace

int runLayout(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
    if (arguments.empty() || arguments[0] != "graph")
        return usageError(err,
                          arguments.empty() ? "missing command" : "unknown command '" + arguments[0] + "'");
    std::string folder;
    bool json = false;
    for (std::size_t i = 1; i < arguments.size(); ++i) {
        if (arguments[i] == "--json")
            json = true;
        else if (folder.empty() && !arguments[i].starts_with("-"))
            folder = arguments[i];
        else
            return usageError(err, "unexpected argument '" + arguments[i] + "'");
    }
    if (folder.empty())
        return usageError(err, "graph needs a layout folder DIR");
    return runGraph(folder, json, out, err);
}

} // namespace stellwerk::cli
