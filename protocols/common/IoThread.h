#pragma once
// One Boost.Asio io_context on its own thread: every protocol stack owns one. Commands enter with post();
// the stack's handlers run only on this thread, so stack state needs no locks.
// Watchdog: a heartbeat timer on the loop stamps an atomic time at every turn; any other thread
// reads how long the loop has not turned (sinceLastTurn) and can tell a stuck handler from an idle stack.
#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <thread>

namespace ocu {

class IoThread {
public:
    // stopPath: the thread carries operator commands (a protocol stack's): raised priority when the process
    // enabled it (ThreadPriority.h).
    explicit IoThread(std::string name = "io", bool stopPath = false);
    ~IoThread();
    IoThread(const IoThread&) = delete;
    IoThread& operator=(const IoThread&) = delete;

    void start();
    // Stops the loop and joins; pending handlers are dropped. Safe to call twice.
    void stop();
    bool running() const { return m_thread.joinable(); }
    bool onThread() const { return std::this_thread::get_id() == m_thread.get_id(); }

    // How long since the loop last ran its heartbeat (kHeartbeat apart while it turns); 0 when not running.
    // Any thread.
    std::chrono::milliseconds sinceLastTurn() const;
    static constexpr std::chrono::milliseconds kHeartbeat{100};

    boost::asio::io_context& context() { return m_context; }
    template <class F> void post(F&& f) { boost::asio::post(m_context, std::forward<F>(f)); }
    // Runs f on the io thread and waits for its result. Never call from the GUI thread's hot paths:
    // meant for tests, start-up and shutdown.
    template <class F> auto call(F&& f) -> decltype(f()) {
        if (onThread() || !running())
            return f();
        // Shared: the io thread may still be leaving task() after the caller already has the result.
        auto task = std::make_shared<std::packaged_task<decltype(f())()>>(std::forward<F>(f));
        auto fut = task->get_future();
        boost::asio::post(m_context, [task] { (*task)(); });
        return fut.get();
    }

private:
    std::string m_name;
    bool m_stopPath = false;
    boost::asio::io_context m_context;
    std::optional<boost::asio::executor_work_guard<boost::asio::io_context::executor_type>> m_work;
    boost::asio::steady_timer m_heartbeat{m_context}; // after m_context: destroyed before it
    std::atomic<std::int64_t> m_lastTurnNs{0};        // steady clock; 0 = not running
    std::thread m_thread;
    void beat();
};

} // namespace ocu
