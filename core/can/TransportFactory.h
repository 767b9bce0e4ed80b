#pragma once

#include "can/Transport.h"
#include "can/TransportSettings.h"
#include "cs2/Expected.h"

#include <QString>
#include <memory>

namespace stellwerk::can {

// Makes the transport that settings or an address (see TransportAddress.h) describe, not opened yet.
std::unique_ptr<Transport> createTransport(const TransportSettings& settings);
// Returns the transport, or what is wrong with the address.
cs2::Expected<std::unique_ptr<Transport>, QString> createTransport(const QString& url);

} // namespace stellwerk::can
