// The mission plan model and the mission files: edits and their undo, length and ETA, the defaults from the
// platform specifications, GeoJSON round trips, GPX and KML imports through OGR, bad files refused.
#include "models/jaus/MissionGeoJson.h"
#include "models/jaus/MissionImport.h"
#include "models/jaus/MissionPlan.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

using namespace ocu;

namespace {

MissionWaypoint wp(double lat, double lon, double speed = 1.5, double tol = 2) {
    return MissionWaypoint{lat, lon, speed, tol};
}

QString write(const QTemporaryDir& dir, const QString& name, const QByteArray& bytes) {
    const QString path = dir.filePath(name);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        qFatal("cannot write %s", qPrintable(path));
    f.write(bytes);
    return path;
}

// Points of a route a few hundred metres long near Munich, with digits to the last bit.
QVector<MissionWaypoint> route() {
    return {wp(48.137154123456789, 11.576124987654321, 1.25, 1.5), wp(48.1375, 11.5770, 2.0, 0.75),
            wp(48.13801, 11.5779999, 0.1 + 0.2, 3), wp(48.1385, 11.5781, 0, 0),
            wp(48.13912345, 11.57654321, 4, 2.5)};
}

double metresBetween(const MissionWaypoint& a, const MissionWaypoint& b) {
    return MissionPlan::distanceM(a.lat, a.lon, b.lat, b.lon);
}

} // namespace

class TestMissionPlan : public QObject {
    Q_OBJECT
private slots:
    void insertMoveDeleteAndUndo() {
        MissionPlan plan;
        QSignalSpy changed(&plan, &MissionPlan::changed);
        plan.append(wp(48.0, 11.0));
        plan.append(wp(48.001, 11.0));
        plan.insert(1, wp(48.0005, 11.001));
        QCOMPARE(plan.size(), 3);
        QCOMPARE(plan.at(1).lon, 11.001);
        plan.move(1, 48.0006, 11.002);
        QCOMPARE(plan.at(1).lat, 48.0006);
        QCOMPARE(changed.last().at(0).toInt(), 1); // moved in place
        plan.remove(0);
        QCOMPARE(plan.size(), 2);
        QCOMPARE(plan.at(0).lat, 48.0006);
        QCOMPARE(plan.undoStack()->count(), 5);
        plan.undo(); // the delete
        QCOMPARE(plan.size(), 3);
        QCOMPARE(plan.at(0).lat, 48.0);
        plan.undo(); // the move
        QCOMPARE(plan.at(1).lat, 48.0005);
        plan.undo(); // the insert
        QCOMPARE(plan.size(), 2);
        plan.redo();
        plan.redo();
        QCOMPARE(plan.at(1).lat, 48.0006);
        QCOMPARE(plan.size(), 3);
        // Out of range: nothing, and no undo step.
        const int steps = plan.undoStack()->count();
        plan.remove(7);
        plan.move(-1, 1, 1);
        plan.insert(9, wp(1, 1));
        QCOMPARE(plan.undoStack()->count(), steps);
    }

    void oneDragIsOneUndoStep() {
        MissionPlan plan;
        plan.append(wp(48.0, 11.0));
        plan.append(wp(48.001, 11.0));
        for (int i = 1; i <= 20; ++i)
            plan.move(1, 48.001 + i * 1e-5, 11.0, /*gesture*/ 7);
        for (int i = 1; i <= 5; ++i)
            plan.move(1, 48.002 + i * 1e-5, 11.0, /*gesture*/ 8);
        QCOMPARE(plan.undoStack()->count(), 4); // two adds, two drags
        plan.undo();
        QCOMPARE(plan.at(1).lat, 48.001 + 20 * 1e-5);
        plan.undo();
        QCOMPARE(plan.at(1).lat, 48.001);
    }

    void speedToleranceAndReplace() {
        MissionPlan plan;
        plan.replace(route(), QStringLiteral("open"));
        QCOMPARE(plan.waypoints(), route());
        plan.setSpeed(0, 3);
        plan.setTolerance(0, 4);
        plan.setSpeed(0, -1);      // refused
        plan.setTolerance(0, 101); // beyond the wire's 0 to 100 m
        QCOMPARE(plan.at(0).speed, 3.0);
        QCOMPARE(plan.at(0).tolerance, 4.0);
        plan.setDefaults({0.8, 1.2});
        plan.fillDefaults();
        QCOMPARE(plan.at(3).speed, 0.8);
        QCOMPARE(plan.at(3).tolerance, 1.2);
        plan.undo();
        QCOMPARE(plan.at(3).speed, 0.0);
        plan.undo(); // the tolerance
        plan.undo(); // the speed
        QCOMPARE(plan.waypoints(), route());
    }

