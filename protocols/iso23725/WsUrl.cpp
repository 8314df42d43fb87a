// ws:// and wss:// URLs of the ISO 23725 WebSocket link (research note §2), apart from Boost.Beast.
#include "protocols/iso23725/WsUrl.h"

#include <stdexcept>

namespace ocu::iso23725 {

Result<WsUrl> parseWsUrl(const std::string& url) {
    WsUrl u;
    std::string rest;
    if (url.rfind("ws://", 0) == 0) {
        rest = url.substr(5);
    } else if (url.rfind("wss://", 0) == 0) {
        u.tls = true;
        rest = url.substr(6);
    } else {
        return makeError("URL '" + url + "' must start with ws:// or wss://");
    }
    auto slash = rest.find('/');
    std::string hostPort = rest.substr(0, slash);
    u.target = slash == std::string::npos ? "/" : rest.substr(slash);
    std::string portText;
    if (!hostPort.empty() && hostPort[0] == '[') {
        auto close = hostPort.find(']');
        if (close == std::string::npos)
            return makeError("URL '" + url + "': unterminated IPv6 address");
        u.host = hostPort.substr(1, close - 1);
        if (close + 1 < hostPort.size() && hostPort[close + 1] == ':')
            portText = hostPort.substr(close + 2);
    } else {
        auto colon = hostPort.rfind(':');
        u.host = hostPort.substr(0, colon);
        if (colon != std::string::npos)
            portText = hostPort.substr(colon + 1);
    }
    if (u.host.empty())
        return makeError("URL '" + url + "': missing host");
    if (portText.empty()) {
        u.port = u.tls ? 443 : 80;
    } else {
        try {
            std::size_t used = 0;
            int p = std::stoi(portText, &used);
            if (used != portText.size() || p < 0 || p > 65535)
                throw std::out_of_range("port");
            u.port = static_cast<std::uint16_t>(p);
        } catch (const std::exception&) {
            return makeError("URL '" + url + "': bad port '" + portText + "'");
        }
    }
    return u;
}

} // namespace ocu::iso23725
