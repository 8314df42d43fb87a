// DiscoveryClient on its own with a FakeClock: the broadcast QueryIdentification at start and every
// discovery interval; a subsystem heard (heartbeat) but not identified asked directly; call sign, platform
// manager and endpoint from ReportIdentification; the component table from ReportServices (service names
// in any namespace, duplicates merged, the services-known hook once); QueryServices until known, then the
// periodic re-check; other consoles told apart; the console's own identification and services answered.
#include <QtTest>

#include "protocols/jaus/clients/DiscoveryClient.h"
#include "tests/protocols/jaus/clients/ClientRig.h"

using namespace ocu;
using namespace ocu::jaus;
using namespace ocu::jaus::test;

namespace {

struct DiscoveryRig : ClientRig {
    int servicesKnown = 0;
    DiscoveryClient discovery{ctx, [this](RemoteSubsystem&) { ++servicesKnown; }};
    explicit DiscoveryRig(JausConfig c = rigConfig()) : ClientRig(std::move(c)) {
        discovery.registerMessages(table);
    }
    void run(RemoteSubsystem* r, double seconds) {
        runFor(seconds, [&](TimePoint now) {
            discovery.tickBroadcast(now);
            if (r)
                discovery.tick(*r, now);
        });
    }
};

ReportIdentification ugvIdent(const std::string& name, IdQueryType q = IdQueryType::Subsystem) {
    return ReportIdentification{q, IdType::Vehicle, name};
}

ReportServices ugvServices() {
    ReportServices rs;
    rs.nodes.push_back(
        {1, {{1, 0, {{"urn:jaus:jss:core:Liveness", 1, 1}, {"urn:jaus:jss:iop:HealthMonitor", 1, 0}}}}});
    rs.nodes.push_back({3,
                        {{1,
                          0,
                          {{"urn:jaus:jss:mobility:PrimitiveDriver", 1, 0},
                           {"urn:jaus:jss:mobility:PlatformSpecifications", 1, 0}}},
                         {2,
                          0,
                          {{"urn:jaus:jss:mobility:GlobalPoseSensor", 1, 0},
                           {"urn:jaus:jss:mobility:LocalPoseSensor", 1, 0},
                           {"urn:vendor:VelocityStateSensor", 1, 0}}}}});
    return rs;
}

} // namespace

class TestDiscoveryClient : public QObject {
    Q_OBJECT

private slots:
    void broadcastAtStartAndEveryInterval() {
        JausConfig c = rigConfig();
        c.discoveryIntervalS = 10;
        DiscoveryRig rig(c);
        rig.run(nullptr, 0.01);
        QCOMPARE(rig.out.sent.size(), std::size_t(1));
        QCOMPARE(rig.out.sent[0].destination, kBroadcastAll);
        QCOMPARE(decodeQueryIdentification(rig.out.sent[0].payload)->type, IdQueryType::Subsystem);
        rig.run(nullptr, 9.9);
        QCOMPARE(rig.out.count(msg::QueryIdentification), 1);
        rig.run(nullptr, 0.2);
        QCOMPARE(rig.out.count(msg::QueryIdentification), 2);
        rig.discovery.discoverNow();
        QCOMPARE(rig.out.count(msg::QueryIdentification), 3);
    }

    void identificationNamesTheVehicle() {
        DiscoveryRig rig;
        RemoteSubsystem& r = rig.ctx.remote(126);
        const JausId pm{126, 1, 1};
        // A component-level answer names it only until the subsystem-level one arrives.
        QVERIFY(rig.deliver(r, encode(ugvIdent("front camera", IdQueryType::Component)), JausId{126, 5, 1}));
        QCOMPARE(r.snap.callSign, std::string("front camera"));
        QVERIFY(rig.deliver(r, encode(ugvIdent("UGV-126")), pm));
        QCOMPARE(r.snap.callSign, std::string("UGV-126"));
        QCOMPARE(r.components.platformManager, pm);
        QCOMPARE(r.snap.endpoint, std::string("192.0.2.26:3794"));
        QVERIFY(rig.deliver(r, encode(ugvIdent("ignored", IdQueryType::Node)), JausId{126, 2, 1}));
        QCOMPARE(r.snap.callSign, std::string("UGV-126"));
        QCOMPARE(rig.rec.count(EventKind::Discovered), 1);
    }

