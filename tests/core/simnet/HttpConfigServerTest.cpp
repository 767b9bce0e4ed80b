// The CS2's web server: GET /config/<file> answers the bytes the station serves, GET /icons/<name>.png
// a locomotive picture, and the simulator's own JSON documents (GET /accidents); anything else is refused
// without touching the file system.

#include "sim/HttpConfigServer.h"

#include "SimTestSupport.h"
#include "cs2config/LocomotivePicture.h"
#include "sim/EmbeddedStation.h"
#include "sim/StationLayout.h"

#include <QTcpSocket>
#include <gtest/gtest.h>
#include <string>

namespace stellwerk::sim {
namespace {

const StationLayout& demoLayout() {
    static const StationLayout layout = StationLayout::demo();
    return layout;
}

std::optional<std::string> demoFile(std::string_view path) {
    return demoLayout().fileForPath(path);
}

HttpAnswer ask(const QByteArray& request) {
    return answerConfigRequest(request, demoFile);
}

// Sends `request` to a server on loopback and returns everything it answered before closing.
QByteArray exchange(std::uint16_t port, const QByteArray& request) {
    QTcpSocket socket;
    socket.connectToHost(QHostAddress::LocalHost, port);
    if (!socket.waitForConnected(test::WaitMs))
        return {};
    socket.write(request);
    QByteArray response;
    QObject::connect(&socket, &QTcpSocket::readyRead, &socket, [&] { response += socket.readAll(); });
    test::waitFor([&] { return socket.state() == QAbstractSocket::UnconnectedState; });
    return response + socket.readAll();
}

QByteArray headerOf(const QByteArray& response) {
    return response.left(response.indexOf("\r\n\r\n"));
}

QByteArray bodyOf(const QByteArray& response) {
    return response.mid(response.indexOf("\r\n\r\n") + 4);
}

TEST(HttpConfigRequest, GetOfAConfigFileAnswersItsBytes) {
    const HttpAnswer answer = ask("GET /config/lokomotive.cs2 HTTP/1.1\r\nHost: cs2\r\n\r\n");
    EXPECT_EQ(answer.status, 200);
    EXPECT_EQ(answer.body.toStdString(), *demoFile("lokomotive.cs2"));
}

TEST(HttpConfigRequest, PageFileNamesArePercentDecoded) {
    EXPECT_EQ(ask("GET /config/gleisbilder/Bahnhof.cs2 HTTP/1.0\r\n\r\n").status, 200);
    EXPECT_EQ(ask("GET /config/gleisbilder/Bahn%68of.cs2 HTTP/1.0\r\n\r\n").status, 200);
}

TEST(HttpConfigRequest, UnknownFileIsNotFound) {
    EXPECT_EQ(ask("GET /config/nichtda.cs2 HTTP/1.0\r\n\r\n").status, 404);
    EXPECT_EQ(ask("GET /index.html HTTP/1.0\r\n\r\n").status, 404);
    EXPECT_EQ(ask("GET /config/ HTTP/1.0\r\n\r\n").status, 404);
}

TEST(HttpConfigRequest, DirectoryTraversalIsRefused) {
    for (const char* target : {"/config/../config/lokomotive.cs2", "/config/gleisbilder/../lokomotive.cs2",
                               "/config/%2e%2e/etc/passwd", "/config/./lokomotive.cs2",
                               "/config//lokomotive.cs2", "/config/gleisbilder%5c..%5clokomotive.cs2"}) {
        EXPECT_EQ(ask(QByteArray("GET ") + target + " HTTP/1.0\r\n\r\n").status, 404) << target;
    }
}

TEST(HttpConfigRequest, MalformedRequestIsBadRequest) {
    EXPECT_EQ(ask("hello\r\n\r\n").status, 400);
    EXPECT_EQ(ask("GET /config/lokomotive.cs2\r\n\r\n").status, 400);
    EXPECT_EQ(ask("GET config/lokomotive.cs2 HTTP/1.0\r\n\r\n").status, 400);
    EXPECT_EQ(ask("GET /config/lokomotive.cs2 SMTP/1.0\r\n\r\n").status, 400);
}

TEST(HttpConfigRequest, OnlyGetAndHeadAreAllowed) {
    EXPECT_EQ(ask("POST /config/lokomotive.cs2 HTTP/1.0\r\n\r\n").status, 405);
    const HttpAnswer head = ask("HEAD /config/lokomotive.cs2 HTTP/1.0\r\n\r\n");
    EXPECT_EQ(head.status, 200);
    const QByteArray response = formatResponse(head);
    EXPECT_TRUE(response.endsWith("\r\n\r\n"));
    EXPECT_TRUE(response.contains("Content-Length: " + QByteArray::number(head.body.size())));
}

TEST(HttpConfigRequest, ResponseCarriesStatusTypeAndLength) {
    const QByteArray response = formatResponse({200, "abc", false});
    EXPECT_EQ(response, "HTTP/1.0 200 OK\r\nContent-Type: text/plain; charset=utf-8\r\nContent-Length: 3\r\n"
                        "Connection: close\r\n\r\nabc");
}

class HttpConfigServerTest : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_TRUE(server_.listen(QHostAddress::LocalHost, 0)); }

