#include "models/video/VideoWatchdog.h"

#include <QCoreApplication>

namespace ocu {

VideoWatchdog::VideoWatchdog(std::shared_ptr<const ModelClock> clock)
    : m_clock(clockOrSystem(std::move(clock))) {}

void VideoWatchdog::setLimitMs(int ms) {
    m_limitMs = std::max(50, ms);
}

void VideoWatchdog::setRequired(bool required) {
    if (required == m_required)
        return;
    m_required = required;
    if (!required) {
        m_tripped = false;
        m_hadGood = false;
    }
}

void VideoWatchdog::setStream(VideoState state, std::optional<std::int64_t> frameTimeMs) {
    m_state = state;
    m_frameTimeMs = frameTimeMs;
}

bool VideoWatchdog::check() {
    m_ageMs.reset();
    if (m_frameTimeMs)
        m_ageMs = std::max<std::int64_t>(0, m_clock->nowMs() - *m_frameTimeMs);
    m_good = m_state == VideoState::Playing && m_ageMs && *m_ageMs <= m_limitMs;
    if (!m_required)
        return true;
    if (m_good) {
        m_hadGood = true;
    } else if (m_hadGood && !m_tripped) {
        m_tripped = true;
        m_tripReason =
            m_state != VideoState::Playing
                ? QCoreApplication::translate("ocu::VideoWatchdog", "video %1").arg(videoStateText(m_state))
                : QCoreApplication::translate("ocu::VideoWatchdog", "video frame %1 ms old (limit %2 ms)")
                      .arg(m_ageMs.value_or(-1))
                      .arg(m_limitMs);
    }
    return allowsDriving();
}

QString VideoWatchdog::reason() const {
    if (!m_required)
        return {};
    if (m_tripped)
        return m_good
                   ? QCoreApplication::translate(
                         "ocu::VideoWatchdog",
                         "VIDEO WATCHDOG stopped driving (%1); video is back: press Resume driving")
                         .arg(m_tripReason)
                   : QCoreApplication::translate("ocu::VideoWatchdog", "VIDEO WATCHDOG stopped driving: %1")
                         .arg(m_tripReason);
    if (!m_good)
        return QCoreApplication::translate("ocu::VideoWatchdog", "Driving waits for video (%1)")
            .arg(videoStateText(m_state));
    return {};
}

bool VideoWatchdog::resume() {
    check();
    if (m_tripped && m_good)
        m_tripped = false;
    return allowsDriving();
}

void VideoWatchdog::reset() {
    m_tripped = false;
    m_tripReason.clear();
    restartStream();
}

void VideoWatchdog::restartStream() {
    m_hadGood = false;
    m_frameTimeMs.reset();
    m_ageMs.reset();
    m_state = VideoState::Idle;
    m_good = false;
}

} // namespace ocu
