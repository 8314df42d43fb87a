// ocu-sim as a separate process and a console that connects to it through the configuration ocu-sim
// writes (the two-host set-up of the README, on loopback).
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSet>
#include <QTemporaryDir>
#include <QtTest>

class TestOcuSim : public QObject {
    Q_OBJECT
private slots:
    void consoleConnectsToOcuSim() {
        QTemporaryDir dir;
        const QString cfg = dir.filePath("sim-site.json");
        QProcess sim;
        sim.start(OCU_SIM_BINARY, {"--duration", "100", "--ugvs", "1", "--trucks", "3", "--rollers", "1",
                                   "--separate-map-service", "--write-config", cfg});
        QVERIFY(sim.waitForStarted(10000));
        // The file appears before its text is complete: wait until it parses as the whole configuration.
        QJsonObject site;
        auto written = [&] {
            QFile f(cfg);
            if (!f.open(QIODevice::ReadOnly))
                return false;
            QJsonParseError err{};
            site = QJsonDocument::fromJson(f.readAll(), &err).object();
            return err.error == QJsonParseError::NoError && site.contains("site") && site.contains("jaus") &&
                   site.contains("iso23725") && site.contains("osyris");
        };
        QTRY_VERIFY2_WITH_TIMEOUT(written(), sim.readAllStandardError().constData(), 30000);
        // The AHS's map service on its own socket (ISO 23725 Q10): the written link names it.
        const QJsonObject link = std::as_const(site)["iso23725"]["links"][0].toObject();
        QVERIFY(link["mapUrl"].toString().startsWith("ws://127.0.0.1:"));
        QVERIFY(link["mapUrl"].toString() != link["url"].toString());
        // The FMS fleet is written too: the manned shovel and light vehicle plus the 3 trucks.
        const QJsonArray fleet = std::as_const(site)["iso23725"]["fleet"].toArray();
        QCOMPARE(fleet.size(), 2 + 3);
        int autonomous = 0;
        for (const QJsonValue& m : fleet)
            autonomous += m["autonomous"].toBool() ? 1 : 0;
        QCOMPARE(autonomous, 3);

        QProcess ocu;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove("DISPLAY");
        ocu.setProcessEnvironment(env);
        // No --duration: the console runs until its stdin ends (closed below), then exits 0.
        ocu.start(OCU_BINARY, {"--config", cfg, "--no-sim", "--headless"});
        QVERIFY(ocu.waitForStarted(10000));
        QSet<QString> protocols, ids;
        QStringList discrepancies; // none: the console is configured with the simulator's own fleet
        bool mapComplete = false;
        QByteArray buf;
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < 60000 && !(protocols.size() == 3 && ids.size() >= 6 && mapComplete) &&
               ocu.state() == QProcess::Running) {
            ocu.waitForReadyRead(100);
            buf += ocu.readAllStandardOutput();
            int nl;
            while ((nl = buf.indexOf('\n')) >= 0) {
                const QJsonObject o = QJsonDocument::fromJson(buf.left(nl)).object();
                buf.remove(0, nl + 1);
                if (o.value("type") == "event" &&
                    o.value("text").toString().contains("discrepancy", Qt::CaseInsensitive))
                    discrepancies << o.value("text").toString();
                if (o.value("type") == "machine") {
                    protocols.insert(o.value("protocol").toString());
                    ids.insert(o.value("id").toString());
                } else if (o.value("type") == "event" && o.value("text").toString().startsWith("map from ")) {
                    mapComplete = mapComplete || o.value("text").toString().contains(" complete: ");
                }
            }
        }
        QVERIFY2(protocols.size() == 3, qPrintable(QStringList(protocols.values()).join(",") + " / " +
                                                   QString::fromUtf8(ocu.readAllStandardError())));
        QVERIFY(ids.contains("jaus:126"));
        QVERIFY(mapComplete);             // fetched over the separate map-service socket
        QVERIFY(ids.size() >= 1 + 3 + 2); // 1 UGV, 3 trucks, a paver and a roller
        // The trucks are known, so their fleet definition has been checked (the check runs when it arrives).
        QVERIFY2(discrepancies.isEmpty(), qPrintable(discrepancies.join("\n")));
        ocu.closeWriteChannel();
        QVERIFY(ocu.waitForFinished(20000));
        QCOMPARE(ocu.exitStatus(), QProcess::NormalExit);
        QCOMPARE(ocu.exitCode(), 0);
        sim.terminate(); // SIGTERM: ocu-sim stops its simulators and exits 0
        QVERIFY(sim.waitForFinished(10000));
        QCOMPARE(sim.exitStatus(), QProcess::NormalExit);
        QCOMPARE(sim.exitCode(), 0);
    }
    void positionRateOption() {
        // --position-rate HZ: 1..10 accepted (the simulator starts and runs), anything else refused.
        for (const char* bad : {"0", "11", "fast"}) {
            QProcess sim;
            sim.start(OCU_SIM_BINARY, {"--position-rate", bad, "--duration", "1"});
            QVERIFY(sim.waitForFinished(20000));
            QCOMPARE(sim.exitCode(), 2);
            QVERIFY(sim.readAllStandardError().contains("--position-rate must be a number 1..10"));
        }
        QProcess sim;
        sim.start(OCU_SIM_BINARY, {"--position-rate", "10", "--trucks", "2", "--ugvs", "0", "--rollers", "0",
                                   "--duration", "1"});
        QVERIFY(sim.waitForFinished(30000));
        QCOMPARE(sim.exitCode(), 0);
        QVERIFY(sim.readAllStandardOutput().contains("AHS with 2 trucks"));
    }
    void badInterfaceIsRefused() {
        QProcess sim;
        sim.start(OCU_SIM_BINARY, {"--interface", "not-an-address", "--duration", "1"});
        QVERIFY(sim.waitForFinished(20000));
        QCOMPARE(sim.exitCode(), 2);
        QVERIFY(sim.readAllStandardError().contains("is not an IPv4 address"));
    }
};

QTEST_GUILESS_MAIN(TestOcuSim)
#include "test_ocu_sim.moc"
