#pragma once
// The video watchdog of teleoperation (AEP-4818 lists video loss among the watchdog
// contingencies): while a vehicle with cameras is driven, its video must be playing and the current frame
// younger than a limit (default 1 s). When that stops holding the watchdog trips: the drive stream goes to
// zero at once and stays there, and driving resumes only when the operator deliberately asks (resume()) once
// the video is back, never by itself. Before the first good frame of a stream (a vehicle just selected, a
// camera just switched) driving waits for the video without latching.
//
// Pure logic on a model clock (models/ModelClock.h), so tests drive it with a manual one.
#include "models/video/VideoPlayer.h"

#include <QString>

#include <cstdint>
#include <memory>
#include <optional>

namespace ocu {

class VideoWatchdog {
public:
    static constexpr int kDefaultLimitMs = 1000;

    // `clock` (null: the system clock) must be the one the frame times given are on: the player's.
    explicit VideoWatchdog(std::shared_ptr<const ModelClock> clock = nullptr);
    void setClock(std::shared_ptr<const ModelClock> clock) { m_clock = clockOrSystem(std::move(clock)); }

    void setLimitMs(int ms);
    int limitMs() const { return m_limitMs; }
    // Whether the vehicle has video at all (no camera: nothing to watch, driving is not held).
    void setRequired(bool required);
    bool required() const { return m_required; }

    // The stream's state and the time of its current frame (capture time when known, else arrival), ms.
    void setStream(VideoState state, std::optional<std::int64_t> frameTimeMs);

    // Evaluates now; returns whether driving is allowed. Trips (latches) when good video went bad.
    bool check();
    bool allowsDriving() const { return !m_tripped && (!m_required || m_good); }
    bool tripped() const { return m_tripped; }
    bool videoGood() const { return m_good; }
    // Why driving is held (translated), empty when it is not.
    QString reason() const;
    // The current frame's age (ms) at the last check, nullopt without a frame.
    std::optional<std::int64_t> frameAgeMs() const { return m_ageMs; }

    // The operator's deliberate resume: clears the trip only while the video is good. Returns whether
    // driving is allowed now.
    bool resume();
    // Another vehicle (a new drive session): forget the trip, wait for the first frame.
    void reset();
    // The same vehicle's stream starts over (another camera, the panel shown again): wait for its first frame
    // without latching a trip on the way, but keep a trip that is already there (only resume() clears it).
    void restartStream();

private:
    std::shared_ptr<const ModelClock> m_clock;
    int m_limitMs = kDefaultLimitMs;
    bool m_required = false;
    VideoState m_state = VideoState::Idle;
    std::optional<std::int64_t> m_frameTimeMs;
    std::optional<std::int64_t> m_ageMs;
    bool m_good = false;
    bool m_hadGood = false; // since reset()
    bool m_tripped = false;
    QString m_tripReason;
};

} // namespace ocu
