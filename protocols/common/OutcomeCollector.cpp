#include "protocols/common/OutcomeCollector.h"

#include <atomic>
#include <iterator>

namespace ocu {

std::shared_ptr<OutcomeCollector> OutcomeCollector::create(int expected, OutcomeCallback done) {
    std::shared_ptr<OutcomeCollector> c(new OutcomeCollector(expected, std::move(done)));
    if (expected <= 0) {
        c->m_missing = 1;
        c->add({});
    }
    return c;
}

OutcomeCallback OutcomeCollector::part() {
    auto answered = std::make_shared<std::atomic<bool>>(false);
    return [self = shared_from_this(), answered](std::vector<TargetOutcome> o) {
        if (!answered->exchange(true))
            self->add(std::move(o));
    };
}

void OutcomeCollector::add(std::vector<TargetOutcome> outcomes) {
    std::unique_lock lock(m_mutex);
    if (m_missing <= 0)
        return;
    m_out.insert(m_out.end(), std::make_move_iterator(outcomes.begin()),
                 std::make_move_iterator(outcomes.end()));
    if (--m_missing > 0)
        return;
    auto all = std::move(m_out);
    auto done = std::move(m_done);
    lock.unlock();
    done(std::move(all));
}

} // namespace ocu
