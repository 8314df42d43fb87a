#pragma once
// The one time source of the Qt models: every age, staleness, timeout and expiry the models decide is
// measured on a ModelClock, so a test moves time by hand and a replay moves it with its cursor. Times are
// milliseconds since the Unix epoch, like the stamps the models keep. Protocol code has its own Clock
// (protocols/common/Clock.h); plain display stamps may read the wall clock.
#include <QtGlobal>

#include <atomic>
#include <memory>

namespace ocu {

class ModelClock {
public:
    virtual ~ModelClock();
    virtual qint64 nowMs() const = 0;
    // The same time in microseconds (video frame ages); a clock without a finer tick gives nowMs() * 1000.
    virtual qint64 nowUs() const { return nowMs() * 1000; }
};

// The default of every model: read the wall clock once, at first use, then advance with the steady clock.
// A stepped system clock (NTP, an operator setting the time) then neither expires a token or a shelved alarm
// early nor makes stale data fresh again: only real elapsed time moves it. Thread-safe, one per process.
std::shared_ptr<const ModelClock> systemModelClock();

// `clock`, or the system clock when it is null (what every setClock() accepts).
inline std::shared_ptr<const ModelClock> clockOrSystem(std::shared_ptr<const ModelClock> clock) {
    return clock ? std::move(clock) : systemModelClock();
}

// A stamp taken on the wall clock (a protocol stack's receive time, a camera's time code) on the model clock:
// its age on the wall clock, counted back from the model clock's now. The age is measured like with like, so
// a wall-clock step after the stamp was taken does not carry over into the model's ages. 0 and negative
// stamps ("never") stay as they are.
qint64 wallStampToModelMs(const ModelClock& clock, qint64 wallMs);
qint64 wallStampToModelUs(const ModelClock& clock, qint64 wallUs);

// A clock set by hand: tests, and the replay (its cursor). Any thread may read it.
class ManualModelClock final : public ModelClock {
public:
    explicit ManualModelClock(qint64 startMs = 0) : m_nowMs(startMs) {}
    qint64 nowMs() const override { return m_nowMs.load(std::memory_order_relaxed); }
    void set(qint64 ms) { m_nowMs.store(ms, std::memory_order_relaxed); }
    void advance(qint64 ms) { m_nowMs.fetch_add(ms, std::memory_order_relaxed); }

private:
    std::atomic<qint64> m_nowMs;
};

} // namespace ocu
