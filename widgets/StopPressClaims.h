#pragma once
// One press, one STOP ALL: a press of the STOP ALL button can be seen twice, by the X11 watcher's thread and
// by the button on the GUI thread. Both claim it by its X server time; the first claim acts, the second not.

#include <algorithm>
#include <deque>
#include <mutex>

namespace ocu {

class StopPressClaims {
public:
    // True for the first claim of this press time (any thread).
    bool claim(unsigned long serverTimeMs) {
        std::lock_guard lock(m_mutex);
        if (std::find(m_times.begin(), m_times.end(), serverTimeMs) != m_times.end())
            return false;
        m_times.push_back(serverTimeMs);
        if (m_times.size() > 32)
            m_times.pop_front();
        return true;
    }

private:
    std::mutex m_mutex;
    std::deque<unsigned long> m_times;
};

} // namespace ocu
