#pragma once
// A vehicle's IOP platform services as the panels see them (AEP-4818 §6.2.5, §6.2.6, §9.2.2, §5.7, §8.8):
// platform mode and state, lights, odometer, and whether it offers a comms-lost policy service (with its
// version). Filled by the JAUS bridge from the vehicle's own reports, never from what was asked.
#include <QCoreApplication>
#include <QString>
#include <QVector>

#include <optional>

namespace ocu {

// A service as the vehicle lists it: offered or not, its URI and version.
struct JausOfferedService {
    bool offered = false;
    QString uri;
    int major = 0, minor = 0;
    QString versionText() const { return QStringLiteral("%1.%2").arg(major).arg(minor); }
    bool operator==(const JausOfferedService&) const = default;
};

// The IlluminationState bits the console switches (the wire's bit positions, ugv:IlluminationService 1.0).
// The whole vehicle's visible-light source is deliberately absent: AEP-4818 §9.2.2 forbids it.
enum class JausLight : quint32 {
    Headlights = 1u << 0,
    LeftTurnSignal = 1u << 1,
    RightTurnSignal = 1u << 2,
    RunningLights = 1u << 3,
    BrakeLights = 1u << 4,
    IrSource = 1u << 7,
};
inline constexpr JausLight kJausLights[] = {JausLight::Headlights,     JausLight::RunningLights,
                                            JausLight::LeftTurnSignal, JausLight::RightTurnSignal,
                                            JausLight::BrakeLights,    JausLight::IrSource};
inline quint32 bitOf(JausLight l) {
    return static_cast<quint32>(l);
}

// Platform modes and states (iop:PlatformMode / iop:PlatformState 1.1 values).
enum class JausPlatformMode { Standard = 0, Training = 1, Maintenance = 2 };
enum class JausPlatformState {
    Initialize = 0,
    Operational = 1,
    Shutdown = 2,
    SystemAbort = 3,
    Emergency = 4,
    RenderUseless = 5
};

struct JausPlatformServices {
    JausOfferedService modeService, stateService, illuminationService, odometryService, commsLostService;
    std::optional<int> mode, modeStatus;
    QVector<int> supportedModes; // empty until the vehicle said
    std::optional<int> state;
    QString stateRefusal; // the vehicle refused our last platform state (its words); empty otherwise
    std::optional<quint32> lights, lightsSupported; // JausLight bits; supported empty until reported
    std::optional<quint32> odometerM, tripM;        // PLATFORM and TRIP_A, metres

    bool emergencyState() const { return state && *state == int(JausPlatformState::Emergency); }
    bool lightOn(JausLight l) const { return lights && (*lights & bitOf(l)); }
    // True when the vehicle has the light, or has not said which it has.
    bool hasLight(JausLight l) const { return !lightsSupported || (*lightsSupported & bitOf(l)); }
    bool operator==(const JausPlatformServices&) const = default;
};

// Words for people (context "JausPlatform"): "standard", "training", "maintenance", "program mode 180";
// "operational", "emergency", ...; "headlights", "left turn signal", ...
class JausPlatformText {
    Q_DECLARE_TR_FUNCTIONS(ocu::JausPlatform)
public:
    static QString modeName(int mode);
    static QString stateName(int state);
    static QString lightName(JausLight light);
};

// The headless and audit key of a light: "headlights", "running_lights", "left_turn_signal",
// "right_turn_signal", "brake_lights", "ir_light".
inline QString jausLightKey(JausLight light) {
    switch (light) {
    case JausLight::Headlights:
        return QStringLiteral("headlights");
    case JausLight::LeftTurnSignal:
        return QStringLiteral("left_turn_signal");
    case JausLight::RightTurnSignal:
        return QStringLiteral("right_turn_signal");
    case JausLight::RunningLights:
        return QStringLiteral("running_lights");
    case JausLight::BrakeLights:
        return QStringLiteral("brake_lights");
    case JausLight::IrSource:
        return QStringLiteral("ir_light");
    }
    return {};
}

} // namespace ocu
