#pragma once
// `ocu --replay FILE --headless`: the headless monitor's lines of a recorded run, as the live monitor printed
// them (machine, machine_removed, event lines; the modules' own fields, such as each UGV's mission, from the
// recording), every change (no rate limit), with a {"type":"replay","time":...} line at each step of the
// replay clock. Queries ("list") answer from the replayed state; commands act on nothing (no gate).
#include <QObject>

#include <functional>
#include <memory>
#include <vector>

class QIODevice;

namespace ocu {

class HeadlessMonitor;
class ProtocolModule;
namespace recording {
class ReplayController;
}

class HeadlessReplay : public QObject {
public:
    // `out` (not owned) gets the lines; the controller's fleet and alarms are the replayed ones.
    HeadlessReplay(recording::ReplayController* controller, QIODevice* out, QObject* parent = nullptr);
    ~HeadlessReplay() override;

    HeadlessMonitor& monitor() { return *m_monitor; }
    // The rest of the recording as fast as possible, in steps of `stepMs` of recorded time; `stop` (may be
    // empty) ends it early when it returns true.
    void runToEnd(qint64 stepMs = 100, const std::function<bool()>& stop = {});

private:
    recording::ReplayController* m_controller;
    QIODevice* m_out;
    std::unique_ptr<HeadlessMonitor> m_monitor;
    qint64 m_lastStamp = -1;
};

} // namespace ocu
