#pragma once
// One command sent to several targets (or through several stack calls) answers once: the collector counts
// the answers it expects, gathers their outcomes from any thread and calls `done` exactly once, with every
// outcome, when the last expected answer is in.
#include "protocols/common/CommandOutcome.h"

#include <memory>
#include <mutex>
#include <vector>

namespace ocu {

class OutcomeCollector : public std::enable_shared_from_this<OutcomeCollector> {
public:
    // `expected` answers (each part() below is one); none expected: `done` runs at once with no outcome.
    static std::shared_ptr<OutcomeCollector> create(int expected, OutcomeCallback done);

    // The callback for one expected answer. A part answering twice counts once (the first).
    OutcomeCallback part();
    // One answer (any thread); the last expected one calls `done`, on this thread. Answers beyond the
    // expected count are ignored.
    void add(std::vector<TargetOutcome> outcomes);

private:
    OutcomeCollector(int expected, OutcomeCallback done) : m_missing(expected), m_done(std::move(done)) {}

    std::mutex m_mutex;
    std::vector<TargetOutcome> m_out;
    int m_missing;
    OutcomeCallback m_done;
};

} // namespace ocu
