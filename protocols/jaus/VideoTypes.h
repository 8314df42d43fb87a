#pragma once
// A video stream of a JAUS vehicle as its IOP services announce it (AEP-4818 §9.1.2-9.1.8; layouts in
// research/jaus-services-extra.md): the Digital Resource Discovery registration gives the endpoint (URL), the
// Visual Sensor / Digital Video services give the sensor ID and name, a Pan Tilt service may drive the
// sensor. Shared by the JAUS stack (which fills it from reports) and the console (which plays it).
#include <cstdint>
#include <string>

namespace ocu::jaus {

struct VideoEndpoint {
    std::uint16_t resourceId = 0; // Digital Resource Discovery resource ID
    std::uint16_t sensorId = 0;   // Visual Sensor ID (Digital Video / Visual Sensor services)
    std::string url;              // e.g. rtsp://127.0.0.1:8554/ugv3/front
    std::string name;             // sensor name from the Visual Sensor configuration; may be empty
    bool panTilt = false;         // a Pan Tilt service drives this sensor
    bool configured = false;      // from the site configuration, not announced by the vehicle
    bool operator==(const VideoEndpoint&) const = default;
};

} // namespace ocu::jaus
