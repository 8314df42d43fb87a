#pragma once
// `ocu --replay FILE` (docs/recording.md): the console's models and views driven from a
// flight recording, with no protocol stack and every command disabled; or, headless, the JSON lines of the
// run; or an export of a time window (JSON lines, CSV, a slice as a new recording).
#include "app/CommandLine.h"

class QApplication;

namespace ocu {

class MainWindow;
namespace recording {
class ReplayController;
}

// Returns the process exit code (2: the file is not a recording or an option is wrong).
int runReplay(QApplication& app, const CommandLineOptions& options);

// Fills `window` for a replay driven by `controller`: the REPLAY banner, the timeline (bottom tool bar) with
// its keys, the fleet list, 2D map, 3D view and event log; STOP ALL and every command panel disabled.
void populateReplayWindow(MainWindow& window, recording::ReplayController* controller);

} // namespace ocu
