#pragma once
// A simulated RAS-G IOP UGV on its own io thread: UgvCore behind a JudpTransport (AEP-4818 §10).
// Several can run at once (distinct subsystem IDs, distinct unicast ports, one shared multicast group).
#include <functional>
#include <memory>
#include <optional>

#include "protocols/common/Clock.h"
#include "protocols/common/Counters.h"
#include "sim/jaus/UgvCore.h"

namespace ocu::sim {

class SimulatedUgv {
public:
    explicit SimulatedUgv(SimulatedUgvConfig config, ocu::Clock& clock = SteadyClock::instance());
    ~SimulatedUgv();
    SimulatedUgv(const SimulatedUgv&) = delete;
    SimulatedUgv& operator=(const SimulatedUgv&) = delete;

    // Throws std::runtime_error when the sockets cannot be opened.
    void start();
    void stop();
    bool running() const;
    std::uint16_t localPort() const;    // unicast port actually bound
    std::uint16_t localTcpPort() const; // JTCP server port (network.jtcpServer), else 0
    const SimulatedUgvConfig& config() const;

    // Thread-safe fault injection (AEP-4818 §10 item 24).
    void setDropHeartbeat(bool on);
    void setHeartbeatRate(double hz);
    void setPacketLoss(double probability);
    void setPacketDelay(int milliseconds);
    void setReorder(bool on);
    void setRejectControl(bool on);
    void setRejectEvents(bool on);
    void setEventRateScale(double scale);
    void setLoseDiscovery(bool on);
    void preemptControl(std::uint8_t authority = 255);
    void forceDriveTimeout();
    void enterEmergency();
    void enterFailure();
    void clearFailure();

    // Every message payload the UGV receives, on its io thread, before it is handled (benchmarks measure
    // command latency on the wire with it). Empty function removes the tap.
    using MessageTap = std::function<void(ByteSpan payload)>;
    void setMessageTap(MessageTap tap);

    // Blocking snapshot of the simulated state (tests, demo).
    UgvState state() const;
    jaus::GlobalPose globalPose() const;
    Counters& counters();

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace ocu::sim
