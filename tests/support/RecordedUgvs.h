#pragma once
// Test support: a synthetic recording of two UGVs (jaus:100 "UGV-100" and jaus:101 "UGV-101") at 10 Hz, for
// the replay tests. Machine k is at (step * 0.5 + k * 10, k * 5) m at step `step` (5 m/s east).
#include "models/FleetEvent.h"
#include "models/MachineState.h"
#include "models/recording/Recorder.h"

#include <QString>

namespace recordtest {

inline ocu::MachineState ugvAt(int k, int step, qint64 clockMs) {
    ocu::MachineState m;
    m.id = QStringLiteral("jaus:%1").arg(100 + k);
    m.protocol = ocu::Protocol::Jaus;
    m.name = QStringLiteral("UGV-%1").arg(100 + k);
    m.link = ocu::LinkState::Up;
    m.hasPosition = true;
    m.e = step * 0.5 + k * 10;
    m.n = k * 5.0;
    m.lastDataMs = clockMs;
    return m;
}

// An unacknowledged alarm of jaus:100 at clockMs (the timeline's alarm marker).
inline ocu::FleetEvent controlLostAlarm(qint64 clockMs) {
    ocu::FleetEvent ev = ocu::makeEvent(ocu::EventSeverity::Alarm, ocu::EventKind::ControlLost,
                                        QStringLiteral("jaus:100"), QStringLiteral("control lost"));
    ev.timeMs = clockMs;
    return ev;
}

// Steps 0..lastStep, 100 ms apart from t0 (the recorder's clock set to each): both UGVs
// recorded, then each(step) for what else the test records at that step.
template <class Each>
void recordTwoUgvs(ocu::recording::Recorder& rec, ocu::ManualModelClock& clock, qint64 t0, int lastStep,
                   Each&& each) {
    for (int step = 0; step <= lastStep; ++step) {
        clock.set(t0 + step * 100);
        for (int k = 0; k < 2; ++k)
            rec.recordStates({ugvAt(k, step, clock.nowMs())});
        each(step);
    }
}

} // namespace recordtest
