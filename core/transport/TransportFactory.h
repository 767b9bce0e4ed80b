#pragma once

#include "base/Expected.h"
#include "transport/Transport.h"
#include "transport/TransportSettings.h"

#include <QString>
#include <memory>

namespace stellwerk::transport {

// Makes the transport that settings or an address (see TransportAddress.h) describe, not opened yet.
std::unique_ptr<Transport> createTransport(const TransportSettings& settings);
// Returns the transport, or what is wrong with the address.
Expected<std::unique_ptr<Transport>, QString> createTransport(const QString& url);

} // namespace stellwerk::transport
