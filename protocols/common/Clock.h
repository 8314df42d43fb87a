#pragma once
// Time source for protocol state machines. Production code uses SteadyClock; tests drive FakeClock
// so timeouts are checked without sleeping.
#include <atomic>
#include <chrono>
#include <cstdint>

namespace ocu {

using Duration = std::chrono::steady_clock::duration;
using TimePoint = std::chrono::steady_clock::time_point;
using std::chrono::milliseconds;
using std::chrono::seconds;

class Clock {
public:
    virtual ~Clock() = default;
    virtual TimePoint now() const = 0;
};

class SteadyClock final : public Clock {
public:
    TimePoint now() const override { return std::chrono::steady_clock::now(); }
    static SteadyClock& instance() {
        static SteadyClock c;
        return c;
    }
};

class FakeClock final : public Clock {
public:
    explicit FakeClock(TimePoint start = TimePoint{} + std::chrono::hours(1))
        : m_now(start.time_since_epoch().count()) {}
    TimePoint now() const override { return TimePoint(Duration(m_now.load())); }
    void advance(Duration d) { m_now += d.count(); }
    void set(TimePoint t) { m_now = t.time_since_epoch().count(); }

private:
    std::atomic<Duration::rep> m_now;
};

// Wall-clock time in milliseconds since the Unix epoch (for timestamps on the wire and in logs).
inline std::int64_t unixMillisNow() {
    return std::chrono::duration_cast<std::chrono::milliseconds>(
               std::chrono::system_clock::now().time_since_epoch())
        .count();
}

} // namespace ocu
