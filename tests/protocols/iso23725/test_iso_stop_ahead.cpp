// The all-stop does not wait for the position backlog (ISO 23725 §7.6: the FMS's safety command). IsoStack
// hands a burst of positions to its listener in short steps, one io-thread handler each, and runs an all-stop
// requested meanwhile before the next step: the frame is on the socket while most of the positions received
// before it have not been handed over yet. Asserted as an order (how many positions the listener had when
// the stop frame was handed to the socket), never as a time. Over a real loopback WebSocket: a fake AHS
// (WsEndpoint service on its own io thread) sends a fleet and bursts of positions; the stack is the client.
#include <QtTest>

#include "protocols/common/IoThread.h"
#include "protocols/common/Log.h"
#include "protocols/iso23725/IsoStack.h"
#include "protocols/iso23725/WsEndpoint.h"

#include <atomic>
#include <mutex>
#include <optional>
#include <set>

using namespace ocu;
using namespace ocu::iso23725;

namespace {

constexpr int kTrucks = 600;
constexpr std::int64_t kT0 = 1'741'918'507'000;

Guid truck(int i) {
    char id[40];
    std::snprintf(id, sizeof id, "00000000-0000-4000-8000-%012d", i);
    return Guid(id);
}

// The AHS side: records the text frames it receives, in order.
struct FakeAhs : WsHandler {
    std::mutex mu;
    std::optional<SessionId> session;
    std::vector<std::string> texts;
    void onOpen(SessionId id, const std::string&) override {
        std::lock_guard l(mu);
        session = id;
    }
    void onText(SessionId, std::string text) override {
        std::lock_guard l(mu);
        texts.push_back(std::move(text));
    }
    void onClose(SessionId, const std::string&) override {
        std::lock_guard l(mu);
        session.reset();
    }
    bool open() {
        std::lock_guard l(mu);
        return session.has_value();
    }
    std::size_t stopsReceived() {
        std::lock_guard l(mu);
        std::size_t n = 0;
        for (auto& t : texts)
            n += t.find("\"ModeAllStop\":\"Apply\"") != std::string::npos ? 1 : 0;
        return n;
    }
};

// The FMS side's listener (the stack's io thread). At the first batch of a burst it requests the all-stop
// and notes how many positions of the burst the stack had received and not yet handed over; when the stop
// frame has been handed to the socket (FmsCore reports the pending request), it notes how many positions of
// the burst the listener had by then.
struct StopListener : IsoListener {
    IsoStack* stack = nullptr;
    Counters* linkCounters = nullptr;

    std::mutex mu;
    std::set<Guid> known;
    std::size_t delivered = 0;
    // One burst:
    bool requestStop = false;
    std::uint64_t positionsAtBurst = 0;
    std::size_t deliveredAtBurst = 0;
    std::size_t firstStep = 0;
    std::size_t pendingAtRequest = 0;
    std::optional<std::size_t> deliveredAtStop;
    std::optional<TargetOutcome> outcome;

    void onMachineChanged(const IsoMachineSnapshot& m) override {
        std::lock_guard l(mu);
        if (m.stateKnown)
            known.insert(m.equipmentId);
    }
    void onMachinePositions(const std::string& link,
                            const std::vector<const IsoMachineSnapshot*>& ms) override {
        std::lock_guard l(mu);
        if (requestStop) {
            requestStop = false;
            firstStep = ms.size();
            const std::size_t received = std::size_t(linkCounters->get("rx.positions") - positionsAtBurst);
            pendingAtRequest = received - (delivered - deliveredAtBurst);
            stack->allStopApply(link, [this](std::vector<TargetOutcome> o) {
                std::lock_guard l(mu);
                outcome = o.at(0);
            });
        }
        delivered += ms.size();
    }
    void onAllStopChanged(const std::string&, const AllStopStatus& s) override {
        std::lock_guard l(mu);
        if (s.pendingId && !deliveredAtStop)
            deliveredAtStop = delivered - deliveredAtBurst;
    }
    std::size_t knownCount() {
        std::lock_guard l(mu);
        return known.size();
    }
    std::size_t deliveredInBurst() {
        std::lock_guard l(mu);
        return delivered - deliveredAtBurst;
    }
};

std::string positionFrame(int i, std::int64_t measuredMs) {
    MachinePositionV1 p;
    p.timestamp = makeTimestamp(measuredMs);
    p.pose.latitude = -23.0 - 0.0001 * i;
    p.pose.longitude = 119.73;
    p.pose.elevation = 500.0;
    p.pose.heading = 90;
    p.pose.speed = 30;
    return encodeMessage(p, truck(i), measuredMs);
}

} // namespace

