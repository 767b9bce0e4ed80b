#include "sim/HttpConfigServer.h"

#include <QTcpServer>
#include <QTcpSocket>
#include <QTimer>
#include <QUrl>

namespace stellwerk::sim {

namespace {

constexpr std::string_view ConfigPrefix = "/config/";
constexpr std::string_view PicturePrefix = "/icons/";

QByteArray reason(int status) {
    switch (status) {
    case 200:
        return "OK";
    case 400:
        return "Bad Request";
    case 404:
        return "Not Found";
    case 405:
        return "Method Not Allowed";
    default:
        return "Error";
    }
}

HttpAnswer problem(int status) {
    return {status, reason(status) + '\n', false};
}

// A path below /config/ that names a file: no "." or ".." segment, no empty segment, no backslash and no
// control character, so that nothing can climb out of the configuration folder.
bool safeConfigPath(std::string_view path) {
    if (path.empty() || path.front() == '/' || path.back() == '/')
        return false;
    for (const char c : path)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F || c == '\\')
            return false;
    std::size_t start = 0;
    while (start <= path.size()) {
        const std::size_t end = std::min(path.find('/', start), path.size());
        const std::string_view segment = path.substr(start, end - start);
        if (segment.empty() || segment == "." || segment == "..")
            return false;
        start = end + 1;
    }
    return true;
}

// The first line of a request, split into method, target and version; false when it is not HTTP.
bool splitRequestLine(const QByteArray& request, QByteArray& method, QByteArray& target) {
    const qsizetype lineEnd = request.indexOf('\n');
    const QList<QByteArray> parts = request.left(lineEnd < 0 ? request.size() : lineEnd).trimmed().split(' ');
    if (parts.size() != 3 || !parts[2].startsWith("HTTP/1.") || !parts[1].startsWith('/'))
        return false;
    method = parts[0];
    target = parts[1];
    return true;
}

// A picture is one file name below /icons/, never a path.
HttpAnswer answerPicture(std::string_view name, const ConfigFileLookup& pictures, bool head) {
    if (!pictures || !safeConfigPath(name) || name.find('/') != std::string_view::npos)
        return problem(404);
    const std::optional<std::string> picture = pictures(name);
    if (!picture)
        return problem(404);
    return {200, QByteArray::fromStdString(*picture), head, "image/png"};
}

} // namespace

HttpAnswer answerConfigRequest(const QByteArray& request, const ConfigFileLookup& files,
                               const ConfigFileLookup& pictures, const JsonDocuments& documents) {
    QByteArray method;
    QByteArray target;
    if (!splitRequestLine(request, method, target))
        return problem(400);
    if (method != "GET" && method != "HEAD")
        return problem(405);
    const qsizetype query = target.indexOf('?');
    const std::string path =
        QByteArray::fromPercentEncoding(target.left(query < 0 ? target.size() : query)).toStdString();
    const bool head = method == "HEAD";
    if (const auto document = documents.find(path); document != documents.end())
        return {200, QByteArray::fromStdString(document->second()), head, "application/json"};
    if (path.starts_with(PicturePrefix))
        return answerPicture(std::string_view(path).substr(PicturePrefix.size()), pictures, head);
    if (!path.starts_with(ConfigPrefix) ||
        !safeConfigPath(std::string_view(path).substr(ConfigPrefix.size())))
        return problem(404);
    const std::optional<std::string> file = files(std::string_view(path).substr(ConfigPrefix.size()));
    if (!file)
        return problem(404);
    return {200, QByteArray::fromStdString(*file), head};
}

QByteArray formatResponse(const HttpAnswer& answer) {
    QByteArray response =
        "HTTP/1.0 " + QByteArray::number(answer.status) + ' ' + reason(answer.status) + "\r\n";
    response += "Content-Type: " + answer.contentType + "\r\n";
    response += "Content-Length: " + QByteArray::number(answer.body.size()) + "\r\n";
    response += "Connection: close\r\n\r\n";
    if (!answer.headOnly)
        response += answer.body;
    return response;
}

HttpConfigServer::HttpConfigServer(ConfigFileLookup files, ConfigFileLookup pictures, QObject* parent)
    : QObject(parent), files_(std::move(files)), pictures_(std::move(pictures)),
      server_(new QTcpServer(this)) {
    connect(server_, &QTcpServer::newConnection, this, &HttpConfigServer::accept);
}

HttpConfigServer::~HttpConfigServer() {
    for (auto& [socket, request] : pending_)
        socket->disconnect(this);
}

void HttpConfigServer::serveJson(std::string path, std::function<std::string()> document) {
    documents_.insert_or_assign(std::move(path), std::move(document));
}

bool HttpConfigServer::listen(const QHostAddress& address, std::uint16_t port) {
    return server_->listen(address, port);
}

std::uint16_t HttpConfigServer::port() const {
    return server_->serverPort();
}

QString HttpConfigServer::errorString() const {
    return server_->errorString();
}

void HttpConfigServer::accept() {
    while (QTcpSocket* socket = server_->nextPendingConnection()) {
        pending_.emplace(socket, QByteArray{});
        connect(socket, &QTcpSocket::readyRead, this, [this, socket] { read(socket); });
        connect(socket, &QTcpSocket::disconnected, this, [this, socket] {
            pending_.erase(socket);
            socket->deleteLater();
        });
        // A client that never finishes its request does not keep the connection.
        QTimer::singleShot(IdleTimeoutMs, socket, [socket] { socket->abort(); });
    }
}

void HttpConfigServer::read(QTcpSocket* socket) {
    const auto pending = pending_.find(socket);
    if (pending == pending_.end())
        return;
    QByteArray& request = pending->second;
    request += socket->readAll();
    const bool complete = request.contains("\r\n\r\n") || request.contains("\n\n");
    if (complete)
        answer(socket, answerConfigRequest(request, files_, pictures_, documents_));
    else if (request.size() > MaxRequestBytes)
        answer(socket, problem(400));
}

void HttpConfigServer::answer(QTcpSocket* socket, const HttpAnswer& answer) {
    pending_.erase(socket);
    socket->disconnect(this, nullptr); // one request per connection: later bytes are ignored
    connect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
    socket->write(formatResponse(answer));
    socket->disconnectFromHost();
    ++answered_;
}

} // namespace stellwerk::sim
