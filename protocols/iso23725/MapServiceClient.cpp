#include "protocols/iso23725/MapServiceClient.h"

#include "protocols/common/Log.h"
#include "protocols/iso23725/LogCategory.h"

namespace ocu::iso23725 {

namespace {
// The API version of the map service this console speaks (§10.6.1 [I]).
constexpr std::int64_t kMapServiceApi = 1;
constexpr std::chrono::seconds kIdentificationWait{5};
} // namespace

MapServiceClient::MapServiceClient(std::string link, bool separateChannel, std::string identificationMember,
                                   IsoListener& listener, Counters& counters, const Clock& clock, Hooks hooks)
    : m_link(std::move(link)), m_separate(separateChannel),
      m_identificationMember(std::move(identificationMember)), m_listener(listener), m_counters(counters),
      m_clock(clock), m_hooks(std::move(hooks)) {}

// ---------------------------------------------------------------- channels

void MapServiceClient::linkOpened() {
    if (!m_separate)
        interruptTransfer("reconnected");
}

void MapServiceClient::linkClosed() {
    if (!m_separate)
        interruptTransfer("link down");
}

void MapServiceClient::channelOpened(const std::string& peer) {
    m_channelState = LinkState::Up;
    interruptTransfer("map service reconnected");
    m_counters.add("map_service.opened");
    m_hooks.event(IsoSeverity::Info, "map service of " + m_link + " up (" + peer + ")");
    // The service speaks first (MapServiceV1, §10.6.1 [I]); the summary is asked for when it has, or after
    // kIdentificationWait from a service that does not identify itself.
    m_identificationDeadline = m_clock.now() + kIdentificationWait;
}

void MapServiceClient::channelClosed(const std::string& reason) {
    m_channelState = LinkState::Down;
    m_identificationDeadline.reset();
    interruptTransfer("map service down");
    m_hooks.event(IsoSeverity::Warning, "map service of " + m_link + " down: " + reason);
}

// ---------------------------------------------------------------- from the service

void MapServiceClient::service(const MapServiceV1& s, bool onMapChannel) {
    m_counters.add("rx.map_service");
    if (s.api > kMapServiceApi)
        logInfo(kLog, "map service of " + m_link + " offers API " + std::to_string(s.api) + "; using " +
                          std::to_string(kMapServiceApi));
    if (s.api < kMapServiceApi)
        m_hooks.event(IsoSeverity::Warning, "map service of " + m_link + " offers API " +
                                                std::to_string(s.api) + " only; this console speaks API " +
                                                std::to_string(kMapServiceApi));
    if (onMapChannel != m_separate)
        return; // identification on the other socket: nothing to ask there
    m_identificationDeadline.reset();
    // Identified: ask where the map stands; the summary decides whether to fetch (§10.6.3).
    askSummaryIfIdle();
}

void MapServiceClient::summary(const MapSummaryV1& s, bool onMapChannel) {
    if (onMapChannel != m_separate) {
        m_counters.add("rx.rejected.map_on_wrong_channel");
        return;
    }
    if (m_assembler.active()) {
        if (m_fetchingSummary && m_fetchingSummary->changeSetMap == s.changeSetMap &&
            m_fetchingSummary->changeSetWay == s.changeSetWay)
            return; // the same map being transferred
        m_hooks.event(IsoSeverity::Warning, "map changed during transfer on " + m_link + ": fetching again");
        m_assembler.reset();
        if (!m_fetchPending) {
            requestMap();
            return;
        }
    }
    if (m_fetchPending) {
        m_fetchPending = false;
        m_fetchingSummary = s;
        m_assembler.begin(s);
        m_listener.onMapProgress(m_link, m_assembler.progress());
        if (s.documentCount == 0)
            finishMap();
        return;
    }
    // Re-fetch when the change sets moved (§8 exchange).
    if (!m_map || m_map->summary.changeSetMap != s.changeSetMap ||
        m_map->summary.changeSetWay != s.changeSetWay)
        requestMap();
}

void MapServiceClient::chunk(std::string_view xml, bool onMapChannel) {
    if (onMapChannel != m_separate) {
        m_counters.add("rx.rejected.map_on_wrong_channel");
        m_hooks.event(IsoSeverity::Warning, "map chunk on the main socket of " + m_link +
                                                " ignored: the map service has its own URL");
        return;
    }
    if (!m_assembler.active()) {
        m_counters.add("rx.rejected.unexpected_map_chunk");
        m_hooks.event(IsoSeverity::Warning,
                      "map chunk from " + m_link + " without a pending map request ignored");
        return;
    }
    auto p = m_assembler.addChunk(xml);
    if (!p) {
        m_counters.add("rx.rejected.map");
        m_hooks.event(IsoSeverity::Error, "map from " + m_link + " rejected: " + p.error() +
                                              (m_map ? " (previous map kept)" : std::string()));
        m_hooks.rejected(p.error(), true);
        return;
    }
    m_listener.onMapProgress(m_link, *p);
    if (p->complete())
        finishMap();
}

// §9: the connectivity comes on the main socket, apart from the map service; it joins the map it belongs to.
void MapServiceClient::connectivity(const MapConnectivityV1& c) {
    m_connectivity = c;
    if (m_map) {
        auto m = std::make_shared<MapModel>(*m_map);
        m->connectivity.assign(c);
        m_map = m;
        m_listener.onMapChanged(m_link, *m);
    }
}

// ---------------------------------------------------------------- fetching

bool MapServiceClient::fetch() {
    if (m_separate && m_channelState != LinkState::Up) {
        m_counters.add("cmd.refused.link_down");
        m_hooks.event(IsoSeverity::Warning, "map fetch refused: the map service of '" + m_link + "' is " +
                                                nameFor(m_channelState) + " (commands are not queued)");
        return false;
    }
    m_assembler.reset();
    if (requestMap())
        return true;
    m_counters.add("cmd.refused.socket");
    m_hooks.event(IsoSeverity::Warning, "map fetch not sent: the socket of the map service of '" + m_link +
                                            "' did not take the frame");
    return false;
}

bool MapServiceClient::requestMap() {
    if (!m_hooks.send(MapCommandV1{"GET", "/"}))
        return false;
    m_fetchPending = true;
    m_counters.add("map.fetch");
    return true;
}

void MapServiceClient::askSummaryIfIdle() {
    if (!m_fetchPending && !m_assembler.active())
        m_hooks.send(MapCommandV1{"GET", "/summary"});
}

void MapServiceClient::interruptTransfer(const std::string& why) {
    if (m_assembler.active()) {
        m_assembler.reset();
        m_hooks.event(IsoSeverity::Warning, "map transfer from " + m_link + " interrupted (" + why + ")" +
                                                (m_map ? ", previous map kept" : std::string()));
    }
    m_fetchPending = false;
}

void MapServiceClient::finishMap() {
    auto m = m_assembler.finish();
    if (!m) {
        m_counters.add("rx.rejected.map");
        m_hooks.event(IsoSeverity::Error, "map from " + m_link + " rejected: " + m.error());
        m_hooks.rejected(m.error(), false);
        return;
    }
    auto model = std::make_shared<MapModel>(std::move(*m));
    if (m_connectivity)
        model->connectivity.assign(*m_connectivity);
    for (auto& w : model->warnings)
        m_hooks.event(IsoSeverity::Warning, "map from " + m_link + ": " + w);
    m_map = model;
    m_counters.add("map.complete");
    m_hooks.event(IsoSeverity::Info, "map from " + m_link +
                                         " complete: " + std::to_string(model->nodes.size()) + " nodes, " +
                                         std::to_string(model->ways.size()) + " ways");
    m_listener.onMapChanged(m_link, *model);
}

void MapServiceClient::poll() {
    if (m_identificationDeadline && m_clock.now() >= *m_identificationDeadline) {
        m_identificationDeadline.reset();
        m_counters.add("map_service.unidentified");
        m_hooks.event(IsoSeverity::Warning, "map service of " + m_link + " did not identify itself (" +
                                                m_identificationMember + "); asking for its summary anyway");
        askSummaryIfIdle();
    }
}

} // namespace ocu::iso23725
