#pragma once
// Qt-typed views of the JAUS picture for the JAUS panels (widgets/jaus): one vehicle (subsystem) as this
// console knows it, a JAUS event about one, a drive demand, and this console's own JAUS identity. The JAUS
// bridge fills them on the GUI thread from the stack's snapshots; the panels never see a protocols/jaus type.
#include "models/jaus/JausHandoff.h"
#include "models/jaus/JausMission.h"
#include "models/jaus/JausPlatformServices.h"

#include <QMetaType>
#include <QPair>
#include <QString>
#include <QVector>

#include <optional>

namespace ocu {

// A JAUS component address [subsystem.node.component]; all zero = none.
struct JausAddress {
    quint16 subsystem = 0;
    quint8 node = 0;
    quint8 component = 0;
    bool operator==(const JausAddress&) const = default;
};

enum class JausLink { Up, Degraded, Down };
// Access control of the vehicle as seen from this console (JausSubsystemModel::accessText gives the words).
enum class JausAccess {
    NotAvailable,
    NotControlled,
    Monitoring, // we only watch (MONITOR role or no control requested)
    ControlAccepted,
    ControlReleased,
    Timeout,
    InsufficientAuthority,
    Preempted
};
// Management service state (AS6009 Management).
enum class JausManagement { Init, Ready, Standby, Shutdown, Failure, Emergency };

struct JausGlobalPose {
    std::optional<double> lat, lon, alt; // degrees, metres
    std::optional<double> yaw;           // radians from north, clockwise
};
struct JausLocalPose {
    std::optional<double> x, y; // metres, x north, y east
    std::optional<double> yaw;  // radians
};
struct JausVelocity {
    std::optional<double> vx, vy;  // m/s
    std::optional<double> yawRate; // rad/s
};
struct JausPlatform {
    QString name;
    int steeringType = 0;                                        // 0 skid steer, 1 Ackermann
    std::optional<double> front, back, left, right, top, bottom; // metres from the reference point
    std::optional<double> maxForwardSpeed, maxReverseSpeed, maxRotationalSpeed;
};
struct JausHealth {
    int severity = 0;               // 0 NONE 1 INFO 2 WARNING 3 ERROR 4 FAILURE
    QVector<QPair<int, int>> nodes; // (node ID, severity)
};
struct JausService {
    QString uri;
    int major = 1, minor = 0;
};
struct JausComponentServices {
    int component = 0;
    QVector<JausService> services;
};
// A camera of the vehicle: announced through its IOP services or configured per vehicle.
struct JausVideoEndpoint {
    quint16 resourceId = 0;
    quint16 sensorId = 0;
    QString url;
    QString name;
    bool panTilt = false;
    bool configured = false; // from the site configuration, not announced
    bool operator==(const JausVideoEndpoint&) const = default;
};
struct JausNodeServices {
    int node = 0;
    QVector<JausComponentServices> components;
};

// One JAUS vehicle (subsystem) as this console knows it from the vehicle's reports.
struct JausVehicle {
    quint16 subsystem = 0;
    QString callSign;
    QString endpoint; // "ip:port" of the platform manager, empty when unknown
    JausLink link = JausLink::Down;
    QString linkText;             // the stack's word for the link state
    qint64 lastMessageUnixMs = 0; // on the models' clock (models/ModelClock.h)

    JausAccess access = JausAccess::Monitoring;
    JausAddress controller; // all zero when uncontrolled
    int controllerAuthority = 0;
    bool controlledByUs = false;
    int accessTimeoutS = 0; // from ReportTimeout (0 = unknown or disabled)

    std::optional<JausManagement> management;
    QString managementText; // the stack's word for the management state; empty when unknown
    bool emergency = false;
    bool driving = false; // a drive session of ours is open

    std::optional<JausGlobalPose> globalPose;
    std::optional<JausLocalPose> localPose;
    std::optional<JausVelocity> velocity;
    std::optional<JausPlatform> platform;
    std::optional<JausHealth> health;

    JausAddress mobilityComponent; // zero until discovered
    QVector<JausNodeServices> services;
    QVector<JausVideoEndpoint> videoEndpoints; // empty until announced or configured
    JausMission mission;                       // state None until this console uploads one
    JausPlatformServices platformServices;     // mode, state, lights, odometer as the vehicle reports them
    JausHandoff handoff;                       // hand-off between consoles (our request, requests to us)
};

enum class JausEventSeverity { Info, Warning, Error };
struct JausVehicleEvent {
    JausEventSeverity severity = JausEventSeverity::Info;
    QString kindText;      // the stack's word for the kind of event
    quint16 subsystem = 0; // 0 when not about one vehicle
    QString text;
};

// A drive demand (teleop).
struct JausDrive {
    enum class Mode { Wrench, Velocity };
    Mode mode = Mode::Velocity;
    double linear = 0; // Wrench: propulsive linear X % [-100,100]; Velocity: m/s (+ forward)
    double angular =
        0; // Wrench: propulsive rotational Z %; Velocity: yaw rate rad/s (+ = right, AEP-4818 §7.7)
    double brake = 0; // Wrench only: resistive linear X % [0,100]
};

// This console on the JAUS network, as configured.
struct JausConsoleIdentity {
    QString callSign;
    quint16 subsystemId = 0;
    int authority = 0;
    bool mayControl = false; // false for the MONITOR role
    // The stop rule, as the JAUS core decides it (JausConfig::mayStop/mayClearStop): any role may stop, only
    // roles with command rights may clear.
    bool mayStop = true;
    bool mayClearStop = false;
    double driveRateHz = 20; // drive stream while a session is open
    JausAddress ownId;       // this console's component
};

} // namespace ocu

Q_DECLARE_METATYPE(ocu::JausVehicle)
Q_DECLARE_METATYPE(ocu::JausVehicleEvent)
