// Document 7.1/7.2: a file requested with 0x20 arrives as a 0x21 stream addressed to our hash.

#include "ScriptedStation.h"

#include <QFile>
#include <QSignalSpy>

namespace stellwerk::station::test {
namespace {

std::string corpusFile(const char* path) {
    QFile file(QStringLiteral(STELLWERK_SHARED_DIR "/corpus/") + QLatin1String(path));
    EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << path;
    return file.readAll().toStdString();
}

struct Download {
    std::optional<DownloadResult> result;
    ConfigDownload::Done callback() {
        return [this](const DownloadResult& r) { result = r; };
    }
};

TEST(ConfigDownload, LokomotiveCs2ArrivesByteForByteWithProgressTo100Percent) {
    Bench bench;
    const std::string loks = corpusFile("GBert__railroad/can2udp/files/maerklin/config/lokomotive.cs2");
    ASSERT_GT(loks.size(), 1000u);
    bench.station.files["loks"] = loks;
    QSignalSpy progress(&bench.session.downloads(), &ConfigDownload::progress);
    Download download;
    bench.session.downloads().fetch(*cs2config::ConfigRequest::forKey("loks"), download.callback());
    ASSERT_TRUE(waitFor([&] { return download.result.has_value(); }));
    ASSERT_TRUE(*download.result) << download.result->error().toStdString();
    EXPECT_EQ((*download.result)->key, "loks");
    EXPECT_TRUE((*download.result)->compressed);
    EXPECT_EQ((*download.result)->contents, loks);
    ASSERT_GE(progress.count(), 1);
    const auto last = progress.last();
    EXPECT_EQ(last.at(0).toString(), QStringLiteral("loks"));
    EXPECT_GT(last.at(2).value<qsizetype>(), 0);
    EXPECT_EQ(last.at(1).value<qsizetype>(), last.at(2).value<qsizetype>()) << "100 %";
    EXPECT_EQ(bench.station.count(cs2::Command::ConfigDataRequest), 1u);
}

TEST(ConfigDownload, FilesAreFetchedOneAfterAnother) {
    Bench bench;
    bench.station.files["fs"] = "[fahrstrassen]\nversion\n .major=1\n";
    bench.station.files["gbs"] = "[gleisbild]\nversion\n .major=1\n";
    Download routes;
    Download plan;
    bench.session.downloads().fetch(*cs2config::ConfigRequest::forKey("fs"), routes.callback());
    bench.session.downloads().fetch(*cs2config::ConfigRequest::forKey("gbs"), plan.callback());
    ASSERT_TRUE(waitFor([&] { return routes.result && plan.result; }));
    ASSERT_TRUE(*routes.result);
    ASSERT_TRUE(*plan.result);
    EXPECT_EQ((*routes.result)->contents, bench.station.files["fs"]);
    EXPECT_EQ((*plan.result)->contents, bench.station.files["gbs"]);
}

TEST(ConfigDownload, AcknowledgedRequestWithoutStreamIsReported) {
    StationSettings settings = Bench::fastSettings();
    settings.streamIdle = 80ms;
    Bench bench(settings);
    Download download;
    bench.session.downloads().fetch(*cs2config::ConfigRequest::forKey("mags"), download.callback());
    ASSERT_TRUE(waitFor([&] { return download.result.has_value(); }));
    ASSERT_FALSE(*download.result);
    EXPECT_TRUE(download.result->error().contains(QStringLiteral("no stream")));
}

TEST(ConfigDownload, UnansweredRequestFailsAfterRetries) {
    Bench bench;
    bench.station.silent = true;
    Download download;
    bench.session.downloads().fetch(*cs2config::ConfigRequest::forKey("loks"), download.callback());
    ASSERT_TRUE(waitFor([&] { return download.result.has_value(); }));
    ASSERT_FALSE(*download.result);
    EXPECT_TRUE(download.result->error().contains(QStringLiteral("did not acknowledge")));
    EXPECT_EQ(bench.station.count(cs2::Command::ConfigDataRequest), 3u);
}

} // namespace
} // namespace stellwerk::station::test
