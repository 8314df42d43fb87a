#pragma once
// JSS service inheritance: which service each JAUS service directly inherits from, so that a
// component listing only a derived service (e.g. LocalWaypointListDriver) is known to offer AccessControl and
// Management too. A peer may or may not list the parent URIs in ReportServices (FKIE's how-to asks
// integrators to, many do not), so the console decides with this table, never with the list alone.
//
// Sources: the JSIDL of the Core Service Set (SAE AS5710A, services Transport, Events, AccessControl,
// Management, Liveness, Discovery, ListManager: each "inherits-from" element), the Mobility Service Set
// (SAE AS6009: PrimitiveDriver, VelocityStateDriver, the waypoint and vector drivers inherit
// core:Management; the waypoint *list* drivers inherit core:ListManager (1.1) or mobility:ListManager
// (1.0); LocalPoseSensor and GlobalPoseSensor inherit core:AccessControl because SetLocalPose/SetGlobalPose
// need control; VelocityStateSensor inherits core:Events), the Manipulator Service Set (SAE AS6057A
// pan-tilt services), the Environment Sensing Service Set (SAE AS6060 VisualSensor and its children), the
// UGV Service Set (PlatformSpecifications) and the IOP services of AEP-4818 (HealthMonitor,
// UnsolicitedHeartbeat, EnhancedAccessControl, PlatformMode, PlatformState, PathReporter,
// DigitalResourceDiscovery). Transcribed from shared/research/jaus-services-extra.md §5.
#include <array>
#include <string_view>
#include <vector>

#include "protocols/jaus/Messages.h"

