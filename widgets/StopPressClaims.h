#pragma once
// One press, one STOP ALL: a press of the STOP ALL button or of a stop key can be seen twice, by the X11
// watcher's thread and by the button or shortcut on the GUI thread. Both claim it by what it was and its X
// server time; the first claim acts, the second not.

#include <algorithm>
#include <deque>
#include <mutex>
#include <utility>

namespace ocu {

// What the operator pressed: two different inputs in the same millisecond are two presses.
enum class StopInput { MouseButton, F12, CtrlShiftSpace };

class StopPressClaims {
public:
    // True for the first claim of this input at this time (any thread).
    bool claim(StopInput input, unsigned long serverTimeMs) {
        const std::pair<StopInput, unsigned long> key{input, serverTimeMs};
        std::lock_guard lock(m_mutex);
        if (std::find(m_claimed.begin(), m_claimed.end(), key) != m_claimed.end())
            return false;
        m_claimed.push_back(key);
        if (m_claimed.size() > 32)
            m_claimed.pop_front();
        return true;
    }

private:
    std::mutex m_mutex;
    std::deque<std::pair<StopInput, unsigned long>> m_claimed;
};

} // namespace ocu
