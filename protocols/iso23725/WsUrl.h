#pragma once
// The parts of a ws:// or wss:// URL (host, port, target), for WsEndpoint and the configuration's checks.
#include "protocols/common/Result.h"

#include <cstdint>
#include <string>

namespace ocu::iso23725 {

struct WsUrl {
    bool tls = false;
    std::string host;
    std::uint16_t port = 0;
    std::string target = "/";
};
Result<WsUrl> parseWsUrl(const std::string& url);

} // namespace ocu::iso23725
