// One direction of a faulty network link, as netem would make it: loss, duplication, reordering, delay with
// jitter, a rate limit with a bounded queue, and partitions. Pure decisions on given time points and a seeded
// generator, so a test can check them exactly; fault_proxy moves the frames.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace ocu::tools {

struct FaultProfile {
    double loss = 0;       // probability a frame is dropped
    double duplicate = 0;  // probability a frame that passes is sent twice
    double reorder = 0;    // probability a frame is held back so later ones overtake it
    int reorderMinMs = 10; // how long a reordered frame is held back
    int reorderMaxMs = 50;
    int delayMs = 0;         // one-way delay ...
    int jitterMs = 0;        // ... ± this, uniform (netem's default distribution)
    double rateBitsPerS = 0; // 0: unlimited
    int queueLimitMs = 2000; // rate-limited: a frame that would wait longer than this is dropped (tail drop)
};

// "loss=0.3,dup=0.1,reorder=0.1,delay=300,jitter=100,rate=20000,queue=2000"; empty means no fault.
// Returns the reason of a refusal in `error`.
FaultProfile parseFaultProfile(const std::string& text, std::string& error);

struct FaultCounters {
    std::uint64_t in = 0;          // frames offered
    std::uint64_t sent = 0;        // copies scheduled (duplicates count twice)
    std::uint64_t lost = 0;        // dropped by `loss`
    std::uint64_t partitioned = 0; // dropped while partitioned
    std::uint64_t overflow = 0;    // dropped by the rate limit's queue
    std::uint64_t duplicated = 0;
    std::uint64_t reordered = 0;
};

class FaultLink {
public:
    using Clock = std::chrono::steady_clock;

    FaultLink(FaultProfile profile, std::uint64_t seed);

    // The departure times of the copies of a frame of `bytes` bytes offered at `now`: none (dropped), one or
    // two (duplicated). Times of later frames may be earlier (jitter, reordering): the caller sends by time.
    std::vector<Clock::time_point> offer(std::size_t bytes, Clock::time_point now);

    void setPartitioned(bool on) { m_partitioned = on; }
    bool partitioned() const { return m_partitioned; }
    const FaultCounters& counters() const { return m_counters; }
    const FaultProfile& profile() const { return m_profile; }

private:
    bool chance(double p);
    Clock::duration delayFor();

    FaultProfile m_profile;
    std::mt19937_64 m_random;
    bool m_partitioned = false;
    Clock::time_point m_lineFreeAt{}; // the rate limit: when the line has sent everything queued so far
    FaultCounters m_counters;
};

} // namespace ocu::tools
