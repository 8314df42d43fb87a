#pragma once
// Shared helpers of the ISO 23725 end-to-end tests: a thread-safe recording listener and polling waits.
#include "protocols/iso23725/IsoStack.h"

#include <chrono>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace isotest {

using namespace ocu::iso23725;

struct Recorder : IsoListener {
    mutable std::mutex mu;
    std::map<std::string, LinkState> links;
    std::vector<std::pair<IsoSeverity, std::string>> events;
    std::vector<AllStopStatus> allStops;
    std::map<Guid, IsoMachineSnapshot> machines;
    std::vector<std::string> discrepancies;
    std::vector<MapProgress> progress;
    int maps = 0;
    std::size_t mapNodes = 0, mapWays = 0, mapConnectivity = 0;

    void onLinkState(const std::string& link, LinkState s, const std::string&) override {
        std::lock_guard l(mu);
        links[link] = s;
    }
    void onMachineChanged(const IsoMachineSnapshot& m) override {
        std::lock_guard l(mu);
        machines[m.equipmentId] = m;
    }
    void onAllStopChanged(const std::string&, const AllStopStatus& s) override {
        std::lock_guard l(mu);
        allStops.push_back(s);
    }
    void onMapProgress(const std::string&, const MapProgress& p) override {
        std::lock_guard l(mu);
        progress.push_back(p);
    }
    void onMapChanged(const std::string&, const MapModel& m) override {
        std::lock_guard l(mu);
        ++maps;
        mapNodes = m.nodes.size();
        mapWays = m.ways.size();
        mapConnectivity = m.connectivity.size();
    }
    void onFleetDiscrepancies(const std::string&, const std::vector<FleetDiscrepancy>& items) override {
        std::lock_guard l(mu);
        discrepancies = discrepancyTexts(items);
    }
    void onEvent(IsoSeverity s, const std::string& text) override {
        std::lock_guard l(mu);
        events.emplace_back(s, text);
    }

    LinkState link(const std::string& n) const {
        std::lock_guard l(mu);
        auto it = links.find(n);
        return it == links.end() ? LinkState::Unknown : it->second;
    }
    AllStopState allStop() const {
        std::lock_guard l(mu);
        return allStops.empty() ? AllStopState::Unknown : allStops.back().state;
    }
    bool hasEvent(const std::string& needle) const {
        std::lock_guard l(mu);
        for (auto& [s, t] : events)
            if (t.find(needle) != std::string::npos)
                return true;
        return false;
    }
    // Fleet discrepancies come once, through onFleetDiscrepancies (no event per item).
    bool hasDiscrepancy(const std::string& needle) const {
        std::lock_guard l(mu);
        for (auto& t : discrepancies)
            if (t.find(needle) != std::string::npos)
                return true;
        return false;
    }
    int machinesWith(const std::function<bool(const IsoMachineSnapshot&)>& pred) const {
        std::lock_guard l(mu);
        int n = 0;
        for (auto& [id, m] : machines)
            n += pred(m) ? 1 : 0;
        return n;
    }
    template <class F> auto with(F&& f) const {
        std::lock_guard l(mu);
        return f();
    }
};

// Polls pred every 20 ms until true or timeout (tests end by themselves). Generous: on an idle machine every
// condition holds within a fraction of it, and a loaded one must not fail a test that is right.
inline bool waitFor(const std::function<bool()>& pred,
                    std::chrono::milliseconds timeout = std::chrono::seconds(20)) {
    auto end = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < end) {
        if (pred())
            return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return pred();
}

// The outcome of one command, waited for: `issue` is given the callback to pass to the stack's command.
template <class Issue> std::vector<ocu::TargetOutcome> outcome(Issue&& issue) {
    auto p = std::make_shared<std::promise<std::vector<ocu::TargetOutcome>>>();
    auto f = p->get_future();
    issue([p](std::vector<ocu::TargetOutcome> o) { p->set_value(std::move(o)); });
    if (f.wait_for(std::chrono::seconds(30)) != std::future_status::ready)
        return {};
    return f.get();
}

// The single outcome of a command for one target: sent, or refused with `cause`.
inline bool sentOne(const std::vector<ocu::TargetOutcome>& o) {
    return o.size() == 1 && o[0].sent;
}
inline bool refusedOne(const std::vector<ocu::TargetOutcome>& o, ocu::OutcomeReason cause) {
    return o.size() == 1 && !o[0].sent && o[0].cause == cause && !o[0].reason.empty();
}

} // namespace isotest
