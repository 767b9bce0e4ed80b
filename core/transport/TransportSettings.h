#pragma once

#include <QHostAddress>
#include <QString>
#include <chrono>
#include <cstdint>
#include <optional>
#include <variant>

namespace stellwerk::transport {

// The ports a CS2 uses on the network: it receives on 15731 and sends to 15730.
inline constexpr std::uint16_t StationPort = 15731;
inline constexpr std::uint16_t ListenPort = 15730;

// How a transport that lost its peer tries again: the first retry after `firstRetry`, each further one
// waiting twice as long up to `maxRetry`; an attempt that gets no answer is given up after `attemptTimeout`.
struct ReconnectTiming {
    std::chrono::milliseconds firstRetry{250};
    std::chrono::milliseconds maxRetry{5000};
    std::chrono::milliseconds attemptTimeout{3000};

    friend bool operator==(const ReconnectTiming&, const ReconnectTiming&) = default;
};

// A CS2 or gateway reached by UDP datagrams (one 13-byte frame per datagram out, n x 13 bytes in).
struct UdpSettings {
    QString host;                                     // name or address; a broadcast address is fine
    std::uint16_t remotePort = StationPort;           // where frames are sent
    std::uint16_t localPort = ListenPort;             // where frames are received; 0 = any free port
    QHostAddress localAddress{QHostAddress::AnyIPv4}; // the local address to receive on
    ReconnectTiming reconnect;

    friend bool operator==(const UdpSettings&, const UdpSettings&) = default;
};

// A CS2 or gateway reached over a TCP connection carrying 13-byte frames.
struct TcpSettings {
    QString host;
    std::uint16_t port = StationPort;
    ReconnectTiming reconnect;

    friend bool operator==(const TcpSettings&, const TcpSettings&) = default;
};

// A CAN interface offered by a QCanBus plugin (socketcan, peakcan, virtualcan, ...).
struct CanBusSettings {
    QString plugin;
    QString interfaceName;      // as the plugin names it: "can0", "usb0"; virtualcan also takes a URL
    std::optional<int> bitrate; // set on the device when given (a CS2 bus runs at 250000 bit/s)
    ReconnectTiming reconnect;

    friend bool operator==(const CanBusSettings&, const CanBusSettings&) = default;
};

using TransportSettings = std::variant<UdpSettings, TcpSettings, CanBusSettings>;

} // namespace stellwerk::transport
