#include "protocols/common/ThreadPriority.h"

#include "protocols/common/Log.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>

#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace ocu {

namespace {

#ifndef SCHED_RESET_ON_FORK
#define SCHED_RESET_ON_FORK 0x40000000
#endif

constexpr int kRealTimePriority = 10; // low among real-time priorities: kernel threads (50) stay ahead
constexpr int kNice = -10;

std::atomic<bool> g_logged{false};
std::atomic<bool> g_enabled{false};

void logOnce(const std::string& text) {
    if (!g_logged.exchange(true))
        logInfo("ocu.priority", text);
}

} // namespace

void enableStopPathPriority(bool on) {
    g_enabled = on;
}

bool stopPathPriorityEnabled() {
    return g_enabled;
}

ScopedStopPathBoost::ScopedStopPathBoost() {
    if (!g_enabled)
        return;
    const char* env = std::getenv("OCU_THREAD_PRIORITY");
    if (env && std::string(env) != "rt")
        return;
    sched_param old{};
    m_policy = ::sched_getscheduler(0);
    if (m_policy < 0 || ::sched_getparam(0, &old) != 0)
        return;
    m_priority = old.sched_priority;
    if ((m_policy & ~SCHED_RESET_ON_FORK) == SCHED_RR || (m_policy & ~SCHED_RESET_ON_FORK) == SCHED_FIFO)
        return; // already real-time (the headless stdin reader)
    sched_param sp{};
    sp.sched_priority = kRealTimePriority;
    rlimit rl{};
    if (::getrlimit(RLIMIT_RTPRIO, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY && rl.rlim_cur > 0)
        sp.sched_priority = std::min<int>(sp.sched_priority, int(rl.rlim_cur));
    m_boosted = ::sched_setscheduler(0, SCHED_RR | SCHED_RESET_ON_FORK, &sp) == 0;
}

ScopedStopPathBoost::~ScopedStopPathBoost() {
    if (!m_boosted)
        return;
    sched_param sp{};
    sp.sched_priority = m_priority;
    ::sched_setscheduler(0, m_policy, &sp);
}

ThreadPriorityResult raiseThreadPriority(const std::string& who) {
    const char* env = std::getenv("OCU_THREAD_PRIORITY");
    const std::string mode = env ? env : "rt";
    if (mode == "off") {
        logOnce("thread priority unchanged (OCU_THREAD_PRIORITY=off)");
        return ThreadPriorityResult::Unchanged;
    }
    std::string rtWhy;
    if (mode != "nice") {
        // RLIMIT_RTPRIO bounds the priority an unprivileged thread may take; root/CAP_SYS_NICE are not bound.
        rlimit rl{};
        int prio = kRealTimePriority;
        if (::getrlimit(RLIMIT_RTPRIO, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY && rl.rlim_cur > 0)
            prio = std::min<int>(prio, int(rl.rlim_cur));
        sched_param sp{};
        sp.sched_priority = prio;
        // pid 0: the calling thread. Reset on fork: children (e.g. a spawned helper) start ordinary.
        if (::sched_setscheduler(0, SCHED_RR | SCHED_RESET_ON_FORK, &sp) == 0) {
            logOnce(who + " and the other stop-path threads run SCHED_RR priority " + std::to_string(prio));
            return ThreadPriorityResult::RealTime;
        }
        rtWhy = std::strerror(errno);
    }
    // setpriority on a thread id affects that thread only (Linux).
    const auto tid = static_cast<id_t>(::syscall(SYS_gettid));
    if (::setpriority(PRIO_PROCESS, tid, kNice) == 0) {
        logOnce(who + " and the other stop-path threads run at nice " + std::to_string(kNice) +
                (rtWhy.empty() ? std::string() : " (SCHED_RR refused: " + rtWhy + ")"));
        return ThreadPriorityResult::Nice;
    }
    logOnce("stop-path threads keep the default priority (SCHED_RR and nice " + std::to_string(kNice) +
            " refused: " + std::strerror(errno) + "; grant CAP_SYS_NICE or RLIMIT_RTPRIO to raise them)");
    return ThreadPriorityResult::Unchanged;
}

} // namespace ocu
