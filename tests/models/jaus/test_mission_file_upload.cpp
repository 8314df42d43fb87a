// A mission saved as GeoJSON, opened again and uploaded again gives byte-identical SetElement payloads:
// the plan as the panel edits it (the platform's defaults, an edited speed and tolerance, a waypoint dragged
// to an awkward position), written and read back through the panel's file functions, mapped as the JAUS
// bridge maps a MissionUpload and uploaded by the MissionClient to a vehicle played by hand, local
// (placed through the vehicle's poses) and global, a short route and one long enough to go in parts.
#include "models/jaus/MissionGeoJson.h"
#include "models/jaus/MissionPlan.h"
#include "tests/protocols/jaus/clients/MissionRig.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace ocu;
using namespace ocu::jaus;
using namespace ocu::jaus::test;

namespace {

// Every SetElement payload the client sends for `waypoints`, each confirmed as a vehicle would.
std::vector<Bytes> setElementPayloads(const QVector<MissionWaypoint>& waypoints, bool global) {
    MissionRig rig;
    RemoteSubsystem& r = rig.missionVehicle();
    std::vector<MissionPoint> points; // as JausBridgeCommands maps a MissionUpload
    for (const MissionWaypoint& w : waypoints)
        points.push_back(MissionPoint{w.lat, w.lon, w.speed, w.tolerance});
    std::vector<Bytes> out;
    if (!rig.mission.upload(r.id(), points, global))
        return out;
    rig.confirmLast(r, msg::DeleteElement);
    while (rig.mission.step(r.id()) == MissionClient::Step::Sending)
        rig.confirmLast(r, msg::SetElement);
    for (const Sent& s : rig.out.sent)
        if (s.id() == msg::SetElement)
            out.push_back(s.payload);
    return out;
}

// The plan as an operator builds it on the map.
void build(MissionPlan& plan, int n) {
    MissionPlan::Defaults d;
    d.speed = 1.35;
    d.tolerance = 0.8;
    plan.setDefaults(d);
    for (int i = 0; i < n; ++i)
        plan.append(plan.makeWaypoint(48.1001234567891 + 0.0000731234567 * i,
                                      11.5000987654321 + 0.0000413579246 * (i % 17)));
    plan.setSpeed(1, 2.25);
    plan.setTolerance(2, 0.333);
    plan.move(n - 1, 48.10037777777777, 11.50011111111111);
}

} // namespace

class TestMissionFileUpload : public QObject {
    Q_OBJECT
private slots:
    void savedReopenedAndUploadedAgainGivesTheSameBytes_data() {
        QTest::addColumn<int>("waypoints");
        QTest::addColumn<bool>("global");
        QTest::newRow("5 local") << 5 << false;
        QTest::newRow("5 global") << 5 << true;
        QTest::newRow("400 local, in parts") << 400 << false;
        QTest::newRow("400 global, in parts") << 400 << true;
    }
    void savedReopenedAndUploadedAgainGivesTheSameBytes() {
        QFETCH(int, waypoints);
        QFETCH(bool, global);
        MissionPlan plan;
        build(plan, waypoints);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("mission.geojson"));
        QString why;
        QVERIFY2(writeMissionGeoJsonFile(path, plan.waypoints(), &why), qPrintable(why));
        const auto read = readMissionGeoJsonFile(path, &why);
        QVERIFY2(read, qPrintable(why));
        MissionPlan reopened; // the panel opens a file into a plan
        reopened.replace(*read, QStringLiteral("Open mission.geojson"));

        const std::vector<Bytes> first = setElementPayloads(plan.waypoints(), global);
        const std::vector<Bytes> again = setElementPayloads(reopened.waypoints(), global);
        QVERIFY(!first.empty());
        if (waypoints > 255)
            QVERIFY(first.size() > 1);
        QCOMPARE(again.size(), first.size());
        for (std::size_t i = 0; i < first.size(); ++i)
            QVERIFY2(again[i] == first[i], qPrintable(QStringLiteral("SetElement %1 differs").arg(i)));

        // The bytes do carry the positions: a waypoint moved by a centimetre changes them.
        QVector<MissionWaypoint> moved = plan.waypoints();
        moved[0].lat += 1e-7;
        QVERIFY(setElementPayloads(moved, global) != first);
    }
};

QTEST_GUILESS_MAIN(TestMissionFileUpload)
#include "test_mission_file_upload.moc"
