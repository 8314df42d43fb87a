#include "models/jaus/JausPlatformServices.h"

namespace ocu {

QString JausPlatformText::modeName(int mode) {
    switch (mode) {
    case int(JausPlatformMode::Standard):
        return tr("standard");
    case int(JausPlatformMode::Training):
        return tr("training");
    case int(JausPlatformMode::Maintenance):
        return tr("maintenance");
    default:
        return tr("program mode %1").arg(mode);
    }
}

QString JausPlatformText::stateName(int state) {
    switch (state) {
    case int(JausPlatformState::Initialize):
        return tr("initialize");
    case int(JausPlatformState::Operational):
        return tr("operational");
    case int(JausPlatformState::Shutdown):
        return tr("shutdown");
    case int(JausPlatformState::SystemAbort):
        return tr("system abort");
    case int(JausPlatformState::Emergency):
        return tr("emergency");
    case int(JausPlatformState::RenderUseless):
        return tr("render useless");
    default:
        return tr("state %1").arg(state);
    }
}

QString JausPlatformText::lightName(JausLight light) {
    switch (light) {
    case JausLight::Headlights:
        return tr("headlights");
    case JausLight::LeftTurnSignal:
        return tr("left turn signal");
    case JausLight::RightTurnSignal:
        return tr("right turn signal");
    case JausLight::RunningLights:
        return tr("running lights");
    case JausLight::BrakeLights:
        return tr("brake lights");
    case JausLight::IrSource:
        return tr("IR source");
    }
    return {};
}

} // namespace ocu