    void unidentifiedSubsystemsAreAsked() {
        DiscoveryRig rig;
        RemoteSubsystem& r = rig.ctx.remote(126);
        const JausId hb{126, 255, 255}; // the IOP unsolicited heartbeat's source may be any component
        QVERIFY(rig.deliver(r, encodeEmpty(msg::ReportHeartbeatPulse), JausId{126, 1, 1}));
        QCOMPARE(rig.out.sent.size(), std::size_t(1));
        QCOMPARE(rig.out.sent[0].destination, (JausId{126, 1, 1}));
        QVERIFY(rig.deliver(r, encodeEmpty(msg::ReportHeartbeatPulse), hb));
        QCOMPARE(rig.out.count(msg::QueryIdentification), 1); // at most once a second
        rig.run(&r, 1.05);
        QCOMPARE(rig.out.count(msg::QueryIdentification), 3); // the broadcast and the platform manager
        QVERIFY(rig.deliver(r, encode(ugvIdent("UGV-126")), JausId{126, 1, 1}));
        const int n = rig.out.count(msg::QueryIdentification);
        rig.run(&r, 3);
        QVERIFY(rig.deliver(r, encodeEmpty(msg::ReportHeartbeatPulse), JausId{126, 1, 1}));
        QCOMPARE(rig.out.count(msg::QueryIdentification), n);
    }

    void servicesBuildTheComponentTable() {
        DiscoveryRig rig;
        RemoteSubsystem& r = rig.ctx.remote(126);
        rig.run(&r, 0.01);
        QCOMPARE(rig.out.count(msg::QueryServices), 1);
        QCOMPARE(rig.out.last(msg::QueryServices)->destination, (JausId{126, 1, 1}));
        rig.run(&r, 1.0);
        QCOMPARE(rig.out.count(msg::QueryServices), 1);
        rig.run(&r, 0.05);
        QCOMPARE(rig.out.count(msg::QueryServices), 2); // once a second until known

        QVERIFY(rig.deliver(r, encode(ugvServices()), JausId{126, 1, 1}));
        QVERIFY(r.components.known);
        QCOMPARE(rig.servicesKnown, 1);
        QCOMPARE(r.snap.mobilityComponent, (JausId{126, 3, 1}));
        QCOMPARE(r.components.platformSpecs, (JausId{126, 3, 1}));
        QCOMPARE(r.components.globalPoseSensor, (JausId{126, 3, 2}));
        QCOMPARE(r.components.localPoseSensor, (JausId{126, 3, 2}));
        QCOMPARE(r.components.velocitySensor, (JausId{126, 3, 2})); // any namespace
        QCOMPARE(r.components.healthMonitor, (JausId{126, 1, 1}));
        QCOMPARE(r.components.platformManager, (JausId{126, 1, 1}));
        QCOMPARE(r.snap.services.size(), std::size_t(2));

        // The same answer again (peers repeat themselves): merged, the hook not called twice.
        QVERIFY(rig.deliver(r, encode(ugvServices()), JausId{126, 1, 1}));
        QCOMPARE(rig.servicesKnown, 1);
        QCOMPARE(r.snap.services[1].components[1].services.size(), std::size_t(3));

        // Known: one re-check at once, then one every discovery interval (30 s).
        const int n = rig.out.count(msg::QueryServices);
        rig.run(&r, 0.01);
        QCOMPARE(rig.out.count(msg::QueryServices), n + 1);
        rig.run(&r, 29.9);
        QCOMPARE(rig.out.count(msg::QueryServices), n + 1);
        rig.run(&r, 0.2);
        QCOMPARE(rig.out.count(msg::QueryServices), n + 2);
    }

