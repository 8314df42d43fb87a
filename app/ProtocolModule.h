#pragma once
// One protocol as the console sees it: its bridge, the panels it adds and fills, the name of its link
// indicator, the headless commands it adds and the capabilities it offers (typed accessors, never a cast or a
// lookup by name). SiteRuntime holds one module per protocol of this build and iterates over them; it names
// no protocol itself. The modules live in app/modules/ (they may include a bridge and its widgets) and are
// listed by CMake in the generated makeProtocolModules(): a protocol left out of the build (OCU_SKIP_DIRS)
// has no module. Map and 3D layers come through the module's bridge (FleetBridge::siteMap, passCountLayer);
// the protocol's simulators are the sim-side modules (sim/SimModule.h).
#include "app/MainWindow.h"
#include "models/MachineState.h"
#include "models/commands/CommandPermissions.h"
#include "protocols/common/GeoFrame.h"
#include "protocols/site/SiteConfig.h"

#include <QList>
#include <QString>
#include <QStringList>

#include <memory>
#include <vector>

namespace ocu {

class FleetBridge;
class HeadlessCommands;
class PassCountPanel;
class ProductionModel;
class MessageTap;
class FleetSelection;
class SiteMapView;
namespace recording {
class ReplayController;
}
class FleetContext;
class ControlRoomModel;
class OwnPosition;
class ProductionModel;

// What a module needs to start its protocol.
struct ModuleStart {
    const SiteConfig& config;
    const GeoFrame& frame;
    FleetContext* fleet;             // the bridge is added to it
    QObject* owner;                  // owns the bridge
    MessageTap* tap = nullptr;       // the flight recorder's tap on inbound messages (nullptr: none)
    QStringList* problems = nullptr; // what else did not start (each becomes an alarm)
    // The operator's role's authority for protocols that command with one (docs/roles.md); -1 when the site
    // manages no roles (the protocol section's own setting stays).
    int roleAuthority = -1;
};

// What a module needs to fill its panels.
struct ModulePanels {
    MainWindow& window; // the main panels are filled (map, 3D) when a module populates
    FleetContext* fleet;
    const SiteConfig& config;
    PassCountPanel* passCounts; // the pass-count panel (its data: the first bridge's pass-count layer)
    // Who is where across the control room (nullptr without the shared history): a panel that names a
    // machine's controller names the person and the console with it.
    ControlRoomModel* controlRoom = nullptr;
};

// What a module needs to fill its panels in a replay (`ocu --replay`): the recording through its controller
// (the replayed fleet, the time), the window's map and the fleet selection. Every panel already says that
// commands are disabled; a module may put a view of the recording in its place.
struct ModuleReplay {
    MainWindow& window;
    recording::ReplayController* controller;
    FleetSelection* selection;
    SiteMapView* map; // nullptr when there is none
    const GeoFrame& frame;
};

// What a module needs in a headless replay (`ocu --replay FILE --headless`): the monitor's command table
// (machine fields and queries answered from the recording) and the recording through its controller.
struct ModuleHeadlessReplay {
    HeadlessCommands& commands;
    recording::ReplayController* controller;
    QObject* owner; // owns what the module creates for it
};

class ProtocolModule {
public:
    virtual ~ProtocolModule() = default;

    // The protocol's name for the operator: its link indicator in the status bar ("JAUS", "ISO 23725", ...).
    virtual QString displayName() const = 0;
    // The protocol of the machines its bridge publishes (data age per protocol).
    virtual Protocol protocol() const = 0;

    // Starts the protocol when the site configuration has its section: creates the bridge, adds it to the
    // fleet context and starts its stack. Returns what went wrong (the bridge stays, its link shows down), or
    // an empty string; does nothing when the site has no section for the protocol.
    virtual QString start(const ModuleStart& start) = 0;
    // Stops the stack (GUI thread; returns when its io thread has ended).
    virtual void stop() = 0;
    // The bridge, or nullptr when the site does not configure the protocol.
    virtual FleetBridge* bridge() const = 0;

    // Once started: the own-position source, for protocols that send the console's own position.
    virtual void attachOwnPosition(OwnPosition* own, const SiteConfig& config) {
        (void)own;
        (void)config;
    }

    // The panels this module adds to the main window when the site runs its protocol (its bridge exists),
    // filled by populate(); on a site without it they appear nowhere. Each declares its PanelKind: the
    // workspaces it appears in (app/WorkspaceLayout.h).
    virtual QList<PanelSpec> panels() const { return {}; }
    virtual void populate(const ModulePanels& ui) { (void)ui; }
    // In a replay: the views of this protocol's own records (none by default: the panels say that commands
    // are disabled).
    virtual void populateReplay(const ModuleReplay& replay) { (void)replay; }
    // In a headless replay: the fields and queries of this protocol's own records (none by default).
    virtual void registerHeadlessReplay(const ModuleHeadlessReplay& replay) { (void)replay; }
    // What STOP ALL does on this protocol, for its tooltip ("JAUS emergency stop to every ...").
    virtual QString stopAllReach() const { return {}; }
    // The protocol for Help › About, with its standards.
    virtual QString aboutName() const { return displayName(); }

    // Once started: the addresses this console's stack commands machines with, as the machines report their
    // controller ("jaus:3.1.1"), published in the control room so that other consoles can name this one.
    virtual QStringList controllerAddresses() const { return {}; }

    // Capabilities. The production (tonnes, loads) of the machines this module's bridge reports, or nullptr.
    virtual ProductionModel* production() const { return nullptr; }

    // The rows of the command gate's permission table for this protocol's commands (which roles may issue
    // each; the stops among them with CommandPermissions::addStop). Called before start, also in builds of
    // tests that start nothing.
    virtual void addPermissions(CommandPermissions& table) const { (void)table; }

    // Once started: the headless monitor's commands and queries this protocol adds (app/HeadlessCommands.h),
    // besides stop and clear_stop, which every bridge answers.
    virtual void registerHeadless(HeadlessCommands& table) { (void)table; }
};

// The modules of this build, in the order of their link indicators (generated by CMake, see
// app/CMakeLists.txt).
std::vector<std::unique_ptr<ProtocolModule>> makeProtocolModules();

} // namespace ocu
