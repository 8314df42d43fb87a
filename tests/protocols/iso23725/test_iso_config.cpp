// The site configuration's iso23725 section: every key read, defaults, and strict errors naming the key.
#include "protocols/iso23725/IsoConfig.h"

#include "protocols/common/ConfigReader.h"

#include <QtTest>

using namespace ocu;
using namespace ocu::iso23725;

namespace {
struct Parsed {
    IsoConfig config;
    std::vector<std::string> errors;
};
Parsed parseFile(const char* name) {
    auto doc = ConfigDocument::load(std::string(OCU_ISO_TEST_DATA) + "/" + name);
    if (!doc)
        return {IsoConfig{}, {doc.error()}};
    ConfigErrors errors;
    ConfigObject root(*doc, "", errors);
    auto section = root.object("iso23725");
    IsoConfig c = parseIsoConfig(*section);
    root.finish();
    return {c, errors.messages()};
}
} // namespace

class TestIsoConfig : public QObject {
    Q_OBJECT
private slots:
    void fullSection() {
        auto parsed = parseFile("site_iso_full.json");
        auto& c = parsed.config;
        auto& errors = parsed.errors;
        QVERIFY2(errors.empty(), errors.empty() ? "" : errors[0].c_str());
        QCOMPARE(c.fmsId, std::string("1b9e6a40-3c2d-4f87-8e15-6a7b9c0d2e41"));
        QVERIFY(c.sendPositions);
        QCOMPARE(c.positionRateHz, 5.0);
        QCOMPARE(c.plausibility, (PoseLimits{8000, 20, 15}));
        QCOMPARE(IsoConfig{}.plausibility, (PoseLimits{50000, 30, 50})); // the safe defaults
        QCOMPARE(c.allStopAckTimeout.count(), 1500);
        QCOMPARE(c.links.size(), std::size_t(2));
        QCOMPARE(c.links[0].ws.tls.caFile, std::string("/etc/ocu/ca.pem"));
        QVERIFY(c.links[0].ws.tls.verifyHostname);
        QCOMPARE(c.links[0].ws.pingInterval.count(), 2000);
        QCOMPARE(c.links[0].ws.maxFrameBytes, std::size_t(1048576));
        QCOMPARE(c.interfaceDiagnosticPeriod.count(), 30000);
        // Q10: the map service's own socket takes the link's TLS files and timing, always as a client.
        QCOMPARE(c.links[0].mapWs.url, std::string("wss://ahs.example:8444/map"));
        QCOMPARE(c.links[0].mapWs.role, WsRole::Client);
        QCOMPARE(c.links[0].mapWs.tls.certFile, std::string("/etc/ocu/me.pem"));
        QCOMPARE(c.links[0].mapWs.pingInterval.count(), 2000);
        QVERIFY(c.links[1].mapWs.url.empty()); // shares the main socket
        QCOMPARE(c.links[1].ws.role, WsRole::Service);
        QCOMPARE(c.links[1].ws.deadAfter.count(), 15000);                     // default
        QCOMPARE(c.links[1].ws.maxFrameBytes, std::size_t(16 * 1024 * 1024)); // default
        QCOMPARE(c.fleet.size(), std::size_t(1));
        QCOMPARE(c.fleet[0].type, std::string("Shovel"));
        QVERIFY(!c.fleet[0].autonomous);
        QVERIFY(!c.rules.repairTimestamps);
        QVERIFY(c.rules.acceptAliases);
    }

    void errorsNameTheKey() {
        auto parsed = parseFile("site_iso_bad.json");
        auto& errors = parsed.errors;
        QStringList all;
        for (auto& e : errors)
            all << QString::fromStdString(e);
        const QString text = all.join("\n");
        QVERIFY2(text.contains("fmsId") && text.contains("GUID"), qPrintable(text));
        QVERIFY2(text.contains("must start with ws:// or wss://"), qPrintable(text));
        QVERIFY2(text.contains("rol"), qPrintable(text));
        QVERIFY2(text.contains("Hauler"), qPrintable(text));
        QVERIFY2(text.contains("positionRateHz"), qPrintable(text));
        QVERIFY2(text.contains("mapUrl"), qPrintable(text));
        QVERIFY(errors.size() >= 6);
    }
};

QTEST_GUILESS_MAIN(TestIsoConfig)
#include "test_iso_config.moc"