class TestIsoStopAhead : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { setLogThreshold(LogLevel::Error); }

    void stopFrameGoesAheadOfThePositionBacklog() {
        IoThread ahsIo("ahs");
        ahsIo.start();
        Counters ahsCounters;
        FakeAhs ahs;
        WsOptions so;
        so.role = WsRole::Service;
        so.url = "ws://127.0.0.1:0/";
        auto service = std::make_unique<WsEndpoint>(ahsIo.context(), so, ahs, ahsCounters);
        QVERIFY(ahsIo.call([&] { return bool(service->start()); }));
        const auto port = ahsIo.call([&] { return service->localPort(); });

        IsoConfig cfg;
        IsoLinkConfig lc;
        lc.name = "ahs";
        lc.ws.url = "ws://127.0.0.1:" + std::to_string(port) + "/";
        cfg.links.push_back(lc);
        StopListener listener;
        IsoStack stack(cfg, listener);
        listener.stack = &stack;
        listener.linkCounters = stack.linkCounters("ahs");
        QVERIFY(stack.start());
        QTRY_VERIFY_WITH_TIMEOUT(ahs.open() && stack.linkState("ahs") == LinkState::Up, 20000);

        auto sendAll = [&](std::vector<std::string> frames) {
            ahsIo.post([&, frames = std::move(frames)]() mutable {
                for (auto& f : frames)
                    service->send(*ahs.session, std::move(f));
            });
        };
        // The fleet, and one member per truck so every truck's state is known: from then on its positions
        // go through the batches.
        {
            FleetDefinitionV2 fleet;
            fleet.ahsId = "7d1f3c2a-5b8e-4c61-9a0d-2e4f6b8c1a37";
            std::vector<std::string> frames;
            for (int i = 0; i < kTrucks; ++i)
                fleet.equipment.push_back(Equipment{truck(i), "HT" + std::to_string(i), "HaulTruck", "OEM",
                                                    "793F", true, 12.9, 7.6});
            frames.push_back(encodeMessage(fleet));
            for (int i = 0; i < kTrucks; ++i)
                frames.push_back(encodeMessage(MachineAutonomyModeV1{"Autonomous"}, truck(i)));
            sendAll(std::move(frames));
        }
        QTRY_COMPARE_WITH_TIMEOUT(listener.knownCount(), std::size_t(kTrucks), 20000);

        // Bursts of one position per truck until one reached the listener in more than one step (a burst
        // handled faster than the batch interval is one step; that proves nothing either way).
        bool stepped = false;
        for (int burst = 1; burst <= 5 && !stepped; ++burst) {
            {
                std::lock_guard l(listener.mu);
                listener.positionsAtBurst = listener.linkCounters->get("rx.positions");
                listener.deliveredAtBurst = listener.delivered;
                listener.deliveredAtStop.reset();
                listener.outcome.reset();
                listener.requestStop = true;
            }
            const std::size_t stopsBefore = ahs.stopsReceived();
            std::vector<std::string> frames;
            for (int i = 0; i < kTrucks; ++i)
                frames.push_back(positionFrame(i, kT0 + burst * 1000));
            sendAll(std::move(frames));
            QTRY_COMPARE_WITH_TIMEOUT(listener.deliveredInBurst(), std::size_t(kTrucks), 20000);
            QTRY_COMPARE_WITH_TIMEOUT(ahs.stopsReceived(), stopsBefore + 1, 20000);

            std::lock_guard l(listener.mu);
            QVERIFY(listener.outcome.has_value());
            QVERIFY2(listener.outcome->sent, listener.outcome->reason.c_str());
            QVERIFY(listener.deliveredAtStop.has_value());
            const QByteArray what = QByteArray("burst ") + QByteArray::number(burst) + ": first step " +
                                    QByteArray::number(qulonglong(listener.firstStep)) + " of " +
                                    QByteArray::number(qulonglong(listener.pendingAtRequest)) +
                                    " pending, stop sent after " +
                                    QByteArray::number(qulonglong(*listener.deliveredAtStop)) + " positions";
            qInfo("%s", what.constData());
            QVERIFY2(listener.firstStep <= listener.pendingAtRequest, what.constData());
            stepped = listener.firstStep < listener.pendingAtRequest;
            if (stepped) // the stop left right after the step in progress, ahead of the positions received
                         // before it was requested
                QVERIFY2(*listener.deliveredAtStop == listener.firstStep, what.constData());
        }
        QVERIFY2(stepped, "no burst of positions was handed over in steps: the whole backlog went in one "
                          "handler, ahead of the all-stop");

        // Every frame the AHS received is whole (a frame is never written into the middle of another).
        {
            std::lock_guard l(ahs.mu);
            for (auto& t : ahs.texts)
                QVERIFY2(decodeMessage(t), t.c_str());
        }
        stack.stop();
        ahsIo.call([&] { service->stop(); });
        ahsIo.stop();
    }
};

QTEST_GUILESS_MAIN(TestIsoStopAhead)
#include "test_iso_stop_ahead.moc"
