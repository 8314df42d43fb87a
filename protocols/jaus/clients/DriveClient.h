#pragma once
// Driving (AS6009 PrimitiveDriver / VelocityStateDriver, AEP-4818 §7): a drive session streams
// SetVelocityCommand (or SetWrenchEffort) to the Core Mobility Component at drive_rate_hz, clamped to the
// platform specification; a demand not refreshed within drive_command_timeout_s streams zero; a stop sends
// stop_repeats zero commands, never a single message (AEP-4818 §9 item 21).
#include <cstdint>
#include <map>
#include <string>

#include "protocols/jaus/clients/ClientService.h"

namespace ocu::jaus {

class DriveClient : public ClientService {
public:
    explicit DriveClient(ClientContext& context) : ClientService(context) {}

    void registerMessages(MessageTable&) override {} // drivers are only commanded: nothing to receive
    void tick(RemoteSubsystem& remote, TimePoint now) override;
    void forget(std::uint16_t subsystem) override { m_state.erase(subsystem); }

    // Commands; each returns false and emits CommandRefused when not allowed. What they return says what went
    // on the wire: startDriving sends a first zero demand at once and is true when the socket
    // took it; setDriveCommand is true when its demand (sent at once when it changed) or, unchanged, the
    // stream's latest message was taken; stopDriving is true when the first of the zero commands was taken.
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
    enum class Session {
        Closed,  // no drive session (the zero commands of a stop may still be repeating: stopRepeatsLeft)
        Driving, // the operator's demand, streamed at the drive rate
        Stale,   // open, but the demand was not refreshed within the drive command timeout: zero streamed
    };
    struct State {
        Session session = Session::Closed;
        int stopRepeatsLeft = 0;
        DriveCommand drive;
        TimePoint lastSent{};
        TimePoint lastUpdate{};       // last setDriveCommand (drive command watchdog)
        bool lastSendOk = true;       // the latest drive message was taken by the socket
        std::string lastError;        // why not, when it was not
        bool failureReported = false; // one event per failing streak, one when it recovers
    };
    DriveCommand::Mode startMode(const RemoteSubsystem& remote) const;
    // The driver service a demand of `mode` needs and the vehicle does not list; nullptr when it may go.
    static const char* missingDriver(const RemoteSubsystem& remote, DriveCommand::Mode mode);
    // True when the socket took the message; a failure (and the recovery after it) is an event.
    bool send(RemoteSubsystem& remote, State& state, bool zero);
    bool stop(RemoteSubsystem& remote, State& state);

    std::map<std::uint16_t, State> m_state;
};

} // namespace ocu::jaus
