#pragma once

#include "base/Expected.h"
#include "transport/TransportSettings.h"

#include <QString>

namespace stellwerk::transport {

// Transport addresses as a person types them and settings store them:
//   udp://host[:port][?listen=port]   frames to host:port (default 15731), received on listen (default 15730)
//   tcp://host[:port]                 a TCP connection to host:port (default 15731)
//   can://plugin/interface[?bitrate=n] a QCanBus device, for example can://socketcan/can0
// Returns the settings, or a message saying what is wrong with the text.
Expected<TransportSettings, QString> parseTransportUrl(const QString& text);

// The address of settings in the form parseTransportUrl() reads (reconnect timing is not part of it).
QString transportUrl(const UdpSettings& settings);
QString transportUrl(const TcpSettings& settings);
QString transportUrl(const CanBusSettings& settings);
QString transportUrl(const TransportSettings& settings);

} // namespace stellwerk::transport