    // A vehicle that answers the wildcard QueryServices with no components and registers its services
    // instead (AS5710A RegisterServices): the empty answer leaves the table unknown (so a stop still goes to
    // every component), the console asks for the configuration and names each component it has heard;
    // every registration merges, and the services-known hook runs again when a part adds services.
    void emptyWildcardAnswerThenRegistrations() {
        DiscoveryRig rig;
        RemoteSubsystem& r = rig.ctx.remote(126);
        QVERIFY(rig.deliver(r, encode(ugvIdent("PUBLIC-126")), JausId{126, 1, 1}));
        for (std::uint8_t c : {1, 2, 3})
            rig.discovery.heardFrom(r, JausId{126, 1, c});
        rig.run(&r, 0.01);
        QCOMPARE(rig.out.count(msg::QueryServices), 1);
        QCOMPARE(rig.out.count(msg::QueryConfiguration), 0); // only after an empty answer

        ReportServices empty;
        empty.nodes.push_back({1, {}});
        QVERIFY(rig.deliver(r, encode(empty), JausId{126, 1, 1}));
        QVERIFY(!r.components.known);
        QCOMPARE(rig.servicesKnown, 0);
        QCOMPARE(rig.counters.get("discovery.empty_services_answer"), std::uint64_t(1));
        QCOMPARE(rig.rec.events.back().severity, Severity::Warning);
        rig.out.sent.clear();
        rig.run(&r, 0.01);
        QCOMPARE(rig.out.count(msg::QueryConfiguration), 1);
        const Sent* qc = rig.out.last(msg::QueryConfiguration);
        QCOMPARE(qc->destination, (JausId{126, 1, 1}));
        QCOMPARE(qc->payload, (Bytes{0x01, 0x2B, 0x02})); // AS5710A QueryConfiguration, subsystem level
        // Named queries: component 1 (the platform manager itself) once, 2 and 3 to the platform manager and
        // to the component: QueryServices {1 node: node 1, 1 component: c} = 03 2B 01 01 01 c.
        int toDriver = 0;
        for (const Sent& m : rig.out.sent)
            if (m.id() == msg::QueryServices && m.payload.size() == 6) {
                QCOMPARE(Bytes(m.payload.begin(), m.payload.begin() + 5),
                         (Bytes{0x03, 0x2B, 0x01, 0x01, 0x01}));
                toDriver += m.destination == JausId{126, 1, 2} ? 1 : 0;
            }
        QCOMPARE(toDriver, 1);
        QCOMPARE(rig.out.count(msg::QueryServices), 1 + 2 + 2); // the named ones (the wildcard: 1 s apart)

        // The driver registers: the table is known, the driver takes efforts only.
        QVERIFY(rig.deliver(r, encode(RegisterServices{{{"urn:jaus:jss:mobility:PrimitiveDriver", 1, 1}}}),
                            JausId{126, 1, 2}));
        QVERIFY(r.components.known);
        QCOMPARE(rig.servicesKnown, 1);
        QCOMPARE(r.snap.mobilityComponent, (JausId{126, 1, 2}));
        QCOMPARE(r.managementTarget(), (JausId{126, 1, 2}));
        QVERIFY(r.components.driverTakesEffort);
        QVERIFY(!r.components.driverTakesVelocity);
        // The pose sensor registers later: merged, the hook runs again (its subscriptions are new).
        const Bytes pose = encode(RegisterServices{{{"urn:jaus:jss:mobility:GlobalPoseSensor", 1, 1},
                                                    {"urn:jaus:jss:mobility:LocalPoseSensor", 1, 1}}});
        QVERIFY(rig.deliver(r, pose, JausId{126, 1, 3}));
        QCOMPARE(rig.servicesKnown, 2);
        QCOMPARE(r.components.globalPoseSensor, (JausId{126, 1, 3}));
        QVERIFY(rig.deliver(r, pose, JausId{126, 1, 3})); // repeated registrations add nothing
        QCOMPARE(rig.servicesKnown, 2);

        // A component named by ReportConfiguration and not listed is asked for by name; one that never
        // answers (here the platform manager, which registers nothing) is asked five times a second apart,
        // then once per discovery interval.
        ReportConfiguration conf;
        conf.nodes.push_back({1, {{1, 0}, {2, 0}, {3, 0}, {4, 0}}});
        QVERIFY(rig.deliver(r, encode(conf), JausId{126, 1, 1}));
        rig.out.sent.clear();
        rig.run(&r, 0.01);
        int toFour = 0;
        for (const Sent& m : rig.out.sent)
            toFour += m.id() == msg::QueryServices && m.destination == JausId{126, 1, 4} ? 1 : 0;
        QCOMPARE(toFour, 1);
        rig.run(&r, 10);
        auto namedTo = [&](JausId c) {
            int n = 0;
            for (const Sent& m : rig.out.sent)
                if (m.id() == msg::QueryServices && m.payload.size() == 6 && m.payload[5] == c.component &&
                    m.destination == c)
                    ++n;
            return n;
        };
        QCOMPARE(namedTo(JausId{126, 1, 4}), 5);
        rig.run(&r, 25);
        QCOMPARE(namedTo(JausId{126, 1, 4}), 6);
    }

