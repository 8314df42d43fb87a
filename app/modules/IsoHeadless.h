#pragma once
// The ISO 23725 module's headless part: the dispatch commands and queries it adds to the headless monitor's
// table (app/HeadlessCommands.h).
//   {"cmd":"assign","id":"iso23725:<guid>","tasks":[{"task":"Load","destination":4201,"route":[2001]},..]}
//   (or one task's keys at the top level; the result echoes "tasks" with their "assignment_id")
//   {"cmd":"reset_assignment","id":"iso23725:<guid>"}
//     through the gate to the bridge owning "id" (audited; the truck is the target, sent only when the socket
//     took the request)
//   {"cmd":"production"[,"id":..]}: result "trucks", the bridge's dispatch views (what the trucks reported),
//     without touching the wire
//   {"cmd":"auto_dispatch","on":true|false} (without "on": the state): the automatic dispatcher
//     (models/AutoDispatcher.h); result "on", "dispatchers":[{"bridge","on","sent","last"}]
//   {"cmd":"shift_report","pdf":"shift.pdf","csv":"shift.csv","plan_tonnes":30000} (either file may be left
//     out; result "written":{"pdf":true,"csv":true}, "loads", "tonnes", "cycles"; ok only when all were
//     written; app/ShiftReportCommand.h)
// Registered also when the site has no ISO 23725 link: the answers then say so.

namespace ocu {

class AutoDispatcher;
class FleetModel;
class HeadlessCommands;
class IsoBridge;
class ProductionModel;

struct IsoHeadlessParts {
    IsoBridge* bridge = nullptr; // nullptr: the site has no ISO 23725 link
    ProductionModel* production = nullptr;
    AutoDispatcher* dispatcher = nullptr;
    FleetModel* fleet = nullptr; // the machines on the shift report's map
};

void registerIsoHeadless(HeadlessCommands& table, const IsoHeadlessParts& parts);

} // namespace ocu
