#pragma once
// Test support for the stacks' end-to-end tests (plain threads, no Qt event loop): a generous polling wait
// that ends as soon as its condition holds, a listener that ignores everything, and the outcomes of one
// command delivered on a stack's io thread.
#include "protocols/common/CommandOutcome.h"

#include <chrono>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace stacktest {

// Generous, for a loaded machine: the wait ends when the condition holds, never on the clock alone.
constexpr double kWaitS = 15;

template <class Pred> bool waitFor(Pred p, double seconds = kWaitS) {
    using Clk = std::chrono::steady_clock;
    const auto end =
        Clk::now() + std::chrono::duration_cast<Clk::duration>(std::chrono::duration<double>(seconds));
    while (Clk::now() < end) {
        if (p())
            return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return p();
}

// The outcomes of one command, delivered on the stack's io thread.
struct Outcomes {
    std::mutex mutex;
    std::optional<std::vector<ocu::TargetOutcome>> value;
    ocu::OutcomeCallback callback() {
        return [this](std::vector<ocu::TargetOutcome> v) {
            std::lock_guard lock(mutex);
            value = std::move(v);
        };
    }
    std::optional<std::vector<ocu::TargetOutcome>> get() {
        waitFor([&] {
            std::lock_guard lock(mutex);
            return value.has_value();
        });
        std::lock_guard lock(mutex);
        return value;
    }
};

} // namespace stacktest
