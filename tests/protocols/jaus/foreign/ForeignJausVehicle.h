#pragma once
// A foreign JAUS vehicle for the OCU's end-to-end tests: a minimal, independent JUDP peer
// written from the JSS texts (AS5669A JUDP framing, AS5710A core services, AS6009 mobility service names)
// and the IOP notes (shared/research/jaus-wire.md §2-3, jaus-services-extra.md §5). It shares no code with
// sim/jaus or protocols/jaus (its own tiny encoder and decoder, Boost.Asio only), so it checks our bytes
// rather than agreeing with them by construction.
//
// One component (by default 126.1.1) hosts every service, and it behaves the way public stacks often do,
// by configuration: only derived services listed in ReportServices, no events (CreateEvent unanswered),
// no heartbeat, no answer to QueryControl or QueryTimeout, a pre-empting RequestControl answered with
// RejectControl then ConfirmControl(accepted) to the same requester, the old controller never told it
// lost control, answers delayed. It listens on 127.0.0.1 unicast only (no multicast): consoles find it
// through their static endpoint list.
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "tests/protocols/jaus/foreign/ForeignHandoff.h"
#include "tests/protocols/jaus/foreign/ForeignPlatformServices.h"
#include "tests/protocols/jaus/foreign/ForeignWaypointList.h"

namespace foreign {

// A stream this vehicle announces through IOP Digital Resource Discovery: its own DRD answers
// QueryDigitalResourceEndpoint (0xE702) with ReportDigitalResourceEndpoint (0xF702).
struct AnnouncedStream {
    std::string url;
    bool withHost = false;       // optional JAUS_ID field (PV bit 0) sent
    bool withResourceId = false; // optional ResourceID field (PV bit 1) sent
    std::uint16_t resourceId = 0;
    std::uint8_t serverType = 0; // 0 RTSP
};

// How the vehicle tells a console its services (AS5710A Discovery), as public stacks differ:
// Report: ReportServices to QueryServices, all components in one answer (the common case).
// EmptyWildcardRegister: the wildcard QueryServices (node 255, component 255) is answered with a
// ReportServices listing 0 components; a query naming a node and component is answered for that component;
// each component pushes RegisterServices (0x0B00) with its complete list to every console that asked.
// Silent: the wildcard answered with 0 components, nothing else ever (its services are never learnt).
enum class ServicesDialect { Report, EmptyWildcardRegister, Silent };

// A further component on the vehicle's node (the first is VehicleOptions' own component).
struct ExtraComponent {
    std::uint8_t component = 2;
    std::vector<std::string> services;
    bool management = false;    // SetEmergency, ClearEmergency, QueryStatus, Resume, Standby
    bool accessControl = false; // RequestControl, ReleaseControl ...
    bool pose = false;          // answers QueryGlobalPose, QueryLocalPose, QueryVelocityState
};

struct VehicleOptions {
    std::uint16_t subsystem = 126;
    std::uint8_t node = 1;
    std::uint8_t component = 1;
    std::string callSign = "FOREIGN-126";
    // ReportServices lists exactly these (URI, version 1.1): by default only derived services.
    std::vector<std::string> services = {"urn:jaus:jss:mobility:LocalPoseSensor",
                                         "urn:jaus:jss:mobility:LocalWaypointListDriver"};
    // Whether this component implements Management (SetEmergency, ClearEmergency, QueryStatus). True for
    // any service deriving from core:Management (LocalWaypointListDriver -> ListManager -> Management).
    bool management = true;
    // Whether it implements AccessControl (RequestControl ...): LocalPoseSensor derives from it.
    bool accessControl = true;
    // Whether this component answers the pose queries too (the one-component layout of the JTS examples).
    bool pose = false;
    bool answerQueryControl = false;
    bool answerQueryTimeout = false;
    // A pre-empting RequestControl: RejectControl(0) to the requester, then ConfirmControl(0).
    bool rejectThenConfirm = true;
    // Whether the pre-empted (or timed-out) controller gets RejectControl(CONTROL_RELEASED).
    bool tellOldController = false;
    int replyDelayMs = 0;
    std::uint8_t accessTimeoutS = 3; // control lapses without a re-request within this time
    std::uint16_t port = 0;          // 127.0.0.1 unicast port; 0 = ephemeral
    // Digital Resource Discovery (list "urn:jaus:jss:iop:DigitalResourceDiscovery" in services).
    std::vector<AnnouncedStream> streams;
    int drdSilentFirstMs = 0; // queries within this time after start are ignored (FKIE's server: 5 s)
    ServicesDialect servicesDialect = ServicesDialect::Report;
    // EmptyWildcardRegister only: whether the components push RegisterServices (false: they answer only
    // queries that name them).
    bool pushRegistrations = true;
    // More components on the same node (a driver, a pose sensor ...), each answering for itself.
    std::vector<ExtraComponent> extraComponents;
    // Whether every component answers a QueryIdentification that reaches it (else only the first).
    bool everyComponentIdentifies = false;
    // A Local Waypoint List Driver (ForeignWaypointList.h) on this component (0 = none). On a component other
    // than the first it has its own control and Management state, and takes the drive component's control
    // (the first component's) itself while it executes; on the first it shares the vehicle's control and
    // state (whoever controls the component runs the list). The pose moves as it drives.
    std::uint8_t listDriverComponent = 0;
    WaypointListDriver::Options listDriver;
    // Platform State and Illumination (ForeignPlatformServices.h) on this component (0 = none; list their
    // URIs in that component's services), under the vehicle's one access control.
    std::uint8_t platformServicesComponent = 0;
    // Enhanced Access Control 1.1 (ForeignHandoff.h) on this component (0 = none; list
    // "urn:jaus:jss:iop:EnhancedAccessControl" in that component's services), over the vehicle's one access
    // control: the component that answers RequestControl.
    std::uint8_t handoffComponent = 0;
    HandoffOptions handoff;
    // The pose the pose components report (WGS84 degrees, local metres, yaw radians).
    double latitude = 48.1, longitude = 11.5, localX = 12.5, localY = -3.25, yaw = 0.5;
};

class ForeignJausVehicle {
public:
    explicit ForeignJausVehicle(VehicleOptions options);
    ~ForeignJausVehicle();
    ForeignJausVehicle(const ForeignJausVehicle&) = delete;
    ForeignJausVehicle& operator=(const ForeignJausVehicle&) = delete;

