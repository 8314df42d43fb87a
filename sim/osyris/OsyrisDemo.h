#pragma once
// A simulated OSYRIS site on real loopback multicast: a paver, tandem rollers and a relay box, each an
// OsyrisStack on 127.0.0.1 with a free port, driven in accelerated time. ocuConfig() gives the OCU the
// settings to join them (used by the built-in demo site and ocu-sim).
#include "protocols/osyris/OsyrisStack.h"
#include "sim/osyris/SimulatedRoller.h"

#include <memory>
#include <string>
#include <vector>

namespace ocu::sim::osyris {

struct OsyrisDemoOptions {
    int rollers = 3; // 0-3 tandem rollers
    bool paver = true;
    bool relay = true;              // a relay-only station (Active 7, no machine)
    double speedUp = 10;            // simulated seconds per real second
    double positionPeriodS = 0.5;   // simulated seconds between positions of one machine
    double crewMessageEveryS = 600; // simulated seconds between a driver's own reports (0 = never)
    // A long paving job (several lifts) instead of the straight test road; the paver starts at
    // station 0 and the positions come at most 40 per real second per machine whatever the speed-up.
    std::shared_ptr<const PavingJob> pavingJob;
    std::string group = "233.1.1.1";
    std::uint16_t port = 0; // 0 = a free port
    std::string interfaceAddress = "127.0.0.1";
    int beatMs = 100;
    ocu::osyris::Checksum checksum = ocu::osyris::Checksum::None;
    std::uint8_t ocuIndex = 200;
    ocu::osyris::RxImpairment impairment; // applied at every simulated station (loss/dup/reorder)
};

struct DemoMachine {
    std::uint8_t idx = 0;
    std::string name;
    MachineKind kind = MachineKind::Roller;
};

class OsyrisDemo {
public:
    explicit OsyrisDemo(OsyrisDemoOptions opts = {});
    ~OsyrisDemo();
    OsyrisDemo(const OsyrisDemo&) = delete;
    OsyrisDemo& operator=(const OsyrisDemo&) = delete;

    bool start(std::string* error = nullptr);
    const OsyrisDemoOptions& options() const { return m_opts; }
    void stop();
    // Configuration for the OCU's own station (group, port, interface, index, Beat, checksum).
    ocu::osyris::OsyrisConfig ocuConfig() const;
    const std::vector<DemoMachine>& machines() const { return m_machines; }
    std::size_t stationCount() const;
    ocu::osyris::OsyrisStack& station(std::size_t i);
    double simTime() const;
    // Parked machines stop writing positions (stations keep running, answering and relaying).
    void setPaused(bool paused);
    void setImpairment(const ocu::osyris::RxImpairment& imp); // at every simulated station
    // Messages from the console station i's driver got (and acknowledged to the console).
    int crewMessagesReceived(std::size_t station) const;

private:
    struct Impl;
    OsyrisDemoOptions m_opts;
    std::vector<DemoMachine> m_machines;
    std::unique_ptr<Impl> m_impl;
};

} // namespace ocu::sim::osyris
