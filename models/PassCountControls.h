#pragma once
// Lifts and filters of a pass-count source for the pass-count panel: which lift the overlay and
// the statistics show, and what the engine counts (a change makes the engine recount the whole job from the
// ribbons). Qt-side values: widgets never see a protocol's settings type.
#include <QStringList>
#include <QVector>
#include <QtGlobal>

namespace ocu {

struct PassCountFilter {
    enum class Vibration { Any, On, Off };
    enum class Direction { Any, Forward, Backward };
    Vibration vibration = Vibration::On;
    Direction direction = Direction::Any;
    double speedMin = 0, speedMax = 0;   // m/s; 0 = no bound
    qint64 timeFromMs = 0, timeToMs = 0; // Unix ms; 0 = open
    double liftThickness = 0;            // m; 0 = one lift
    double liftBase = 0;                 // m z of the bottom of lift 0
    bool operator==(const PassCountFilter&) const = default;
};

struct PassCountLiftInfo {
    double bottom = 0, top = 0; // m z
};

class PassCountControls {
public:
    virtual ~PassCountControls() = default;
    virtual PassCountFilter passCountFilter() const = 0;
    virtual void setPassCountFilter(const PassCountFilter& filter) = 0;
    // Lifts with data, lowest first (as of the latest counts).
    virtual QVector<PassCountLiftInfo> passCountLifts() const = 0;
    // The lift the layer shows: -1 = the top-most lift with data per cell.
    virtual int viewLift() const = 0;
    virtual void setViewLift(int lift) = 0;
    // What the counts lack: one line per machine with slots given up as unobtainable.
    virtual QStringList passCountGaps() const { return {}; }
};

} // namespace ocu