    void lengthAndEta() {
        MissionPlan plan;
        // About 111.2 m per 0.001° of latitude at 48°; legs at 2 m/s and 1 m/s.
        plan.append(wp(48.000, 11.0, 5));
        plan.append(wp(48.001, 11.0, 2));
        plan.append(wp(48.002, 11.0, 1));
        const double leg = MissionPlan::distanceM(48.000, 11.0, 48.001, 11.0);
        QVERIFY(std::abs(leg - 111.2) < 0.3);
        QVERIFY(std::abs(plan.lengthM() - 2 * leg) < 0.01);
        QVERIFY(std::abs(plan.etaS() - (leg / 2 + leg / 1)) < 0.01);
        // From the vehicle's position: one more leg at the first waypoint's speed.
        const QPair<double, double> from{47.999, 11.0};
        QVERIFY(std::abs(plan.lengthM(from) - 3 * leg) < 0.01);
        QVERIFY(std::abs(plan.etaS(from) - (leg / 5 + leg / 2 + leg)) < 0.01);
        // East-west at 48°: cos(48°) of the degree's length.
        QVERIFY(std::abs(MissionPlan::distanceM(48, 11, 48, 11.001) - 74.6) < 0.3);
        // A speed of 0 drives at the default.
        plan.setDefaults({0.5, 2});
        plan.setSpeed(2, 0);
        QVERIFY(std::abs(plan.etaS() - (leg / 2 + leg / 0.5)) < 0.01);
    }

    void defaultsFromThePlatform() {
        QCOMPARE(MissionPlan::defaultsFor(std::nullopt), MissionPlan::Defaults{});
        JausPlatform p;
        p.maxForwardSpeed = 3.0;
        p.front = 1.2;
        p.back = 0.6;
        const MissionPlan::Defaults d = MissionPlan::defaultsFor(p);
        QCOMPARE(d.speed, 1.5);
        QVERIFY(std::abs(d.tolerance - 1.8) < 1e-9);
        JausPlatform small;
        small.front = 0.2;
        small.back = 0.1;
        QCOMPARE(MissionPlan::defaultsFor(small).tolerance, 1.0); // at least 1 m
        QCOMPARE(MissionPlan::defaultsFor(small).speed, 1.0);     // none reported
        MissionPlan plan;
        plan.setDefaults(d);
        QCOMPARE(plan.makeWaypoint(1, 2), (MissionWaypoint{1, 2, 1.5, d.tolerance}));
    }

