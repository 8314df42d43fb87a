#pragma once
// The timing rules of an ISO 23725 WebSocket link, kept apart from the sockets so they run on a fake clock in
// tests. Research note §2 [I] / Q1: ping every 5 s, the link is dead after 15 s without any received frame
// (pongs count), reconnect with exponential backoff 1 -> 30 s with +-20 % jitter.
#include "protocols/common/Clock.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <random>

namespace ocu::iso23725 {

class KeepAlive {
public:
    enum class Action { None, SendPing, Dead };

    KeepAlive(Duration pingInterval, Duration deadAfter)
        : m_pingInterval(pingInterval), m_deadAfter(deadAfter) {}

    void start(TimePoint now) {
        m_lastRx = now;
        m_nextPing = now + m_pingInterval;
    }
    // Any frame, control frames included, proves the peer alive.
    void received(TimePoint now) { m_lastRx = now; }

    // Called at (or after) deadline(); says what is due now. Dead wins over a due ping.
    Action poll(TimePoint now) {
        if (now - m_lastRx >= m_deadAfter)
            return Action::Dead;
        if (now >= m_nextPing) {
            // Pings keep their own cadence; a late poll does not send a burst of pings.
            while (m_nextPing <= now)
                m_nextPing += m_pingInterval;
            return Action::SendPing;
        }
        return Action::None;
    }
    TimePoint deadline() const { return std::min(m_nextPing, m_lastRx + m_deadAfter); }
    Duration silentFor(TimePoint now) const { return now - m_lastRx; }

private:
    Duration m_pingInterval;
    Duration m_deadAfter;
    TimePoint m_lastRx{};
    TimePoint m_nextPing{};
};

class ReconnectBackoff {
public:
    ReconnectBackoff(std::chrono::milliseconds min, std::chrono::milliseconds max, double jitter,
                     std::uint32_t seed = std::random_device{}())
        : m_min(min), m_max(max), m_jitter(std::clamp(jitter, 0.0, 0.9)), m_rng(seed) {}

    // Delay before the next attempt: min * 2^n capped at max, then +-jitter so a fleet of consoles does not
    // reconnect in lockstep after an AHS restart.
    std::chrono::milliseconds next() {
        double base = static_cast<double>(m_min.count()) * std::pow(2.0, std::min(m_attempt, 30));
        base = std::min(base, static_cast<double>(m_max.count()));
        std::uniform_real_distribution<double> j(-m_jitter, m_jitter);
        ++m_attempt;
        return std::chrono::milliseconds(static_cast<std::int64_t>(std::llround(base * (1.0 + j(m_rng)))));
    }
    void reset() { m_attempt = 0; }
    int attempts() const { return m_attempt; }

private:
    std::chrono::milliseconds m_min;
    std::chrono::milliseconds m_max;
    double m_jitter;
    int m_attempt = 0;
    std::mt19937 m_rng;
};

} // namespace ocu::iso23725
