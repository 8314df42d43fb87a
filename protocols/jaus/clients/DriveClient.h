#pragma once
// Driving (AS6009 PrimitiveDriver / VelocityStateDriver, AEP-4818 §7): a drive session streams
// SetVelocityCommand (or SetWrenchEffort) to the Core Mobility Component at drive_rate_hz, clamped to the
// platform specification; a demand not refreshed within drive_command_timeout_s streams zero; a stop sends
// stop_repeats zero commands, never a single message (AEP-4818 §9 item 21).
#include <cstdint>
#include <map>

#include "protocols/jaus/clients/ClientService.h"

namespace ocu::jaus {

class DriveClient : public ClientService {
public:
    explicit DriveClient(ClientContext& context) : ClientService(context) {}

    void registerMessages(MessageTable&) override {} // drivers are only commanded: nothing to receive
    void tick(RemoteSubsystem& remote, TimePoint now) override;
    void forget(std::uint16_t subsystem) override { m_state.erase(subsystem); }

    // Commands; each returns false and emits CommandRefused when not allowed.
    bool startDriving(std::uint16_t subsystem);
    bool setDriveCommand(std::uint16_t subsystem, DriveCommand command);
    bool stopDriving(std::uint16_t subsystem);

    // The session ends because control was lost or an emergency was set. dropZeroTail also ends the zero
    // commands of an earlier stop that are still going out.
    void endSession(RemoteSubsystem& remote, bool dropZeroTail);
    // Before control is released: the stream stops and zero commands go out first.
    void beforeRelease(RemoteSubsystem& remote);
    // True while any drive stream (including the zero tail after a stop) is pending.
    bool anyActive() const;

private:
    struct State {
        bool active = false;
        int stopRepeatsLeft = 0;
        DriveCommand drive;
        TimePoint lastSent{};
        TimePoint lastUpdate{}; // last setDriveCommand (drive command watchdog)
        bool stale = false;
    };
    void send(RemoteSubsystem& remote, State& state, bool zero);
    bool stop(RemoteSubsystem& remote, State& state);

    std::map<std::uint16_t, State> m_state;
};

} // namespace ocu::jaus
