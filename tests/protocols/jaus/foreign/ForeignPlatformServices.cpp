#include "tests/protocols/jaus/foreign/ForeignPlatformServices.h"

namespace foreign {

namespace {

enum : std::uint16_t {
    SetPlatformState = 0xFF25,
    QueryPlatformState = 0xFF26,
    ConfirmPlatformStateRequest = 0xFF27,
    ReportPlatformState = 0xFF28,
    SetIlluminationState = 0x0513,
    QueryIlluminationState = 0x2513,
    ReportIlluminationState = 0x4513,
    QueryIlluminationConfiguration = 0x2514,
    ReportIlluminationConfiguration = 0x4514,
};
constexpr std::uint8_t kEmergencyStatus = 5; // ReportStatus EMERGENCY
constexpr std::uint8_t kOperational = 1, kEmergency = 4, kTransitioning = 0, kInvalidState = 1;
constexpr std::uint32_t kLights = 0x01 | 0x80; // headlights (b0), IR light source (b7)

Buf message(std::uint16_t id) {
    Buf b;
    put16(b, id);
    return b;
}

} // namespace

bool PlatformServices::handle(std::uint16_t mid, std::uint32_t src, const std::uint8_t* body, std::size_t len,
                              std::vector<Buf>& replies) {
    switch (mid) {
    case SetPlatformState: {
        if (len < 1 || src != m_controller)
            return true; // needs control (AccessControl guards)
        const std::uint8_t state = body[0];
        std::uint8_t code = kTransitioning;
        if (state == kEmergency && m_status != kEmergencyStatus) {
            m_beforeEmergency = m_status;
            m_status = kEmergencyStatus;
        } else if (state == kOperational && m_status == kEmergencyStatus) {
            m_status = m_beforeEmergency;
        } else if (state != kEmergency && state != kOperational) {
            code = kInvalidState;
        }
        Buf b = message(ConfirmPlatformStateRequest);
        put8(b, state);
        put8(b, code);
        replies.push_back(b);
        return true;
    }
    case QueryPlatformState: {
        Buf b = message(ReportPlatformState);
        put8(b, m_status == kEmergencyStatus ? kEmergency : kOperational);
        replies.push_back(b);
        return true;
    }
    case SetIlluminationState:
        if (len >= 4 && src == m_controller)
            m_lights = get32(body) & kLights;
        return true;
    case QueryIlluminationState:
    case QueryIlluminationConfiguration: {
        Buf b = message(mid == QueryIlluminationState ? ReportIlluminationState
                                                      : ReportIlluminationConfiguration);
        put32(b, mid == QueryIlluminationState ? m_lights : kLights);
        replies.push_back(b);
        return true;
    }
    default:
        return false;
    }
}

} // namespace foreign
