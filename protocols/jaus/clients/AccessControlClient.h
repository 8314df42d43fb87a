#pragma once
// Access control (AS5710A AccessControl, AEP-4818 §4.3): RequestControl with the configured authority to the
// Core Mobility Component, QueryTimeout once, re-requests every 40 % of the access timeout, QueryControl at
// status_poll_hz. Tells apart: accepted, refused (NOT_AVAILABLE / INSUFFICIENT_AUTHORITY, no retry),
// released, pre-empted by a higher authority and lost by timeout (AEP-4818 §9 items 10-16). The monitor role
// (authority 0) never requests control.
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>

#include "protocols/jaus/Messages.h"
#include "protocols/jaus/clients/ClientService.h"

namespace ocu::jaus {

class DriveClient;

class AccessControlClient : public ClientService {
public:
    // Losing or releasing control ends the drive session (zero commands before a release).
    AccessControlClient(ClientContext& context, DriveClient& drive)
        : ClientService(context), m_drive(drive) {}

    void registerMessages(MessageTable& table) override;
    void tick(RemoteSubsystem& remote, TimePoint now) override;
    void forget(std::uint16_t subsystem) override { m_state.erase(subsystem); }

    // Commands; each returns false and emits CommandRefused when not allowed.
    bool requestControl(std::uint16_t subsystem);
    bool releaseControl(std::uint16_t subsystem);
    // We granted a hand-off (HandoffClient): zero drive commands, stop re-requesting and take the vehicle's
    // RejectControl as a release, without a ReleaseControl of our own (the vehicle passes control on).
    void handOver(std::uint16_t subsystem);
    // Every subsystem we control or asked for (stop() of the stack).
    void releaseAll();
    // True between requestControl and its refusal, loss or release.
    bool wantsControl(std::uint16_t subsystem) const;
    // ConfirmControl / RejectControl from components another client holds control of (the
    // pan-tilt units): the filter returns true when it handled the message, which then is not the vehicle's.
    using OtherControl = std::function<bool(RemoteSubsystem&, const JausId&, std::uint16_t, ByteSpan)>;
    void setOtherControl(OtherControl filter) { m_other = std::move(filter); }

private:
    // Where our wish for control of one vehicle stands (AS5710A AccessControl, client side). Whether the
    // vehicle granted it is the snapshot's controlledByUs.
    enum class Phase {
        Idle,       // control not wanted
        Requesting, // control wanted: requested, and once accepted held and re-requested inside the timeout
        // A RejectControl answered our outstanding request: some stacks answer a pre-empting request with
        // RejectControl and then ConfirmControl(accepted); the reject counts only if no accept follows.
        RefusalPending,
        Releasing, // ReleaseControl sent while in control: RejectControl(0) is the answer
    };
    struct State {
        Phase phase = Phase::Idle;
        bool wants() const { return phase == Phase::Requesting || phase == Phase::RefusalPending; }
        // Control no longer wanted (a release under way stays one).
        void giveUp() {
            if (wants())
                phase = Phase::Idle;
        }
        // Control ended: until this deadline the next ReportControl tells pre-emption from a timeout. Apart
        // from the phase: a control handed back meanwhile (Releasing) does not cancel the check.
        std::optional<TimePoint> lossCheckUntil;
        TimePoint lastRequest{}, lastConfirm{}, lastControlPoll{};
        bool timeoutQueried = false;
        TimePoint rejectDeadline{}; // RefusalPending
        std::uint8_t rejectCode = 0;
        TimePoint releaseDeadline{}, lastReleaseSent{};
    };

    void onConfirm(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);
    void onReject(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);
    void onReport(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);
    void onControlLost(RemoteSubsystem& remote, State& state, const std::string& why);
    void classify(RemoteSubsystem& remote, State& state, const ReportControl& report);
    double timeoutS(const RemoteSubsystem& remote) const;

    DriveClient& m_drive;
    OtherControl m_other;
    std::map<std::uint16_t, State> m_state;
};

} // namespace ocu::jaus
