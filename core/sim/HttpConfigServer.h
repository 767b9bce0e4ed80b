#pragma once

#include <QByteArray>
#include <QHostAddress>
#include <QObject>
#include <QString>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>

class QTcpServer;
class QTcpSocket;

namespace stellwerk::sim {

// What to answer an HTTP request.
struct HttpAnswer {
    int status = 200;
    QByteArray body;
    bool headOnly = false; // a HEAD request: headers as for GET, no body
    QByteArray contentType = "text/plain; charset=utf-8";
};

// Answers one request (everything up to the empty line) with the file `files` gives for the path
// below /config/, the picture `pictures` gives for a file name below /icons/ ("BR 218.png", sent as
// image/png), or the JSON document of a path `documents` names ("/accidents"): 200 with the bytes, 404 for
// unknown files and other paths, 400 for requests that are not HTTP, 405 for methods other than GET and
// HEAD. Pure, for tests and the server.
using ConfigFileLookup = std::function<std::optional<std::string>(std::string_view path)>;
using JsonDocuments = std::map<std::string, std::function<std::string()>, std::less<>>;
HttpAnswer answerConfigRequest(const QByteArray& request, const ConfigFileLookup& files,
                               const ConfigFileLookup& pictures = {}, const JsonDocuments& documents = {});
// The whole response: status line, Content-Type, Content-Length, Connection: close, body.
QByteArray formatResponse(const HttpAnswer& answer);

// The CS2's web server as far as Stellwerk uses it: GET /config/lokomotive.cs2 and friends, and the
// locomotive pictures /icons/<name>.png; HTTP/1.0, one request per connection. It never touches the file
// system; names are looked up in the layout. The simulator adds documents of its own (GET /accidents).
class HttpConfigServer : public QObject {
    Q_OBJECT

public:
    static constexpr int MaxRequestBytes = 8192;
    static constexpr int IdleTimeoutMs = 10000;

    explicit HttpConfigServer(ConfigFileLookup files, ConfigFileLookup pictures = {},
                              QObject* parent = nullptr);
    ~HttpConfigServer() override;

    // Answers GET `path` (e.g. "/accidents") with the JSON `document` makes at the time of the request.
    void serveJson(std::string path, std::function<std::string()> document);

    bool listen(const QHostAddress& address, std::uint16_t port);
    std::uint16_t port() const;
    QString errorString() const;
    std::uint64_t requestsAnswered() const { return answered_; }

private:
    void accept();
    void read(QTcpSocket* socket);
    void answer(QTcpSocket* socket, const HttpAnswer& answer);

    ConfigFileLookup files_;
    ConfigFileLookup pictures_;
    JsonDocuments documents_;
    QTcpServer* server_ = nullptr;
    std::map<QTcpSocket*, QByteArray> pending_;
    std::uint64_t answered_ = 0;
};

} // namespace stellwerk::sim
