#pragma once
// What a vehicle reports about its IOP platform services (AEP-4818 §6.2.5, §6.2.6, §9.2.2, §5.7, §8.8):
// platform mode and state, lights, odometer, and whether it offers a comms-lost policy service. Every value
// comes from the vehicle's own reports (PlatformClient), never from what the console asked for.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ocu::jaus {

// A service found in the vehicle's ReportServices: whether it is offered, and which version.
struct OfferedService {
    bool offered = false;
    std::string uri; // as the vehicle names it (namespaces differ between stacks)
    int major = 0, minor = 0;
    bool operator==(const OfferedService&) const = default;
};

struct PlatformServicesStatus {
    OfferedService modeService, stateService, illuminationService, odometryService, commsLostService;

    // Platform Mode: 0 standard, 1 training, 2 maintenance, 175-255 program-specific.
    std::optional<std::uint8_t> mode, modeStatus;
    std::vector<std::uint8_t> supportedModes; // empty until ReportSupportedPlatformModes
    // Platform State: 0 initialize, 1 operational, 2 shutdown, 3 system abort, 4 emergency, 5 render useless.
    std::optional<std::uint8_t> state;
    // ConfirmPlatformStateRequest refusing our last request (InvalidState), in words; empty otherwise.
    std::string stateRefusal;
    // IlluminationState bits (MessagesPlatformServices.h, namespace light) and which the vehicle has (in the
    // state's bit positions; empty until ReportIlluminationConfiguration).
    std::optional<std::uint32_t> lights, lightsSupported;
    // Odometry, metres: PLATFORM (lifetime) and TRIP_A (since the last ResetOdometry(TRIP_A)).
    std::optional<std::uint32_t> odometerM, tripM;

    bool emergencyState() const { return state && *state == 4; }
    bool operator==(const PlatformServicesStatus&) const = default;
};

} // namespace ocu::jaus
