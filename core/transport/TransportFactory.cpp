#include "transport/TransportFactory.h"

#include "transport/CanBusTransport.h"
#include "transport/TcpTransport.h"
#include "transport/TransportAddress.h"
#include "transport/UdpTransport.h"

namespace stellwerk::transport {

namespace {

std::unique_ptr<Transport> make(const UdpSettings& settings) {
    return std::make_unique<UdpTransport>(settings);
}
std::unique_ptr<Transport> make(const TcpSettings& settings) {
    return std::make_unique<TcpTransport>(settings);
}
std::unique_ptr<Transport> make(const CanBusSettings& settings) {
    return std::make_unique<CanBusTransport>(settings);
}

} // namespace

std::unique_ptr<Transport> createTransport(const TransportSettings& settings) {
    return std::visit([](const auto& each) { return make(each); }, settings);
}

Expected<std::unique_ptr<Transport>, QString> createTransport(const QString& url) {
    const auto settings = parseTransportUrl(url);
    if (!settings)
        return settings.error();
    return createTransport(*settings);
}

} // namespace stellwerk::transport