    HttpConfigServer server_{demoFile, [](std::string_view name) { return demoLayout().pictureFor(name); }};
};

TEST_F(HttpConfigServerTest, GetLokomotiveCs2ReturnsTheServedBytes) {
    const QByteArray response = exchange(server_.port(), "GET /config/lokomotive.cs2 HTTP/1.0\r\n\r\n");
    EXPECT_TRUE(headerOf(response).startsWith("HTTP/1.0 200 OK\r\n"));
    EXPECT_TRUE(headerOf(response).contains("Content-Type: text/plain; charset=utf-8"));
    EXPECT_EQ(bodyOf(response).toStdString(), *demoFile("lokomotive.cs2"));
    EXPECT_TRUE(
        headerOf(response).contains("Content-Length: " + QByteArray::number(bodyOf(response).size())));
}

TEST_F(HttpConfigServerTest, RequestArrivingInPiecesIsAnswered) {
    QTcpSocket socket;
    socket.connectToHost(QHostAddress::LocalHost, server_.port());
    ASSERT_TRUE(socket.waitForConnected(test::WaitMs));
    QByteArray response;
    QObject::connect(&socket, &QTcpSocket::readyRead, &socket, [&] { response += socket.readAll(); });
    for (const char* piece : {"GET /config/glei", "sbild.cs2 HTTP/1.0\r\n", "Host: x\r\n", "\r\n"}) {
        socket.write(piece);
        socket.flush();
        QTest::qWait(10);
    }
    EXPECT_TRUE(test::waitFor([&] { return socket.state() == QAbstractSocket::UnconnectedState; }));
    EXPECT_EQ(bodyOf(response).toStdString(), *demoFile("gleisbild.cs2"));
}

TEST_F(HttpConfigServerTest, UnknownFileAndTraversalAreRefused) {
    EXPECT_TRUE(
        exchange(server_.port(), "GET /config/fehlt.cs2 HTTP/1.0\r\n\r\n").startsWith("HTTP/1.0 404 "));
    EXPECT_TRUE(exchange(server_.port(), "GET /config/../../etc/passwd HTTP/1.0\r\n\r\n")
                    .startsWith("HTTP/1.0 404 "));
    EXPECT_TRUE(exchange(server_.port(), "NONSENSE\r\n\r\n").startsWith("HTTP/1.0 400 "));
    EXPECT_EQ(server_.requestsAnswered(), 3U);
}

TEST_F(HttpConfigServerTest, OverlongRequestIsBadRequest) {
    const QByteArray request = "GET /config/" + QByteArray(HttpConfigServer::MaxRequestBytes + 10, 'a');
    EXPECT_TRUE(exchange(server_.port(), request).startsWith("HTTP/1.0 400 "));
}

} // namespace
} // namespace stellwerk::sim