    void serviceListForOurSubsystemOnly() {
        DiscoveryRig rig;
        RemoteSubsystem& r = rig.ctx.remote(126);
        ReportServiceList list;
        list.subsystems.push_back({127, ugvServices().nodes});
        QVERIFY(rig.deliver(r, encode(list), JausId{126, 1, 1}));
        QVERIFY(!r.components.known);
        list.subsystems.push_back({126, ugvServices().nodes});
        QVERIFY(rig.deliver(r, encode(list), JausId{126, 1, 1}));
        QVERIFY(r.components.known);
        QCOMPARE(r.snap.mobilityComponent, (JausId{126, 3, 1}));
    }

    void noServicesQueryWhileDown() {
        DiscoveryRig rig;
        RemoteSubsystem& r = rig.ctx.remote(126);
        r.snap.link = LinkState::Down;
        rig.run(&r, 3);
        QCOMPARE(rig.out.count(msg::QueryServices), 0);
    }

    void otherConsolesAreToldApart() {
        DiscoveryRig rig;
        const JausId ocu{201, 1, 1};
        const ByteSpan none;
        QCOMPARE(rig.discovery.classify(ocu, msg::ReportHeartbeatPulse, none),
                 DiscoveryClient::Sender::Vehicle);
        const Bytes ident = encode(ReportIdentification{IdQueryType::Subsystem, IdType::Ocu, "OCU-201"});
        QCOMPARE(rig.discovery.classify(ocu, msg::ReportIdentification, ident),
                 DiscoveryClient::Sender::NewConsole);
        QCOMPARE(rig.discovery.classify(ocu, msg::ReportHeartbeatPulse, none),
                 DiscoveryClient::Sender::Console);
        const Bytes ugv = encode(ugvIdent("UGV-126"));
        QCOMPARE(rig.discovery.classify({126, 1, 1}, msg::ReportIdentification, ugv),
                 DiscoveryClient::Sender::Vehicle);
    }

    void answersAsASubsystem() {
        DiscoveryRig rig;
        const JausId asker{77, 1, 1};
        QVERIFY(rig.table.answer(msg::QueryIdentification, asker,
                                 encode(QueryIdentification{IdQueryType::Subsystem})));
        QVERIFY(rig.table.answer(msg::QueryIdentification, asker,
                                 encode(QueryIdentification{IdQueryType::Node})));
        QVERIFY(rig.table.answer(msg::QueryServices, asker, encode(QueryServices{})));
        QVERIFY(rig.table.answer(msg::QueryServiceList, asker, encode(QueryServiceList{})));
        QCOMPARE(rig.out.sent.size(), std::size_t(4));
        auto ri = decodeReportIdentification(rig.out.sent[0].payload);
        QVERIFY(ri && ri->type == IdType::Ocu && ri->identification == "OCU-200");
        QCOMPARE(decodeReportIdentification(rig.out.sent[1].payload)->type, IdType::Node);
        auto rs = decodeReportServices(rig.out.sent[2].payload);
        QVERIFY(rs && rs->nodes.size() == 1 && rs->nodes[0].components[0].services.size() == 5);
        // Transport, Events, Liveness, Discovery and, for a console that may hold a vehicle,
        // HandoffController.
        QCOMPARE(QString::fromStdString(rs->nodes[0].components[0].services.back().uri),
                 QStringLiteral("urn:jaus:jss:iop:HandoffController"));
        auto sl = decodeReportServiceList(rig.out.sent[3].payload);
        QVERIFY(sl && sl->subsystems.size() == 1 && sl->subsystems[0].subsystem == 200);
        for (auto& s : rig.out.sent)
            QCOMPARE(s.destination, asker);
    }
};

QTEST_GUILESS_MAIN(TestDiscoveryClient)
#include "test_discovery_client.moc"