namespace ocu::jaus {

namespace service {
inline constexpr std::string_view Transport = "urn:jaus:jss:core:Transport";
inline constexpr std::string_view Events = "urn:jaus:jss:core:Events";
inline constexpr std::string_view AccessControl = "urn:jaus:jss:core:AccessControl";
inline constexpr std::string_view Management = "urn:jaus:jss:core:Management";
inline constexpr std::string_view Liveness = "urn:jaus:jss:core:Liveness";
inline constexpr std::string_view Discovery = "urn:jaus:jss:core:Discovery";
inline constexpr std::string_view ListManager = "urn:jaus:jss:core:ListManager";
inline constexpr std::string_view PrimitiveDriver = "urn:jaus:jss:mobility:PrimitiveDriver";
inline constexpr std::string_view VelocityStateDriver = "urn:jaus:jss:mobility:VelocityStateDriver";
inline constexpr std::string_view LocalPoseSensor = "urn:jaus:jss:mobility:LocalPoseSensor";
inline constexpr std::string_view GlobalPoseSensor = "urn:jaus:jss:mobility:GlobalPoseSensor";
inline constexpr std::string_view VelocityStateSensor = "urn:jaus:jss:mobility:VelocityStateSensor";
inline constexpr std::string_view PlatformSpecifications = "urn:jaus:jss:ugv:PlatformSpecifications";
inline constexpr std::string_view HealthMonitor = "urn:jaus:jss:exp:aeodrs:HealthMonitor";
} // namespace service

struct ServiceParent {
    std::string_view uri;
    std::string_view parent; // empty: a root service
};

// One row per JSS service the console may meet: the service and its direct parent.
inline constexpr std::array kServiceParents{
    // Core (AS5710A)
    ServiceParent{service::Transport, {}},
    ServiceParent{service::Events, service::Transport},
    ServiceParent{service::AccessControl, service::Events},
    ServiceParent{service::Management, service::AccessControl},
    ServiceParent{service::Liveness, service::Events},
    ServiceParent{service::Discovery, service::Events},
    ServiceParent{service::ListManager, service::Management},
    // Mobility (AS6009); ListManager 1.0 lived in the mobility namespace
    ServiceParent{"urn:jaus:jss:mobility:ListManager", service::Management},
    ServiceParent{service::PrimitiveDriver, service::Management},
    ServiceParent{service::VelocityStateDriver, service::Management},
    ServiceParent{"urn:jaus:jss:mobility:LocalWaypointDriver", service::Management},
    ServiceParent{"urn:jaus:jss:mobility:GlobalWaypointDriver", service::Management},
    ServiceParent{"urn:jaus:jss:mobility:LocalWaypointListDriver", service::ListManager},
    ServiceParent{"urn:jaus:jss:mobility:GlobalWaypointListDriver", service::ListManager},
    ServiceParent{"urn:jaus:jss:mobility:LocalVectorDriver", service::Management},
    ServiceParent{"urn:jaus:jss:mobility:GlobalVectorDriver", service::Management},
    ServiceParent{service::LocalPoseSensor, service::AccessControl},
    ServiceParent{service::GlobalPoseSensor, service::AccessControl},
    ServiceParent{service::VelocityStateSensor, service::Events},
    // UGV
    ServiceParent{service::PlatformSpecifications, service::Events},
    ServiceParent{"urn:jaus:jss:ugv:IlluminationService", service::AccessControl},
    ServiceParent{"urn:jaus:jss:ugv:OdometryService", service::AccessControl},
    // Environment sensing (AS6060)
    ServiceParent{"urn:jaus:jss:environmentSensing:VisualSensor", service::AccessControl},
    ServiceParent{"urn:jaus:jss:environmentSensing:DigitalVideo",
                  "urn:jaus:jss:environmentSensing:VisualSensor"},
    ServiceParent{"urn:jaus:jss:environmentSensing:AnalogVideo",
                  "urn:jaus:jss:environmentSensing:VisualSensor"},
    ServiceParent{"urn:jaus:jss:environmentSensing:StillImage",
                  "urn:jaus:jss:environmentSensing:VisualSensor"},
    ServiceParent{"urn:jaus:jss:environmentSensing:H264VideoEncoding",
                  "urn:jaus:jss:environmentSensing:DigitalVideo"},
    // Manipulator (AS6057A pan-tilt)
    ServiceParent{"urn:jaus:jss:manipulator:PrimitivePanTilt", service::Management},
    ServiceParent{"urn:jaus:jss:manipulator:PanTiltJointPositionDriver", service::Management},
    ServiceParent{"urn:jaus:jss:manipulator:PanTiltJointVelocityDriver", service::Management},
    ServiceParent{"urn:jaus:jss:manipulator:PanTiltJointPositionSensor", service::Events},
    ServiceParent{"urn:jaus:jss:manipulator:PanTiltJointVelocitySensor", service::Events},
    ServiceParent{"urn:jaus:jss:manipulator:PanTiltSpecificationService", service::Events},
    ServiceParent{"urn:jaus:jss:manipulator:PanTiltMotionProfileService", service::AccessControl},
    // IOP (AEP-4818)
    ServiceParent{service::HealthMonitor, service::AccessControl},
    ServiceParent{"urn:jaus:jss:iop:PathReporter", service::Events},
    ServiceParent{"urn:jaus:jss:iop:DigitalResourceDiscovery", service::Events},
    ServiceParent{"urn:jaus:jss:iop:UnsolicitedHeartbeat", service::Liveness},
    ServiceParent{"urn:jaus:jss:iop:UnsolicitedBroadcastControlAvailable", service::AccessControl},
    ServiceParent{"urn:jaus:jss:iop:EnhancedAccessControl", service::AccessControl},
    ServiceParent{"urn:jaus:jss:iop:PlatformMode", service::AccessControl},
    ServiceParent{"urn:jaus:jss:iop:PlatformState", service::AccessControl},
    ServiceParent{"urn:jaus:jss:iop:HandoffController", service::Transport},
};

// The direct parent of a service; empty for a root or a service the table does not know.
constexpr std::string_view parentOf(std::string_view uri) {
    for (const ServiceParent& p : kServiceParents)
        if (p.uri == uri)
            return p.parent;
    return {};
}

// True when `uri` is `ancestor` or inherits from it (directly or through its parents).
constexpr bool inheritsFrom(std::string_view uri, std::string_view ancestor) {
    for (int depth = 0; depth < 16 && !uri.empty(); ++depth) { // the deepest chain has 6 links
        if (uri == ancestor)
            return true;
        uri = parentOf(uri);
    }
    return false;
}

// True when a component with these services offers `service`, directly or by inheritance.
inline bool offers(const std::vector<ServiceRecord>& services, std::string_view service) {
    for (const ServiceRecord& s : services)
        if (inheritsFrom(s.uri, service))
            return true;
    return false;
}

} // namespace ocu::jaus