namespace stellwerk::sim {
namespace {

TEST(DemoPictures, EveryDemoLocomotiveHasASoundPicture) {
    ASSERT_FALSE(demoLayout().locomotives().locomotives.empty());
    for (const cs2config::Locomotive& loco : demoLayout().locomotives().locomotives) {
        const auto name = cs2config::picture::fileName(loco.icon);
        ASSERT_TRUE(name) << loco.name;
        const auto picture = demoLayout().pictureFor(*name);
        ASSERT_TRUE(picture) << *name;
        cs2config::picture::Size size;
        EXPECT_EQ(cs2config::picture::problem(*picture, &size), std::nullopt) << *name;
        EXPECT_EQ(size.width, 240);
        EXPECT_EQ(size.height, 80);
    }
}

TEST_F(HttpConfigServerTest, APictureIsServedAsPng) {
    const QByteArray response = exchange(server_.port(), "GET /icons/BR%20218.png HTTP/1.0\r\n\r\n");
    EXPECT_TRUE(headerOf(response).startsWith("HTTP/1.0 200 OK\r\n"));
    EXPECT_TRUE(headerOf(response).contains("Content-Type: image/png\r\n"));
    EXPECT_EQ(bodyOf(response).toStdString(), *demoLayout().pictureFor("BR 218.png"));
}

TEST_F(HttpConfigServerTest, UnknownPicturesAndPathsBelowIconsAreRefused) {
    for (const QByteArray& target :
         {QByteArray("/icons/fehlt.png"), QByteArray("/icons/../config/lokomotive.cs2"),
          QByteArray("/icons/a/BR%20218.png"), QByteArray("/icons/")})
        EXPECT_TRUE(
            exchange(server_.port(), "GET " + target + " HTTP/1.0\r\n\r\n").startsWith("HTTP/1.0 404 "))
            << target.toStdString();
}

TEST(HttpConfigRequest, WithoutPicturesIconsAreNotFound) {
    EXPECT_EQ(ask("GET /icons/BR%20218.png HTTP/1.0\r\n\r\n").status, 404);
}

// The simulator's own documents (stellwerk-sim's GET /accidents): JSON made at the time of each request.
TEST(HttpConfigRequest, AJsonDocumentIsMadeForEachRequest) {
    int asked = 0;
    const JsonDocuments documents{
        {"/accidents", [&asked] { return "{\"total\":" + std::to_string(++asked) + "}"; }}};
    HttpAnswer answer = answerConfigRequest("GET /accidents HTTP/1.0\r\n\r\n", demoFile, {}, documents);
    EXPECT_EQ(answer.status, 200);
    EXPECT_EQ(answer.contentType, "application/json");
    EXPECT_EQ(answer.body, "{\"total\":1}");
    answer = answerConfigRequest("HEAD /accidents HTTP/1.0\r\n\r\n", demoFile, {}, documents);
    EXPECT_TRUE(answer.headOnly);
    EXPECT_EQ(answerConfigRequest("GET /accidents/x HTTP/1.0\r\n\r\n", demoFile, {}, documents).status, 404);
    EXPECT_EQ(ask("GET /accidents HTTP/1.0\r\n\r\n").status, 404) << "only where the simulator serves it";
}

TEST_F(HttpConfigServerTest, ServesJsonDocumentsGivenToIt) {
    server_.serveJson("/accidents", [] { return std::string("{\"total\":0}"); });
    const QByteArray response = exchange(server_.port(), "GET /accidents HTTP/1.0\r\n\r\n");
    EXPECT_TRUE(headerOf(response).contains("Content-Type: application/json")) << response.toStdString();
    EXPECT_EQ(bodyOf(response), "{\"total\":0}");
}

TEST(EmbeddedStationWeb, ServesTheDemoPicturesOnItsOwnLoopbackPort) {
    EmbeddedStation station;
    EXPECT_TRUE(station.webAddress().isEmpty());
    ASSERT_TRUE(station.start()) << station.errorString().toStdString();
    const QUrl web(station.webAddress());
    EXPECT_EQ(web.host(), "127.0.0.1");
    ASSERT_GT(web.port(), 0);
    EXPECT_NE(web.port(), station.tcpPort());
    const QByteArray response =
        exchange(std::uint16_t(web.port()), "GET /icons/ICE%203.png HTTP/1.0\r\n\r\n");
    EXPECT_EQ(bodyOf(response).toStdString(), *demoLayout().pictureFor("ICE 3.png"));
}

} // namespace
} // namespace stellwerk::sim