    void geoJsonRoundTripIsIdentical() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("m.geojson"));
        QString error;
        QVERIFY(writeMissionGeoJsonFile(path, route(), &error));
        const auto read = readMissionGeoJsonFile(path, &error);
        QVERIFY2(read, qPrintable(error));
        QCOMPARE(*read, route()); // bit for bit
        const QString again = dir.filePath(QStringLiteral("again.geojson"));
        QVERIFY(writeMissionGeoJsonFile(again, *read, &error));
        QFile a(path), b(again);
        QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
        QCOMPARE(a.readAll(), b.readAll());
        // The format: a FeatureCollection with one LineString, longitude first, per-point properties.
        const QJsonObject root = QJsonDocument::fromJson(writeMissionGeoJson(route())).object();
        QCOMPARE(root.value("type").toString(), QString("FeatureCollection"));
        const QJsonObject f = root.value("features").toArray().at(0).toObject();
        QCOMPARE(f.value("geometry").toObject().value("type").toString(), QString("LineString"));
        QCOMPARE(
            f.value("geometry").toObject().value("coordinates").toArray().at(1).toArray().at(0).toDouble(),
            11.5770);
        QCOMPARE(
            f.value("properties").toObject().value("waypoints").toArray().at(1).toObject().value("speed"),
            QJsonValue(2.0));
    }

    void geoJsonWithoutPropertiesOrAsBareGeometry() {
        const auto line =
            readMissionGeoJson("{\"type\":\"LineString\",\"coordinates\":[[11,48],[11.1,48.1]]}", nullptr);
        QVERIFY(line);
        QCOMPARE(line->size(), 2);
        QCOMPARE(line->at(1), (MissionWaypoint{48.1, 11.1, 0, 0}));
        // One waypoint: a Point feature.
        const auto point =
            readMissionGeoJson("{\"type\":\"FeatureCollection\",\"features\":[{\"type\":\"Feature\","
                               "\"geometry\":{\"type\":\"Point\",\"coordinates\":[11,48]},"
                               "\"properties\":{\"waypoints\":[{\"speed\":2,\"tolerance\":3}]}}]}",
                               nullptr);
        QVERIFY(point);
        QCOMPARE(*point, (QVector<MissionWaypoint>{{48, 11, 2, 3}}));
    }

    void badGeoJsonIsRefusedWithAMessage_data() {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("says");
        QTest::newRow("not json") << QByteArray("{\"type\": ") << "not JSON";
        QTest::newRow("binary") << QByteArray("\x89PNG\r\n\x1a\n\0\0", 10) << "not JSON";
        QTest::newRow("no line") << QByteArray("{\"type\":\"Polygon\",\"coordinates\":[[[1,2],[2,3],[1,2]]]}")
                                 << "no GeoJSON LineString";
        QTest::newRow("empty line") << QByteArray("{\"type\":\"LineString\",\"coordinates\":[]}")
                                    << "no positions";
        QTest::newRow("bad point") << QByteArray("{\"type\":\"LineString\",\"coordinates\":[[1],[2,3]]}")
                                   << "position 1";
        QTest::newRow("text point") << QByteArray("{\"type\":\"LineString\",\"coordinates\":[[\"a\",\"b\"]]}")
                                    << "position 1";
        QTest::newRow("latitude") << QByteArray("{\"type\":\"LineString\",\"coordinates\":[[1,2],[11,95]]}")
                                  << "position 2 lies outside WGS84";
        QTest::newRow("count")
            << QByteArray("{\"type\":\"Feature\",\"geometry\":{\"type\":\"LineString\",\"coordinates\":"
                          "[[1,2],[3,4]]},\"properties\":{\"waypoints\":[{\"speed\":1}]}}")
            << "one {speed, tolerance} per position";
        QTest::newRow("negative")
            << QByteArray("{\"type\":\"Feature\",\"geometry\":{\"type\":\"LineString\",\"coordinates\":"
                          "[[1,2]]},\"properties\":{\"waypoints\":[{\"speed\":-1,\"tolerance\":1}]}}")
            << "waypoint 1";
        QTest::newRow("tolerance")
            << QByteArray("{\"type\":\"Feature\",\"geometry\":{\"type\":\"LineString\",\"coordinates\":"
                          "[[1,2]]},\"properties\":{\"waypoints\":[{\"speed\":1,\"tolerance\":250}]}}")
            << "tolerance 0 to 100 m";
        QTest::newRow("text speed")
            << QByteArray("{\"type\":\"Feature\",\"geometry\":{\"type\":\"LineString\",\"coordinates\":"
                          "[[1,2]]},\"properties\":{\"waypoints\":[{\"speed\":\"fast\"}]}}")
            << "waypoint 1";
    }
    void badGeoJsonIsRefusedWithAMessage() {
        QFETCH(QByteArray, json);
        QFETCH(QString, says);
        QString error;
        QVERIFY(!readMissionGeoJson(json, &error));
        QVERIFY2(error.contains(says), qPrintable(error));
    }

    void filesThatCannotBeReadOrWritten() {
        QTemporaryDir dir;
        QString error;
        QVERIFY(!readMissionGeoJsonFile(dir.filePath(QStringLiteral("none.geojson")), &error));
        QVERIFY(error.contains("none.geojson"));
        QVERIFY(!writeMissionGeoJsonFile(dir.filePath(QStringLiteral("x.geojson")), {}, &error)); // nothing
        QVERIFY(error.contains("no waypoints"));
        QVERIFY(
            !writeMissionGeoJsonFile(dir.filePath(QStringLiteral("no/such/dir/x.geojson")), route(), &error));
        QVERIFY2(error.contains("cannot be written"), qPrintable(error));
    }

    void gpxRouteImportsToTheSamePoints() {
        QTemporaryDir dir;
        QByteArray gpx =
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<gpx version=\"1.1\" creator=\"test\" xmlns=\"http://www.topografix.com/GPX/1/1\">\n"
            "  <wpt lat=\"1.0\" lon=\"1.0\"><name>elsewhere</name></wpt>\n"
            "  <rte><name>patrol</name>\n";
        for (const MissionWaypoint& w : route())
            gpx += QStringLiteral("    <rtept lat=\"%1\" lon=\"%2\"/>\n")
                       .arg(w.lat, 0, 'g', 17)
                       .arg(w.lon, 0, 'g', 17)
                       .toUtf8();
        gpx += "  </rte>\n</gpx>\n";
        const MissionFileRead r = importMissionRoute(write(dir, QStringLiteral("r.gpx"), gpx));
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(r.waypoints.size(), route().size());
        for (int i = 0; i < r.waypoints.size(); ++i) {
            QVERIFY2(metresBetween(r.waypoints[i], route()[i]) < 0.01, qPrintable(QString::number(i)));
            QCOMPARE(r.waypoints[i].speed, 0.0); // the plan's defaults fill them
        }
    }

    void gpxTrackImportsWhenThereIsNoRoute() {
        QTemporaryDir dir;
        const QByteArray gpx =
            "<?xml version=\"1.0\"?>\n"
            "<gpx version=\"1.1\" creator=\"test\" xmlns=\"http://www.topografix.com/GPX/1/1\">\n"
            "  <trk><name>t</name><trkseg>\n"
            "    <trkpt lat=\"48.1\" lon=\"11.1\"/><trkpt lat=\"48.2\" lon=\"11.2\"/><trkpt lat=\"48.3\" "
            "lon=\"11.3\"/>\n"
            "  </trkseg></trk>\n"
            "</gpx>\n";
        const MissionFileRead r = importMissionRoute(write(dir, QStringLiteral("t.gpx"), gpx));
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(r.waypoints.size(), 3);
        QVERIFY(metresBetween(r.waypoints[2], wp(48.3, 11.3)) < 0.01);
    }

    void kmlLineImportsToTheSamePoints() {
        QTemporaryDir dir;
        QByteArray kml =
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<kml xmlns=\"http://www.opengis.net/kml/2.2\"><Document>\n"
            "  <Placemark><name>start</name><Point><coordinates>1,1,0</coordinates></Point></Placemark>\n"
            "  <Placemark><name>patrol</name><LineString><coordinates>\n";
        for (const MissionWaypoint& w : route())
            kml += QStringLiteral("%1,%2,0 ").arg(w.lon, 0, 'g', 17).arg(w.lat, 0, 'g', 17).toUtf8();
        kml += "\n  </coordinates></LineString></Placemark>\n</Document></kml>\n";
        const MissionFileRead r = importMissionRoute(write(dir, QStringLiteral("r.kml"), kml));
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(r.waypoints.size(), route().size());
        for (int i = 0; i < r.waypoints.size(); ++i)
            QVERIFY2(metresBetween(r.waypoints[i], route()[i]) < 0.01, qPrintable(QString::number(i)));
    }

    void badRouteFilesAreRefusedWithAMessage_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("bytes");
        QTest::newRow("truncated gpx")
            << "a.gpx" << QByteArray("<?xml version=\"1.0\"?><gpx><rte><rtept lat=");
        QTest::newRow("empty gpx") << "b.gpx"
                                   << QByteArray("<?xml version=\"1.0\"?><gpx version=\"1.1\" "
                                                 "xmlns=\"http://www.topografix.com/GPX/1/1\"></gpx>");
        QTest::newRow("kml without geometry")
            << "c.kml"
            << QByteArray("<?xml version=\"1.0\"?><kml "
                          "xmlns=\"http://www.opengis.net/kml/2.2\"><Document>"
                          "</Document></kml>");
        QTest::newRow("garbage") << "d.gpx" << QByteArray("\x00\x01\x02garbage\xff\xfe", 12);
        QTest::newRow("empty file") << "e.kml" << QByteArray();
    }
    void badRouteFilesAreRefusedWithAMessage() {
        QFETCH(QString, name);
        QFETCH(QByteArray, bytes);
        QTemporaryDir dir;
        const MissionFileRead r = importMissionRoute(write(dir, name, bytes));
        QVERIFY(!r.ok());
        QVERIFY(r.waypoints.isEmpty());
        QVERIFY2(r.error.startsWith(dir.filePath(name)), qPrintable(r.error));
        QVERIFY(r.error.size() > dir.filePath(name).size() + 4); // says why
        const MissionFileRead none = importMissionRoute(dir.filePath(QStringLiteral("missing.gpx")));
        QVERIFY(!none.ok() && none.error.contains("missing.gpx"));
    }
};

QTEST_GUILESS_MAIN(TestMissionPlan)
#include "test_mission_plan.moc"
