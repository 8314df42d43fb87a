#pragma once
// Waiting for a state of a test's own io_context: runs it in 10 ms slices until the predicate holds, so a
// test waits for what it checks and never for a fixed time; the bound only ends a test that would never get
// there.
#include <boost/asio/io_context.hpp>

#include <chrono>

namespace ocu::testing {

template <class Pred> bool runUntil(boost::asio::io_context& io, Pred p, int ms = 20000) {
    for (int i = 0; i < ms / 10; ++i) {
        if (p())
            return true;
        io.restart();
        io.run_for(std::chrono::milliseconds(10));
    }
    return p();
}

} // namespace ocu::testing
