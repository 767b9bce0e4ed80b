#include "Cs2Command.h"

#include "cs2config/ConfigFile.h"
#include "cs2config/LayoutFolder.h"
#include "cs2config/TrackLayout.h"
#include "model/LayoutInUse.h"

#include <filesystem>
#include <fstream>
#include <ostream>

namespace stellwerk::cli {

namespace {

using cs2config::ConfigFile;
using cs2config::ConfigKind;
using cs2config::LayoutFolder;

constexpr const char* Usage = "usage: stellwerk-cli cs2 check FILE|DIR...\n"
                              "       stellwerk-cli cs2 json FILE\n"
                              "       stellwerk-cli cs2 format FILE [-o OUT]\n";

int usageError(std::ostream& err, const std::string& problem) {
    err << "stellwerk-cli cs2: " << problem << "\n" << Usage;
    return 2;
}

std::string counted(std::size_t n, const char* what) {
    return std::to_string(n) + ' ' + what + (n == 1 ? "" : "s");
}

std::string verdict(const ConfigFile& file) {
    const cs2config::Diagnostics& diagnostics = file.diagnostics();
    const std::size_t errors = diagnostics.errorCount();
    const std::size_t warnings = diagnostics.count() - errors;
    if (file.kind() == ConfigKind::NotConfiguration)
        return "not a .cs2 file";
    if (errors > 0)
        return "not usable, " + counted(errors, "error") +
               (warnings > 0 ? ", " + counted(warnings, "warning") : "");
    return warnings == 0 ? "ok" : "usable, " + counted(warnings, "warning");
}

// Prints the file's problems and its verdict line; false when it is not usable.
bool checkFile(const std::filesystem::path& path, std::ostream& out) {
    const ConfigFile file = ConfigFile::load(path);
    out << file.diagnostics().formatAll();
    out << path.string() << ": " << verdict(file);
    if (file.kind() != ConfigKind::NotConfiguration)
        out << " - " << file.summary();
    out << "\n";
    return file.usable();
}

// A layout folder: every file it holds as `check FILE` does, then the files checked against each other.
bool checkFolder(const std::filesystem::path& folder, std::ostream& out) {
    model::LayoutInUse layout;
    if (const std::string problem = layout.open(folder); !problem.empty()) {
        out << folder.string() << ": not usable - " << problem << "\n";
        return false;
    }
    const LayoutFolder::Content& content = *layout.folderContent();
    bool usable = true;
    if (content.extent == LayoutFolder::Extent::PagesOnly) // the index is missing: what was done instead
        out << content.layout.diagnostics.formatAll();
    for (const std::string& name : LayoutFolder::presentFiles(content))
        usable = checkFile(content.configDirectory / std::u8string(name.begin(), name.end()), out) && usable;
    for (const cs2config::LayoutFinding& finding : content.findings)
        out << finding.format(content.configDirectory) << "\n";
    out << folder.string() << ": " << (usable ? "usable" : "not usable") << " as a layout, "
        << counted(content.findings.size(), "layout warning") << " - "
        << counted(content.layout.pages.size(), "page") << "\n";
    return usable;
}

int runCheck(const std::vector<std::string>& names, std::ostream& out) {
    int status = 0;
    for (const std::string& name : names) {
        std::error_code error;
        const bool usable =
            std::filesystem::is_directory(name, error) ? checkFolder(name, out) : checkFile(name, out);
        if (!usable)
            status = 1;
    }
    return status;
}

// An index with its page folder beside it is shown as the whole layout.
bool isLayoutDirectory(const ConfigFile& file, const std::filesystem::path& path) {
    std::error_code error;
    return file.kind() == ConfigKind::TrackPlan &&
           std::filesystem::is_directory(path.parent_path() / "gleisbilder", error);
}

int runJson(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
    if (arguments.size() != 1)
        return usageError(err, "json takes exactly one FILE");
    const std::filesystem::path path = arguments[0];
    const ConfigFile file = ConfigFile::load(path);
    if (isLayoutDirectory(file, path)) {
        const cs2config::TrackLayout layout = cs2config::TrackLayout::load(path);
        err << layout.diagnostics.formatAll();
        for (const cs2config::TrackLayoutPage& page : layout.pages)
            err << page.diagnostics.formatAll();
        out << cs2config::toJson(layout);
        return 0;
    }
    err << file.diagnostics().formatAll();
    if (!file.usable())
        return 1;
    out << file.json();
    return 0;
}

int runFormat(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
    std::string input;
    std::string output;
    for (std::size_t i = 0; i < arguments.size(); ++i) {
        if (arguments[i] == "-o" && i + 1 < arguments.size())
            output = arguments[++i];
        else if (input.empty() && arguments[i] != "-o")
            input = arguments[i];
        else
            return usageError(err, "unexpected argument '" + arguments[i] + "'");
    }
    if (input.empty())
        return usageError(err, "format needs a FILE");
    const ConfigFile file = ConfigFile::load(input);
    err << file.diagnostics().formatAll();
    if (!file.usable())
        return 1;
    const std::string bytes = file.write();
    if (output.empty()) {
        out << bytes;
        return 0;
    }
    std::ofstream target(output, std::ios::binary | std::ios::trunc);
    target << bytes;
    if (!target.good()) {
        err << output << ": cannot write the file\n";
        return 1;
    }
    return 0;
}

} // namespace

int runCs2(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
    if (arguments.empty())
        return usageError(err, "missing sub-command");
    const std::vector<std::string> rest(arguments.begin() + 1, arguments.end());
    if (arguments[0] == "check")
        return rest.empty() ? usageError(err, "check needs at least one FILE") : runCheck(rest, out);
    if (arguments[0] == "json")
        return runJson(rest, out, err);
    if (arguments[0] == "format")
        return runFormat(rest, out, err);
    return usageError(err, "unknown sub-command '" + arguments[0] + "'");
}

} // namespace stellwerk::cli
