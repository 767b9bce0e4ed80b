#include "TransferCommands.h"

#include "cs2/FrameReport.h"
#include "cs2config/ConfigStreamRequest.h"

#include <charconv>
#include <fstream>
#include <memory>
#include <ostream>

namespace stellwerk::cli {
namespace {

using Arguments = std::vector<std::string>;

struct DownloadOptions {
    std::string key;
    std::string qualifier;
    std::string file; // empty: standard output
};

// Writes the file's bytes; false (with a message on `err`) when it cannot.
bool store(const DownloadOptions& options, const std::string& contents, std::ostream& out,
           std::ostream& err) {
    if (options.file.empty()) {
        out << contents << std::flush;
        return true;
    }
    std::ofstream file(options.file, std::ios::binary | std::ios::trunc);
    file.write(contents.data(), std::streamsize(contents.size()));
    file.close();
    if (!file) {
        err << "error: cannot write " << options.file << '\n';
        return false;
    }
    return true;
}

void showProgress(std::ostream& err, const QString& key, qsizetype received, qsizetype announced) {
    const qsizetype percent = announced > 0 ? received * 100 / announced : 0;
    err << "\rdownloading " << key.toStdString() << ": " << percent << "% (" << received << " of "
        << announced << " bytes)" << std::flush;
}

void downloadFinished(StationClient& client, const DownloadOptions& options,
                      const station::DownloadResult& result, std::ostream& out, std::ostream& err) {
    if (!result) {
        err << "error: download " << options.key << ": " << result.error().toStdString() << '\n';
        return client.finish(NotAcknowledged);
    }
    if (!store(options, result->contents, out, err))
        return client.finish(NotAcknowledged);
    if (!options.file.empty())
        out << "ok: download " << options.key << ": " << result->contents.size() << " bytes written to "
            << options.file << " (acknowledged)\n";
    client.finish(Acknowledged);
}

ParsedJob download(const Arguments& a, std::ostream& out, std::ostream& err) {
    DownloadOptions options;
    std::vector<std::string> positional;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i] == "-o" && i + 1 < a.size())
            options.file = a[++i];
        else if (a[i].starts_with("-"))
            return std::string("usage: stellwerk-cli --station URL download KEY [QUALIFIER] [-o FILE]");
        else
            positional.push_back(a[i]);
    }
    if (positional.empty() || positional.size() > 2)
        return std::string("usage: stellwerk-cli --station URL download KEY [QUALIFIER] [-o FILE]");
    options.key = positional[0];
    options.qualifier = positional.size() > 1 ? positional[1] : "";
    const auto request = options.key == "lokinfo"
                             ? Expected<cs2config::ConfigRequest, std::string>(
                                   cs2config::ConfigRequest::locoInfo(options.qualifier))
                             : cs2config::ConfigRequest::forKey(options.key, options.qualifier);
    if (!request)
        return "download: " + request.error();
    auto start = [options, request = *request, &out, &err](StationClient& client) {
        auto& downloads = client.session().downloads();
        QObject::connect(&downloads, &station::ConfigDownload::progress, &client,
                         [&err](const QString& key, qsizetype received, qsizetype announced) {
                             showProgress(err, key, received, announced);
                         });
        downloads.fetch(request, [options, &client, &out, &err](const station::DownloadResult& result) {
            err << '\n';
            downloadFinished(client, options, result, out, err);
        });
    };
    return StationJob{std::move(start), std::chrono::minutes(5)};
}

ParsedJob monitor(const Arguments& a, std::ostream& out) {
    bool json = false;
    std::optional<std::uint64_t> count;
    for (std::size_t i = 0; i < a.size(); ++i) {
        std::uint64_t n = 0;
        if (a[i] == "--json") {
            json = true;
        } else if (a[i] == "--count" && i + 1 < a.size() &&
                   std::from_chars(a[i + 1].data(), a[i + 1].data() + a[i + 1].size(), n).ptr ==
                       a[i + 1].data() + a[i + 1].size() &&
                   n > 0) {
            count = n;
            ++i;
        } else {
            return std::string("usage: stellwerk-cli --station URL monitor [--json] [--count N]");
        }
    }
    auto start = [json, count, &out](StationClient& client) {
        client.finishOnInterrupt(Acknowledged);
        auto seen = std::make_shared<std::uint64_t>(0);
        QObject::connect(&client.transport(), &transport::Transport::framesReceived, &client,
                         [json, count, seen, &out, &client](const std::vector<can::CanFrame>& frames) {
                             for (const can::CanFrame& frame : frames) {
                                 if (count && *seen >= *count)
                                     return;
                                 const cs2::FrameReport report(frame);
                                 out << (json ? report.json() : report.text()) << std::endl;
                                 if (count && ++*seen >= *count)
                                     client.finish(Acknowledged);
                             }
                         });
    };
    return StationJob{std::move(start), std::nullopt};
}

} // namespace

std::optional<ParsedJob> parseTransferCommand(const std::string& command, const Arguments& arguments,
                                              std::ostream& out, std::ostream& err) {
    if (command == "download")
        return download(arguments, out, err);
    if (command == "monitor")
        return monitor(arguments, out);
    return std::nullopt;
}

} // namespace stellwerk::cli
