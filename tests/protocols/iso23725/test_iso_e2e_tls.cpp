// OCU <-> simulated AHS over wss:// with a test CA made by the test (openssl command): the full exchange
// works, a wrong CA and a wrong host name are refused (verification on by default), and mutual TLS with a
// client certificate works.
#include "sim/iso23725/SimulatedAhs.h"
#include "tests/protocols/iso23725/IsoTestSupport.h"

#include <QtTest>

#include <cstdlib>
#include <fstream>

using namespace isotest;
using namespace ocu::sim;

namespace {

bool run(const std::string& cmd) {
    return std::system((cmd + " >/dev/null 2>&1").c_str()) == 0;
}

// CA + leaf certificate for 127.0.0.1 (IP SAN only), EC P-256 keys.
bool makeCa(const std::string& dir, const std::string& name) {
    return run(
        "openssl req -x509 -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes -days 2 -subj '/CN=" +
        name +
        "' -addext basicConstraints=critical,CA:TRUE -addext keyUsage=critical,keyCertSign,cRLSign -keyout " +
        dir + "/" + name + ".key -out " + dir + "/" + name + ".pem");
}
bool makeLeaf(const std::string& dir, const std::string& ca, const std::string& name,
              const std::string& ext) {
    std::string e = dir + "/" + name + ".ext";
    std::ofstream(e) << ext << "\nbasicConstraints=CA:FALSE\n";
    return run("openssl req -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes -subj '/CN=" + name +
               "' -keyout " + dir + "/" + name + ".key -out " + dir + "/" + name + ".csr") &&
           run("openssl x509 -req -days 2 -in " + dir + "/" + name + ".csr -CA " + dir + "/" + ca +
               ".pem -CAkey " + dir + "/" + ca + ".key -CAcreateserial -extfile " + e + " -out " + dir + "/" +
               name + ".pem");
}

} // namespace

