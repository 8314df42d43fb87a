#pragma once
// A foreign AHS for the dispatch tests (issue 15 acceptance): written from the message tables of
// shared/research/iso23725.md (§5 rows 8, 10, 17, 21-24; §6 examples), sharing no code with sim/ or with the
// console's codec. Its own minimal WebSocket server (Boost.Beast, synchronous, one FMS at a time, 127.0.0.1,
// port 0) sends hand-written frames and records every text frame the FMS sends, verbatim. Behaviours as other
// vendors' stacks might have them: no DispatchingCustodian at all, a custodian of AHS, assignments answered
// (Accepted + HaulTruckAssignmentV1 Active) or left unanswered.
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace foreign {

struct ForeignAhsOptions {
    std::string truckId = "c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78";
    std::string custodian = "FMS";  // "" = never reports MachineDispatchAvailabilityV1
    std::int64_t truckWayId = 4101; // HaulTruckProductionStateV2.WayId at connection
    bool answerAssignments = true;
};

class ForeignAhs {
public:
    explicit ForeignAhs(ForeignAhsOptions options = {});
    ~ForeignAhs();
    ForeignAhs(const ForeignAhs&) = delete;
    ForeignAhs& operator=(const ForeignAhs&) = delete;

    std::uint16_t port() const { return m_port; }
    std::string url() const { return "ws://127.0.0.1:" + std::to_string(m_port) + "/iso23725"; }

    // Every text frame received from the FMS, verbatim, in order.
    std::vector<std::string> received() const;
    // Waits (up to timeoutMs) until a received frame contains `needle`; returns it, or "" on timeout.
    std::string waitFor(const std::string& needle, int timeoutMs = 30000) const;
    bool connected() const;

private:
    void run();
    void serve(void* socket);

    ForeignAhsOptions m_opt;
    struct Net;
    std::unique_ptr<Net> m_net;
    std::uint16_t m_port = 0;
    std::thread m_thread;
    mutable std::mutex m_mu;
    mutable std::condition_variable m_cv;
    std::vector<std::string> m_received;
    bool m_connected = false;
    bool m_stopping = false;
};

} // namespace foreign
