#pragma once
// One JAUS client service of the console (AEP-4818 §9): its own state per remote subsystem, the message IDs
// it handles (registered in the MessageTable), its timers. A pure state machine: time comes from the
// ClientContext's Clock, messages leave through the ClientContext, so tests drive it with a FakeClock.
// JausCore composes the services and calls these hooks; the order of the hooks is documented there.
#include <cstdint>

#include "protocols/jaus/clients/ClientContext.h"
#include "protocols/jaus/clients/MessageTable.h"

namespace ocu::jaus {

class ClientService {
public:
    explicit ClientService(ClientContext& context) : m_ctx(context) {}
    virtual ~ClientService() = default;
    ClientService(const ClientService&) = delete;
    ClientService& operator=(const ClientService&) = delete;

    // Registers the message IDs this service handles.
    virtual void registerMessages(MessageTable& table) = 0;
    // The subsystem's services became known (first ReportServices): subscribe, start polling.
    virtual void onServicesKnown(RemoteSubsystem&) {}
    // The link to the subsystem was down and is back: the platform may have restarted.
    virtual void onLinkRestored(RemoteSubsystem&) {}
    // Timers, called every tick (the stack uses 10 ms) for each subsystem whose services are known.
    virtual void tick(RemoteSubsystem&, TimePoint) {}
    // The subsystem's record is dropped (it turned out to be another console): drop its state.
    virtual void forget(std::uint16_t) {}

protected:
    ClientContext& m_ctx;
};

} // namespace ocu::jaus