class TestIsoEndToEndTls : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    std::string d;

    SimulatedAhsConfig simConfig() {
        SimulatedAhsConfig c;
        c.truckCount = 4;
        c.positionRateHz = 5;
        c.tls = true;
        c.certFile = d + "/server.pem";
        c.keyFile = d + "/server.key";
        return c;
    }
    IsoConfig stackConfig(const std::string& url, const std::string& ca) {
        IsoConfig ic;
        ic.links.push_back(IsoLinkConfig{"ahs", {}, {}});
        auto& ws = ic.links[0].ws;
        ws.url = url;
        ws.tls.caFile = ca;
        ws.backoffMin = std::chrono::milliseconds(100);
        ws.backoffMax = std::chrono::milliseconds(300);
        return ic;
    }

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        d = m_dir.path().toStdString();
        QVERIFY(makeCa(d, "ca"));
        QVERIFY(makeCa(d, "otherca"));
        QVERIFY(makeLeaf(d, "ca", "server", "subjectAltName=IP:127.0.0.1\nextendedKeyUsage=serverAuth"));
        QVERIFY(makeLeaf(d, "ca", "client", "extendedKeyUsage=clientAuth"));
        // Signed by the right CA but for another address: only the host name check can refuse it.
        QVERIFY(makeLeaf(d, "ca", "othername", "subjectAltName=IP:127.0.0.2\nextendedKeyUsage=serverAuth"));
        QVERIFY(run("openssl x509 -in " + d +
                    "/server.pem -noout -ext subjectAltName | grep -q 'IP Address:127.0.0.1'"));
    }

    void wssEndToEnd() {
        auto cfg = simConfig();
        auto ahs = std::make_unique<SimulatedAhs>(cfg);
        QVERIFY2(ahs->start(), ahs->lastError().c_str());
        QVERIFY(ahs->url().rfind("wss://127.0.0.1:", 0) == 0);
        const auto port = ahs->port();
        // The FMS expects one truck of the AHS with another HID, and a truck the AHS does not have.
        auto ic = stackConfig(ahs->url(), d + "/ca.pem");
        auto expected = ahs->fleet().front();
        expected.hid = "T-WRONG";
        ic.fleet.push_back(expected);
        ic.fleet.push_back(
            Equipment{"9b8a7c6d-5e4f-4a3b-8c2d-1e0f9a8b7c6d", "HT99", "HaulTruck", "", "", true, 12.0, 7.0});
        Recorder rec;
        IsoStack stack(ic, rec);
        QVERIFY(stack.start());
        QVERIFY(waitFor([&] { return rec.link("ahs") == LinkState::Up; }));
        QVERIFY(waitFor([&] { return !ahs->stats().fmsFirstMessages.empty(); }));
        QCOMPARE(ahs->stats().fmsFirstMessages.front(), std::string("FleetDefinitionV2"));
        QVERIFY(waitFor([&] {
            return rec.hasDiscrepancy("at the AHS, 'T-WRONG' at the FMS") &&
                   rec.hasDiscrepancy("machine HT99 (9b8a7c6d-5e4f-4a3b-8c2d-1e0f9a8b7c6d) is missing");
        }));
        QVERIFY(
            waitFor([&] { return rec.machinesWith([](auto& m) { return m.position.has_value(); }) == 4; }));
        QVERIFY(waitFor([&] { return rec.with([&] { return rec.maps; }) == 1; }));
        QVERIFY(stack.map("ahs")->summary.documentCount >= 3);
        QVERIFY(sentOne(outcome([&](auto done) { stack.allStopApply("ahs", done); })));
        QVERIFY(waitFor([&] { return rec.allStop() == AllStopState::On; }));
        QVERIFY(waitFor([&] { return ahs->stats().movingTrucks == 0; }));
        QVERIFY(sentOne(outcome([&](auto done) { stack.allStopRemove("ahs", done); })));
        QVERIFY(waitFor([&] { return rec.allStop() == AllStopState::Off; }));
        QCOMPARE(stack.counters().get("ws.tls.failed"), 0u);

        // Killed: UNKNOWN meanwhile, commands refused; restarted on the same port: state rebuilt over wss.
        ahs->stop();
        QVERIFY(waitFor([&] { return rec.link("ahs") == LinkState::Down; }));
        QCOMPARE(rec.allStop(), AllStopState::Unknown);
        QCOMPARE(rec.machinesWith([](auto& m) { return m.stateKnown; }), 0);
        QVERIFY(refusedOne(outcome([&](auto done) { stack.allStopApply("ahs", done); }),
                           ocu::OutcomeReason::LinkDown));
        QVERIFY(waitFor([&] { return rec.hasEvent("all-stop Apply refused: link 'ahs' is DOWN"); }));
        ahs.reset();
        cfg.port = port;
        auto again = std::make_unique<SimulatedAhs>(cfg);
        QVERIFY2(again->start(), again->lastError().c_str());
        QVERIFY(waitFor([&] { return rec.link("ahs") == LinkState::Up; }));
        QVERIFY(waitFor(
            [&] { return rec.machinesWith([](auto& m) { return m.stateKnown && m.position; }) == 4; }));
        QVERIFY(waitFor([&] { return rec.allStop() == AllStopState::Off; }));
        QCOMPARE(again->counters().get("sim.allstop.on"), 0u);
        stack.stop();
    }

    void wrongCaRefused() {
        SimulatedAhs ahs(simConfig());
        QVERIFY(ahs.start());
        Recorder rec;
        IsoStack stack(stackConfig(ahs.url(), d + "/otherca.pem"), rec);
        QVERIFY(stack.start());
        QVERIFY(waitFor([&] { return stack.counters().get("ws.tls.failed") >= 2; }));
        QCOMPARE(rec.link("ahs"), LinkState::Down);
        QCOMPARE(stack.counters().get("ws.sessions.opened"), 0u);
        stack.stop();
    }

    void hostnameVerifiedByDefault() {
        // The service presents a valid certificate for 127.0.0.2 while we connect to 127.0.0.1 (no name
        // resolution involved, so the test also runs where "localhost" is not in /etc/hosts).
        auto sc = simConfig();
        sc.certFile = d + "/othername.pem";
        sc.keyFile = d + "/othername.key";
        SimulatedAhs ahs(sc);
        QVERIFY(ahs.start());
        const std::string url = ahs.url();
        QVERIFY(url.rfind("wss://127.0.0.1:", 0) == 0);
        {
            Recorder rec;
            IsoStack stack(stackConfig(url, d + "/ca.pem"), rec);
            QVERIFY(stack.start());
            QVERIFY(waitFor([&] { return stack.counters().get("ws.tls.failed") >= 2; }));
            QCOMPARE(stack.counters().get("ws.sessions.opened"), 0u);
            stack.stop();
        }
        {
            Recorder rec;
            auto cfg = stackConfig(url, d + "/ca.pem");
            cfg.links[0].ws.tls.verifyHostname = false;
            IsoStack stack(cfg, rec);
            QVERIFY(stack.start());
            QVERIFY(waitFor([&] { return rec.link("ahs") == LinkState::Up; }));
            stack.stop();
        }
    }

    void mutualTls() {
        auto sc = simConfig();
        sc.clientCaFile = d + "/ca.pem";
        SimulatedAhs ahs(sc);
        QVERIFY(ahs.start());
        {
            Recorder rec; // no client certificate: refused by the service
            IsoStack stack(stackConfig(ahs.url(), d + "/ca.pem"), rec);
            QVERIFY(stack.start());
            QVERIFY(waitFor([&] { return stack.counters().get("link.connect_failed") >= 2; }));
            QCOMPARE(rec.link("ahs"), LinkState::Down);
            QVERIFY(!rec.with([&] { return rec.machines.size(); }));
            stack.stop();
        }
        {
            Recorder rec;
            auto cfg = stackConfig(ahs.url(), d + "/ca.pem");
            cfg.links[0].ws.tls.certFile = d + "/client.pem";
            cfg.links[0].ws.tls.keyFile = d + "/client.key";
            IsoStack stack(cfg, rec);
            QVERIFY(stack.start());
            QVERIFY(waitFor(
                [&] { return rec.machinesWith([](auto& m) { return m.position.has_value(); }) == 4; }));
            stack.stop();
        }
    }
};

QTEST_GUILESS_MAIN(TestIsoEndToEndTls)
#include "test_iso_e2e_tls.moc"
