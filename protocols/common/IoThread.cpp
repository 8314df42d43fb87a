#include "protocols/common/IoThread.h"

#include "protocols/common/Log.h"
#include "protocols/common/ThreadPriority.h"

#include <exception>
#include <pthread.h>

namespace ocu {

IoThread::IoThread(std::string name, bool stopPath) : m_name(std::move(name)), m_stopPath(stopPath) {}

IoThread::~IoThread() {
    stop();
}

void IoThread::start() {
    if (running())
        return;
    m_context.restart();
    m_work.emplace(boost::asio::make_work_guard(m_context));
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

void IoThread::stop() {
    if (!m_thread.joinable())
        return;
    m_work.reset();
    m_context.stop();
    if (onThread())
        m_thread.detach();
    else
        m_thread.join();
}

} // namespace ocu
