#pragma once
// Scheduling priority for the threads on the stop path: the protocol stacks' io threads and
// the headless monitor's stdin reader. On a loaded machine their wake-up latency, not their work, decides how
// soon a STOP ALL is on the wire, so they ask the OS to run them ahead of ordinary threads:
//   1. SCHED_RR (real-time round robin) at a low real-time priority, when permitted (root, CAP_SYS_NICE or
//      RLIMIT_RTPRIO > 0); the kernel's real-time throttling still leaves ordinary threads 5 % of each CPU.
//   2. otherwise nice -10 for this thread (CAP_SYS_NICE or RLIMIT_NICE), otherwise
//   3. unchanged.
// The environment variable OCU_THREAD_PRIORITY selects "rt" (default: 1, else 2), "nice" (2 only) or "off".
// One log line per process says what was obtained; failures are otherwise silent.
// Only a console process asks (enableStopPathPriority() from its main): simulators and tools that share the
// stacks (ocu-sim stands for machines on other hosts) keep ordinary priority.
#include <string>

namespace ocu {

enum class ThreadPriorityResult { RealTime, Nice, Unchanged };

// Process-wide switch, off by default: the console's main turns it on before starting its stacks.
void enableStopPathPriority(bool on = true);
bool stopPathPriorityEnabled();

// Raises the calling thread's priority as above; `who` names the thread in the log line.
ThreadPriorityResult raiseThreadPriority(const std::string& who);

// While it lives, the calling thread (the GUI thread issuing a STOP ALL) runs SCHED_RR at the io threads'
// priority, when the process enabled the stop-path priority and the OS permits: the io threads, woken by the
// stop or busy with telemetry, cannot take its core between two protocols' sends. Restores the thread's
// previous policy; costs two system calls. Silent when refused.
class ScopedStopPathBoost {
public:
    ScopedStopPathBoost();
    ~ScopedStopPathBoost();
    ScopedStopPathBoost(const ScopedStopPathBoost&) = delete;
    ScopedStopPathBoost& operator=(const ScopedStopPathBoost&) = delete;

private:
    bool m_boosted = false;
    int m_policy = 0;
    int m_priority = 0;
};

} // namespace ocu
