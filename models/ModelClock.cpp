#include "models/ModelClock.h"

#include <chrono>

namespace ocu {

ModelClock::~ModelClock() = default;

namespace {

qint64 wallUs() {
    using namespace std::chrono;
    return duration_cast<microseconds>(system_clock::now().time_since_epoch()).count();
}

// Wall time at construction plus steady time since: see systemModelClock().
class SystemModelClock final : public ModelClock {
public:
    SystemModelClock() : m_anchorWallUs(wallUs()), m_anchorSteady(std::chrono::steady_clock::now()) {}
    qint64 nowMs() const override { return nowUs() / 1000; }
    qint64 nowUs() const override {
        using namespace std::chrono;
        return m_anchorWallUs + duration_cast<microseconds>(steady_clock::now() - m_anchorSteady).count();
    }

private:
    const qint64 m_anchorWallUs;
    const std::chrono::steady_clock::time_point m_anchorSteady;
};

} // namespace

std::shared_ptr<const ModelClock> systemModelClock() {
    static const std::shared_ptr<const ModelClock> clock = std::make_shared<SystemModelClock>();
    return clock;
}

qint64 wallStampToModelMs(const ModelClock& clock, qint64 wallMs) {
    if (wallMs <= 0)
        return wallMs;
    return clock.nowMs() - (wallUs() / 1000 - wallMs);
}

qint64 wallStampToModelUs(const ModelClock& clock, qint64 wallUsStamp) {
    if (wallUsStamp <= 0)
        return wallUsStamp;
    return clock.nowUs() - (wallUs() - wallUsStamp);
}

} // namespace ocu