    std::uint16_t port() const;
    // Offline: everything received is dropped and nothing is sent (a vehicle out of radio range).
    void setOffline(bool offline);

    // Observed state (thread-safe).
    std::uint32_t controller() const; // JAUS ID as u32 (ss<<16 | node<<8 | comp); 0 when uncontrolled
    std::uint8_t status() const;      // ReportStatus code: 1 READY, 2 STANDBY, 5 EMERGENCY
    // Messages received with this ID addressed to (or broadcast to) the component `component`.
    int receivedBy(std::uint16_t messageId, std::uint8_t component) const;
    int received(std::uint16_t messageId) const;
    int receivedFrom(std::uint16_t messageId, std::uint32_t source) const;
    // The list driver's active element (0 = idle) and the local position it drove to.
    std::uint16_t activeElement() const;
    std::pair<double, double> localPosition() const;
    // The lights the platform services have on (IlluminationState bits; 0 without the services).
    std::uint32_t lights() const;
    // Hand-off requests in the Enhanced Access Control's queue, and hand-offs granted (0 without it).
    std::size_t handoffsQueued() const;
    int handoffsGranted() const;
    // Datagrams received that did not parse as AS5669A JUDP (must stay 0: our bytes are checked here).
    int malformed() const;

    static std::uint32_t id(std::uint16_t ss, std::uint8_t node, std::uint8_t comp) {
        return std::uint32_t(ss) << 16 | std::uint32_t(node) << 8 | comp;
    }

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace foreign
