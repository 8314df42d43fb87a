#pragma once
// The JSON of the JAUS platform-service commands (platform_mode, platform_state, lights, odometry), used by
// OperatorCommand.cpp's toJson and parseOperatorCommand:
//   {"cmd":"platform_mode","id":"UGV-126","mode":"training"}   (standard, training, maintenance or 175-255)
//   {"cmd":"platform_state","id":"UGV-126","state":"emergency"} (initialize, operational, shutdown,
//                                                                system_abort, emergency, render_useless)
//   {"cmd":"lights","id":"UGV-126","headlights":true,"left_turn_signal":false} (any of headlights,
//        running_lights, left_turn_signal, right_turn_signal, brake_lights, ir_light; never the vehicle's
//        visible-light source, AEP-4818 §9.2.2)
//   {"cmd":"odometry","id":"UGV-126","reset_trip":true}          (reset_trip optional: read only)
#include "models/commands/OperatorCommand.h"

namespace ocu::platformjson {

QStringList names();
bool isPlatformCommand(const QString& name);
// Adds the command's arguments to `o` (which has "cmd" already).
void addArguments(QJsonObject& o, const SetPlatformMode& c);
void addArguments(QJsonObject& o, const SetPlatformState& c);
void addArguments(QJsonObject& o, const SetLights& c);
void addArguments(QJsonObject& o, const Odometry& c);
ParsedCommand parse(const QString& name, const QJsonObject& json);

} // namespace ocu::platformjson
