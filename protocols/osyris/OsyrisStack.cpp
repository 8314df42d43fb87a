#include "protocols/osyris/OsyrisStack.h"

#include "protocols/common/IoThread.h"
#include "protocols/common/Log.h"
#include "protocols/common/Udp.h"

#include <boost/asio/ip/udp.hpp>
#include <boost/asio/steady_timer.hpp>

#include <array>
#include <random>

namespace ocu::osyris {

namespace asio = boost::asio;
using asio::ip::udp;

struct OsyrisStack::Impl {
    IoThread io{"osyris"};
    udp::socket socket{io.context()};
    asio::steady_timer beat{io.context()};
    std::unique_ptr<RibbonStore> store;
    std::unique_ptr<StationCore> core;
    UdpOptions udpOptions;
    std::vector<udp::endpoint> destinations;
    std::array<std::uint8_t, 65536> rxBuf{};
    udp::endpoint sender;
    RxImpairment imp;
    std::mt19937 rng{1};
    bool running = false;
    std::chrono::steady_clock::time_point nextBeat;
};

OsyrisStack::OsyrisStack(OsyrisConfig cfg, OsyrisListener& listener)
    : m_cfg(std::move(cfg)), m_listener(listener), m_grid(m_cfg.passCount), m_impl(std::make_unique<Impl>()) {
}

OsyrisStack::~OsyrisStack() {
    stop();
}

Counters& OsyrisStack::counters() {
    return m_impl->core ? m_impl->core->counters() : m_fallbackCounters;
}
RibbonStore* OsyrisStack::store() {
    return m_impl->store.get();
}
StationCore* OsyrisStack::core() {
    return m_impl->core.get();
}
bool OsyrisStack::running() const {
    return m_impl->running;
}

void OsyrisStack::callOnIo(const std::function<void()>& f) {
    m_impl->io.call([&] { f(); });
}

bool OsyrisStack::start(std::string* error) {
    if (m_impl->running)
        return true;
    auto fail = [&](const std::string& msg) {
        if (error)
            *error = msg;
        logWarning("osyris", msg);
        m_listener.onEvent(Severity::Error, msg);
        return false;
    };
    auto st = RibbonStore::open(m_cfg.sqlitePath);
    if (!st)
        return fail(st.error());
    m_impl->store = std::move(*st);
    auto& o = m_impl->udpOptions;
    // Multicast: bind the group address, so only the group's datagrams arrive and nothing listens on other
    // addresses; unicast: the interface; broadcast needs the wildcard.
    o.bindAddress = m_cfg.addressing == Addressing::Multicast ? m_cfg.group
                    : m_cfg.addressing == Addressing::Unicast ? m_cfg.interfaceAddress
                                                              : std::string("0.0.0.0");
    o.port = m_cfg.port;
    o.interfaceAddress = m_cfg.interfaceAddress;
    o.multicastTtl = m_cfg.multicastTtl;
    o.broadcast = m_cfg.addressing == Addressing::Broadcast;
    o.multicastGroup = m_cfg.addressing == Addressing::Multicast ? m_cfg.group : "";
    try {
        openUdpSocket(m_impl->socket, o);
        boost::system::error_code ec;
        m_impl->destinations.clear();
        m_impl->destinations.emplace_back(asio::ip::make_address_v4(m_cfg.group), m_cfg.port);
        for (auto& peer : m_cfg.unicastPeers) {
            auto colon = peer.rfind(':');
            std::string ip = colon == std::string::npos ? peer : peer.substr(0, colon);
            int port = colon == std::string::npos ? m_cfg.port : std::atoi(peer.c_str() + colon + 1);
            auto addr = asio::ip::make_address_v4(ip, ec);
            if (ec || port <= 0 || port > 65535)
                return fail("OSYRIS unicast peer '" + peer + "' is not ip:port");
            m_impl->destinations.emplace_back(addr, static_cast<std::uint16_t>(port));
        }
        m_localPort = m_impl->socket.local_endpoint().port();
    } catch (const std::exception& e) {
        return fail(std::string("OSYRIS socket: ") + e.what());
    }
    Impl* impl = m_impl.get();
    auto send = [impl](const Bytes& d) {
        for (auto& ep : impl->destinations) {
            boost::system::error_code ec;
            impl->socket.send_to(asio::buffer(d), ep, 0, ec);
            if (ec && impl->core)
                impl->core->counters().add("tx.error");
        }
    };
    m_impl->core =
        std::make_unique<StationCore>(m_cfg, SteadyClock::instance(), *m_impl->store, &m_grid, &m_listener,
                                      send, static_cast<std::uint32_t>(m_cfg.stationIndex) * 7919u + 17u);
    m_impl->running = true;
    m_impl->io.start();
    m_impl->io.post([this] {
        m_impl->core->start();
        m_impl->core->updateGrid(); // counts of a reopened site file appear at once
        auto receive = [this](auto&& self) -> void {
            m_impl->socket.async_receive_from(
                asio::buffer(m_impl->rxBuf), m_impl->sender,
                [this, self](boost::system::error_code ec, std::size_t n) {
                    if (ec == asio::error::operation_aborted || !m_impl->socket.is_open())
                        return;
                    if (!ec) {
                        auto& imp = m_impl->imp;
                        std::uniform_real_distribution<double> u(0, 1);
                        if (imp.loss > 0 && u(m_impl->rng) < imp.loss) {
                            m_impl->core->counters().add("rx.impaired.lost");
                        } else {
                            Bytes copy(m_impl->rxBuf.begin(),
                                       m_impl->rxBuf.begin() + static_cast<std::ptrdiff_t>(n));
                            int times = (imp.duplicate > 0 && u(m_impl->rng) < imp.duplicate) ? 2 : 1;
                            if (times == 2)
                                m_impl->core->counters().add("rx.impaired.duplicated");
                            if (imp.reorder > 0 && u(m_impl->rng) < imp.reorder) {
                                m_impl->core->counters().add("rx.impaired.delayed");
                                auto t = std::make_shared<asio::steady_timer>(m_impl->io.context());
                                t->expires_after(std::chrono::milliseconds(imp.delayMs));
                                t->async_wait([this, t, copy, times](boost::system::error_code e) {
                                    if (!e && m_impl->running)
                                        for (int i = 0; i < times; ++i)
                                            m_impl->core->receive(copy);
                                });
                            } else {
                                for (int i = 0; i < times; ++i)
                                    m_impl->core->receive(copy);
                            }
                        }
                    }
                    self(self);
                });
        };
        receive(receive);
        m_impl->nextBeat = std::chrono::steady_clock::now() + std::chrono::milliseconds(m_cfg.beatMs);
        auto onBeat = [this](auto&& self) -> void {
            m_impl->beat.expires_at(m_impl->nextBeat);
            m_impl->beat.async_wait([this, self](boost::system::error_code ec) {
                if (ec || !m_impl->running)
                    return;
                m_impl->core->tick();
                m_impl->nextBeat += std::chrono::milliseconds(m_cfg.beatMs);
                auto now = std::chrono::steady_clock::now();
                if (m_impl->nextBeat < now)
                    m_impl->nextBeat = now; // never burst to catch up after a stall
                self(self);
            });
        };
        onBeat(onBeat);
    });
    return true;
}

void OsyrisStack::stop() {
    if (!m_impl->running)
        return;
    m_impl->io.call([this] {
        m_impl->running = false;
        boost::system::error_code ec;
        m_impl->beat.cancel();
        leaveMulticast(m_impl->socket, m_impl->udpOptions); // IGMP leave
        m_impl->socket.close(ec);
        if (m_impl->store)
            m_impl->store->commit();
    });
    m_impl->io.stop();
}

void OsyrisStack::sendText(std::string text) {
    if (!m_impl->running)
        return;
    m_impl->io.post([this, t = std::move(text)] { m_impl->core->sendText(t); });
}

void OsyrisStack::ping(std::uint8_t idx) {
    if (!m_impl->running)
        return;
    m_impl->io.post([this, idx] { m_impl->core->ping(idx); });
}

void OsyrisStack::publishOwnPosition(CmPos p, std::vector<PosProp> props) {
    if (!m_impl->running)
        return;
    m_impl->io.post(
        [this, p, pr = std::move(props)]() mutable { m_impl->core->publishOwnPosition(p, std::move(pr)); });
}

void OsyrisStack::setImpairment(const RxImpairment& imp) {
    auto apply = [this, imp] {
        m_impl->imp = imp;
        m_impl->rng.seed(imp.seed);
    };
    if (m_impl->running)
        m_impl->io.post(apply);
    else
        apply();
}

} // namespace ocu::osyris
