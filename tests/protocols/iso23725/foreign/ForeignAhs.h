#pragma once
// A foreign AHS for the dispatch tests: written from the message tables of
// shared/research/iso23725.md (§5 rows 8, 10, 17, 21-24; §6 examples), sharing no code with sim/ or with the
// console's codec. Its own minimal WebSocket server (Boost.Beast, synchronous, one FMS at a time, 127.0.0.1,
// port 0) sends hand-written frames and records every text frame the FMS sends, verbatim. Behaviours as other
// vendors' stacks might have them: no DispatchingCustodian at all, a custodian of AHS, assignments answered
// (Accepted + HaulTruckAssignmentV1 Active), answered late or left unanswered, an unsolicited Rejected after
// an Accepted. With `production`, one load-haul-dump cycle of production messages (§5 rows 16-20, §6
// examples) after the snapshot, in one of several dialects: as the tables' examples, with every optional
// field left out, with unknown extra members and fields, or with the fields in another order.
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
    int answerDelayMs = 0;         // answers that come late
    std::string unsolicitedReject; // after the Accepted and Active: Rejected with this Detail ("" = none)
    bool production = false;       // the production cycle below after the snapshot
    enum class Dialect { Tables, Minimal, Extra, Reordered };
    Dialect dialect = Dialect::Tables;
};

// The values of the production cycle the peer sends (the §6 examples' values); what the console must show.
struct ForeignProduction {
    static constexpr const char* cycleId = "3c5e7a91-2b4d-4f60-8a1c-9e0d2f4b6c88";
    static constexpr const char* loadAssignment = "e41a7c2b-6d3f-4b58-a9e0-7f1c2d3b4a56";
    static constexpr const char* dumpAssignment = "f52b8d3c-7e40-4c69-b0f1-8a2d3e4c5b67";
    static constexpr const char* loader = "a2d4f6b8-1c3e-4a5b-9d7f-0e2c4b6a8d13";
    static constexpr std::int64_t payload = 289;
    static constexpr double accuracy = 4.5;
    static constexpr std::int64_t loadWay = 4201;
    static constexpr std::int64_t dumpWay = 4101;
    static constexpr std::int64_t haulWay = 2001;
    // The last production state: back on the ramp, empty, after the dump.
    static constexpr const char* finalState = "Driving";
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
