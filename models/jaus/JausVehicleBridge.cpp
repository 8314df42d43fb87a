#include "models/jaus/JausVehicleBridge.h"

namespace ocu {

JausVehicleBridge::JausVehicleBridge(QObject* parent) : FleetBridge(Protocol::Jaus, parent) {
    qRegisterMetaType<ocu::JausVehicle>();
    qRegisterMetaType<ocu::JausVehicleEvent>();
}

JausVehicleBridge::~JausVehicleBridge() = default;

CommandResult JausVehicleBridge::panTilt(quint16, quint16, double, double) {
    return CommandResult::failure(tr("pan-tilt: this vehicle link drives no pan-tilt; nothing sent"));
}

QString JausVehicleBridge::machineId(quint16 subsystem) {
    return protocolPrefix(Protocol::Jaus) + QString::number(subsystem);
}

std::optional<quint16> JausVehicleBridge::subsystemOf(const QString& machineId) {
    const QString prefix = protocolPrefix(Protocol::Jaus);
    if (!machineId.startsWith(prefix))
        return std::nullopt;
    bool ok = false;
    const uint v = machineId.mid(prefix.size()).toUInt(&ok);
    if (!ok || v == 0 || v > 65534)
        return std::nullopt;
    return static_cast<quint16>(v);
}

} // namespace ocu
