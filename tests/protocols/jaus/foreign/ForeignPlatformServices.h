#pragma once
// The foreign vehicle's IOP platform services, as an FKIE-style platform component would offer them
// (jaus-autonomy.md §6.3, §7; FKIE's PlatformState server supports Operational and Emergency): Platform
// State 1.1 (Emergency puts the vehicle's Management into Emergency, Operational clears it, every other state
// is answered InvalidState; Set only from the controller) and Illumination 1.0 with headlights and an IR
// source only (absent lights report 0). No events: reports only when queried. Written from the research note
// with its own decoding (nothing from protocols/ or sim/).
#include "tests/protocols/jaus/foreign/ForeignBytes.h"

#include <cstdint>
#include <vector>

namespace foreign {

class PlatformServices {
public:
    // controller / status / beforeEmergency: the vehicle's access control and Management state.
    PlatformServices(std::uint32_t& controller, std::uint8_t& status, std::uint8_t& beforeEmergency)
        : m_controller(controller), m_status(status), m_beforeEmergency(beforeEmergency) {}

    // A message to the services' component: true when it is theirs (answers appended to `replies`).
    bool handle(std::uint16_t mid, std::uint32_t src, const std::uint8_t* body, std::size_t len,
                std::vector<Buf>& replies);
    std::uint32_t lights() const { return m_lights; }

private:
    std::uint32_t& m_controller;
    std::uint8_t& m_status;
    std::uint8_t& m_beforeEmergency;
    std::uint32_t m_lights = 0;
};

} // namespace foreign
