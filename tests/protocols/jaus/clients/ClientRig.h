#pragma once
// JAUS client services tested on their own: a ClientContext on a FakeClock, everything sent captured, every
// listener call recorded, and a MessageTable the clients under test register in. No JausCore, no simulated
// vehicle, no sockets: the tests play the vehicle by hand, message by message.
#include <QtTest>

#include <algorithm>
#include <vector>

#include "protocols/jaus/Messages.h"
#include "protocols/jaus/clients/ClientContext.h"
#include "protocols/jaus/clients/MessageTable.h"

namespace ocu::jaus::test {

struct Sent {
    JausId destination;
    Bytes payload;
    SendOptions options;
    std::uint16_t id() const { return peekMessageId(payload); }
};

struct CaptureOutput : JausOutput {
    std::vector<Sent> sent;
    std::string endpoint = "192.0.2.26:3794"; // what the transport learnt for every JAUS ID
    std::string failWith; // non-empty: the socket takes nothing, every send fails with this reason
    void send(const JausId& dst, const Bytes& payload, SendOptions o) override {
        sent.push_back({dst, payload, o});
    }
    std::string sendOrWhy(const JausId& dst, const Bytes& payload, SendOptions o) override {
        if (!failWith.empty())
            return failWith;
        send(dst, payload, o);
        return {};
    }
    std::string endpointOf(const JausId&) const override { return endpoint; }
    int count(std::uint16_t id) const {
        return int(std::count_if(sent.begin(), sent.end(), [&](const Sent& s) { return s.id() == id; }));
    }
    // The last message with this ID (nullptr when none).
    const Sent* last(std::uint16_t id) const {
        auto it = std::find_if(sent.rbegin(), sent.rend(), [&](const Sent& s) { return s.id() == id; });
        return it == sent.rend() ? nullptr : &*it;
    }
    std::vector<std::uint16_t> ids() const {
        std::vector<std::uint16_t> out;
        for (auto& s : sent)
            out.push_back(s.id());
        return out;
    }
};

struct Recorder : JausListener {
    std::vector<JausEvent> events;
    std::vector<SubsystemSnapshot> snapshots;
    void onSubsystemChanged(const SubsystemSnapshot& s) override { snapshots.push_back(s); }
    void onEvent(const JausEvent& e) override { events.push_back(e); }
    int count(EventKind k) const {
        return int(
            std::count_if(events.begin(), events.end(), [&](const JausEvent& e) { return e.kind == k; }));
    }
};

inline JausConfig rigConfig(std::uint8_t authority = 205) {
    JausConfig c;
    c.subsystemId = 200;
    c.callSign = "OCU-200";
    c.authority = authority;
    c.role = authority == 0 ? Role::Monitor : Role::PrimaryOperator;
    return c;
}

struct ClientRig {
    FakeClock clock;
    Counters counters;
    CaptureOutput out;
    Recorder rec;
    ClientContext ctx;
    MessageTable table;

    explicit ClientRig(JausConfig config = rigConfig()) : ctx(std::move(config), rec, out, clock, counters) {}

    // A vehicle as discovery leaves it: call sign, platform manager ss.1.1, Core Mobility Component ss.3.1,
    // sensors ss.3.2, health monitor ss.1.4, services known.
    RemoteSubsystem& vehicle(std::uint16_t ss = 126) {
        RemoteSubsystem& r = ctx.remote(ss);
        r.snap.callSign = "UGV-" + std::to_string(ss);
        r.snap.mobilityComponent = JausId{ss, 3, 1};
        r.components.known = true;
        r.components.globalPoseSensor = r.components.localPoseSensor = r.components.velocitySensor =
            JausId{ss, 3, 2};
        r.components.platformSpecs = JausId{ss, 3, 1};
        r.components.healthMonitor = JausId{ss, 1, 4};
        return r;
    }
    static JausId mobility(std::uint16_t ss = 126) { return JausId{ss, 3, 1}; }

    // The stack's timer: the clock advances in 10 ms steps for seconds, tick(now) after each step.
    template <class Tick> void runFor(double seconds, Tick&& tick) {
        for (int i = 0; i < int(seconds * 100 + 0.5); ++i) {
            clock.advance(std::chrono::milliseconds(10));
            tick(clock.now());
        }
    }

    // A message from the vehicle, through the table as JausCore would route it; false when nobody handles it.
    bool deliver(RemoteSubsystem& r, const Bytes& payload, JausId from = mobility()) {
        return table.dispatch(r, from, peekMessageId(payload), payload);
    }
};

} // namespace ocu::jaus::test
