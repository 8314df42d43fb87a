#pragma once
// Pure mapping of the JAUS stack's reports to the Qt side: a subsystem snapshot becomes the panels'
// JausVehicle and a JAUS event their JausVehicleEvent (JausBridge::toMachine, in JausBridgeRows.cpp, makes
// the fleet row). No state, no threads: any thread may call them.
#include "models/jaus/JausVehicleBridge.h"

#include "protocols/jaus/JausTypes.h"

namespace ocu::jausrow {

JausAddress toAddress(const jaus::JausId& id);
JausVehicle toVehicle(const jaus::SubsystemSnapshot& s);
JausVehicleEvent toVehicleEvent(const jaus::JausEvent& e);
// The mission as the stack knows it, in the models' types (state from the vehicle's reports).
JausMission toMission(const jaus::MissionStatus& m);
// Platform mode and state, lights, odometer, the comms-lost service (from the vehicle's reports).
JausPlatformServices toPlatformServices(const jaus::PlatformServicesStatus& p);
// Hand-off between consoles (prompt stamps still on the wall clock: the bridge moves them to the models').
JausHandoff toHandoff(const jaus::HandoffStatus& h);

} // namespace ocu::jausrow
