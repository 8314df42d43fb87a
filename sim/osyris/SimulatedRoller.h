#pragma once
// Simulated OSYRIS machines: a paver advancing at paver pace along a straight road section
// (+x = east, lane centre y = 0) and tandem rollers doing forward/backward passes in a window behind it,
// with vibration switched on and off, accuracy flags and an occasional GPS shadow. Pure functions of the
// simulated time, so runs are reproducible.
#include "protocols/osyris/OsyrisCodec.h"
#include "sim/osyris/PavingJob.h"

#include <memory>

#include <cstdint>
#include <optional>
#include <string>

namespace ocu::sim::osyris {

enum class MachineKind { Paver, Roller, Relay };

struct MachineSpec {
    MachineKind kind = MachineKind::Roller;
    std::string name = "Roller";
    double width = 2.1;                    // m, drum width (1.7-2.1 for tandem rollers) or paving width
    double laneOffset = 0;                 // m, y of the lane centre
    double speed = 1.2;                    // m/s roller working speed
    double paverSpeed = 2.0 / 60;          // m/s (~2 m/min)
    double paverStartX = 40;               // m
    double gapBehindPaver = 5;             // m between paver screed and the roller window
    double passLength = 30;                // m, length of one forward/backward pass
    double phase = 0;                      // m, offset along the pass cycle
    int vibrationOffEvery = 4;             // every n-th pass static (0 = always vibrating)
    double shadowFromX = 0, shadowToX = 0; // GPS shadow (e.g. under a bridge) when from < to
    double mediumAccuracyRate = 0.05;      // share of positions flagged medium instead of high
    // Relay: moves back and forth between (x0,y0) and (x1,y1) at speed (speed 0 = static at x0,y0)
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    std::uint32_t seed = 1;
    // Crew messages: the driver reports every this many simulated seconds (0 = never).
    double crewMessageEveryS = 600;
    // Drive a long job instead of the straight test road: the straight-road pose (x along,
    // y lateral) is laid onto the job's centre line, lift after lift (z rises by the lift thickness).
    std::shared_ptr<const PavingJob> job;
};

class SimulatedMachine {
public:
    explicit SimulatedMachine(MachineSpec spec) : m_spec(std::move(spec)) {}
    const MachineSpec& spec() const { return m_spec; }
    // Pose at t seconds of simulated time (slot is assigned by the station).
    ocu::osyris::CmPos poseAt(double t, std::int64_t unixMs = 0) const;
    double paverX(double t) const { return m_spec.paverStartX + m_spec.paverSpeed * t; }
    // What the driver reports between simulated times t0 (exclusive) and t1 (inclusive), if anything
    // ("Roller 1: rolled up to x=62 m"); at most 79 bytes (one CmMsg).
    std::optional<std::string> crewMessage(double t0, double t1) const;
    // The driver's answer to a message from the console.
    std::string crewReply(const std::string& received) const;

private:
    MachineSpec m_spec;
};

// The roller the issue names ("SimulatedRoller.h"): a machine with roller defaults.
inline MachineSpec rollerSpec(std::string name, double laneOffset, double width, double phase,
                              std::uint32_t seed) {
    MachineSpec s;
    s.kind = MachineKind::Roller;
    s.name = std::move(name);
    s.laneOffset = laneOffset;
    s.width = width;
    s.phase = phase;
    s.seed = seed;
    return s;
}
inline MachineSpec paverSpec() {
    MachineSpec s;
    s.kind = MachineKind::Paver;
    s.name = "Paver";
    s.width = 4.5;
    s.vibrationOffEvery = 0;
    return s;
}
inline MachineSpec relaySpec(std::string name, double x0, double y0, double x1, double y1, double speed) {
    MachineSpec s;
    s.kind = MachineKind::Relay;
    s.name = std::move(name);
    s.x0 = x0;
    s.y0 = y0;
    s.x1 = x1;
    s.y1 = y1;
    s.speed = speed;
    s.width = 0;
    return s;
}

} // namespace ocu::sim::osyris
