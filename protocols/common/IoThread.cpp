#include "protocols/common/IoThread.h"

#include "protocols/common/Log.h"
#include "protocols/common/ThreadPriority.h"

#include <exception>
#include <pthread.h>

namespace ocu {

static std::int64_t steadyNowNs() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

IoThread::IoThread(std::string name, bool stopPath) : m_name(std::move(name)), m_stopPath(stopPath) {}

IoThread::~IoThread() {
    stop();
}

void IoThread::start() {
    if (running())
        return;
    m_context.restart();
    m_work.emplace(boost::asio::make_work_guard(m_context));
    m_lastTurnNs = steadyNowNs();
    beat(); // expires_after() also cancels a wait left over from a previous run
    m_thread = std::thread([this] {
        pthread_setname_np(pthread_self(), m_name.substr(0, 15).c_str());
        // Commands (a STOP ALL above all) wait for this thread to wake up: ahead of ordinary threads where
        // the OS permits (ThreadPriority.h).
        if (m_stopPath && stopPathPriorityEnabled())
            raiseThreadPriority("io thread " + m_name);
        for (;;) {
            try {
                m_context.run();
                return;
            } catch (const std::exception& e) {
                // A handler must never take the stack down; log and keep serving.
                logError("ocu.io", m_name + ": handler threw: " + e.what());
            }
        }
    });
}

void IoThread::beat() {
    m_heartbeat.expires_after(kHeartbeat);
    m_heartbeat.async_wait([this](boost::system::error_code ec) {
        if (ec)
            return;
        m_lastTurnNs = steadyNowNs();
        beat();
    });
}

std::chrono::milliseconds IoThread::sinceLastTurn() const {
    const std::int64_t last = m_lastTurnNs.load();
    if (last == 0)
        return std::chrono::milliseconds(0);
    return std::chrono::duration_cast<std::chrono::milliseconds>(
        std::chrono::nanoseconds(steadyNowNs() - last));
}

void IoThread::stop() {
    if (!m_thread.joinable())
        return;
    m_lastTurnNs = 0;
    m_work.reset();
    m_context.stop();
    if (onThread())
        m_thread.detach();
    else
        m_thread.join();
}

} // namespace ocu
