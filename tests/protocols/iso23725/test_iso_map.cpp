// ISO 23725 map model: the note's example chunk parses into roads/areas with tags; chunking, sequence and the
// ID rules (§10.2) are enforced with messages naming chunk and rule; MapConnectivityV1 routes.
#include "protocols/iso23725/MapModel.h"

#include <QtTest>

#include <fstream>
#include <sstream>

using namespace ocu::iso23725;

namespace {
std::string example() {
    std::ifstream in(OCU_ISO_TEST_DATA "/map_example.osm");
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}
std::string chunk(int seq, const std::string& body) {
    return "<?xml version=\"1.0\"?><osm version=\"0.6\" sequence=\"" + std::to_string(seq) + "\">" + body +
           "</osm>";
}
const std::string kNodes =
    R"(<node id="1" lat="-23.36" lon="119.73"/><node id="2" lat="-23.361" lon="119.731"/>)"
    R"(<node id="3" lat="-23.362" lon="119.73"/>)";
} // namespace

class TestIsoMap : public QObject {
    Q_OBJECT
private slots:
    void exampleChunk() {
        auto r = parseMapDocument({example()});
        QVERIFY2(r.ok(), r.ok() ? "" : r.error().c_str());
        QCOMPARE(r->nodes.size(), std::size_t(6));
        QCOMPARE(r->roads, std::vector<std::int64_t>{2001});
        QCOMPARE(r->areas, std::vector<std::int64_t>{4201});
        auto* road = r->way(2001);
        QCOMPARE(road->name(), std::string("North Ramp"));
        QCOMPARE(road->tag("autonomy"), std::string("mixed"));
        QCOMPARE(*road->changeset, 18241);
        QCOMPARE(r->way(4201)->defaultTask(), std::string("load"));
        QCOMPARE(*r->nodes.at(700001).ele, 512.3);
        // ENU around the centroid: node 700001 is south-east of 700003.
        QVERIFY(r->nodes.at(700001).enu.e > r->nodes.at(700003).enu.e);
        QVERIFY(r->nodes.at(700001).enu.n < r->nodes.at(700003).enu.n);
        QVERIFY(r->warnings.empty());
    }

    void chunksAndProgressAndRoundTrip() {
        auto r = parseMapDocument({example()});
        QVERIFY(r.ok());
        auto chunks = writeOsmChunks(*r, 3, 99);
        QCOMPARE(chunks.size(), std::size_t(3)); // 8 elements, 3 per chunk
        MapAssembler a;
        MapSummaryV1 s;
        s.documentCount = 3;
        s.nodeCount = 6;
        s.wayCount = 2;
        a.begin(s);
        for (int i = 0; i < 3; ++i) {
            auto p = a.addChunk(chunks[i]);
            QVERIFY2(p.ok(), p.ok() ? "" : p.error().c_str());
            QCOMPARE(p->received, i + 1);
            QCOMPARE(p->total, 3);
        }
        auto m = a.finish();
        QVERIFY(m.ok());
        QCOMPARE(m->ways.size(), std::size_t(2));
        QCOMPARE(m->way(2001)->nodes, r->way(2001)->nodes);
        QCOMPARE(m->way(4201)->tags, r->way(4201)->tags);
        QCOMPARE(m->nodes.at(700002).lat, r->nodes.at(700002).lat);
        QVERIFY(m->warnings.empty());
    }

    void incompleteIsNotAMap() {
        MapAssembler a;
        MapSummaryV1 s;
        s.documentCount = 2;
        a.begin(s);
        QVERIFY(a.addChunk(chunk(1, kNodes)).ok());
        auto m = a.finish();
        QVERIFY(!m.ok());
        QCOMPARE(QString::fromStdString(m.error()), QString("map incomplete: 1 of 2 chunks"));
    }

    void rejections_data() {
        QTest::addColumn<QString>("xml");
        QTest::addColumn<QString>("error");
        QTest::newRow("not xml") << QString::fromStdString(chunk(1, "<node id=\"1\""))
                                 << "map chunk 1: not well-formed XML";
        QTest::newRow("version") << "<osm version=\"0.5\" sequence=\"1\"/>"
                                 << "map chunk 1: osm version '0.5' is not 0.6";
        QTest::newRow("sequence") << QString::fromStdString("<osm version=\"0.6\" sequence=\"2\"/>")
                                  << "map chunk 1: sequence 2 out of order, expected 1";
        QTest::newRow("node id 0") << QString::fromStdString(chunk(1, R"(<node id="0" lat="1" lon="1"/>)"))
                                   << "map chunk 1: node id 0 is forbidden (§10.2)";
        QTest::newRow("negative way")
            << QString::fromStdString(chunk(1, kNodes + R"(<way id="-5"><nd ref="1"/><nd ref="2"/></way>)"))
            << "map chunk 1: way id -5 is negative; the service serves positive IDs only (§10.2)";
        QTest::newRow("duplicate node")
            << QString::fromStdString(chunk(1, kNodes + R"(<node id="2" lat="1" lon="1"/>)"))
            << "map chunk 1: duplicate node id 2 (§10.2: IDs are unique per category)";
        QTest::newRow("lat range") << QString::fromStdString(chunk(1, R"(<node id="4" lat="91" lon="1"/>)"))
                                   << "map chunk 1: node 4: lat/lon out of range";
        QTest::newRow("dangling ref")
            << QString::fromStdString(chunk(1, kNodes + R"(<way id="5"><nd ref="1"/><nd ref="9"/></way>)"))
            << "way 5: references unknown node 9";
        QTest::newRow("short road") << QString::fromStdString(
                                           chunk(1, kNodes + R"(<way id="5"><nd ref="1"/></way>)"))
                                    << "way 5: a road needs at least 2 nodes";
        QTest::newRow("small area")
            << QString::fromStdString(
                   chunk(1, kNodes + R"(<way id="5"><nd ref="1"/><nd ref="2"/><nd ref="1"/></way>)"))
            << "way 5: an area needs at least 3 distinct nodes";
        QTest::newRow("self crossing")
            << QString::fromStdString(chunk(
                   1,
                   R"(<node id="1" lat="0" lon="0"/><node id="2" lat="0.001" lon="0.001"/><node id="3" lat="0" lon="0.001"/><node id="4" lat="0.001" lon="0"/><way id="6"><nd ref="1"/><nd ref="2"/><nd ref="3"/><nd ref="4"/></way>)"))
            << "way 6: crosses itself (segments 0 and 2)";
    }
    void rejections() {
        QFETCH(QString, xml);
        QFETCH(QString, error);
        auto r = parseMapDocument({xml.toStdString()});
        QVERIFY(!r.ok());
        QVERIFY2(QString::fromStdString(r.error()).startsWith(error), r.error().c_str());
    }

    void tagWarnings() {
        auto r = parseMapDocument({chunk(
            1,
            kNodes +
                R"(<way id="5"><nd ref="1"/><nd ref="2"/><tag k="oneway" v="sometimes"/><tag k="autonomy:area" v="AOZ"/></way>)"
                R"(<way id="6"><nd ref="1"/><nd ref="2"/><nd ref="3"/><nd ref="1"/><tag k="default task" v="park"/></way>)")});
        QVERIFY(r.ok());
        QCOMPARE(r->way(6)->defaultTask(), std::string("park"));
        QCOMPARE(r->warnings.size(), std::size_t(2));
        QCOMPARE(r->warnings[0], std::string("way 5: tag autonomy:area is not allowed on a road"));
        QCOMPARE(r->warnings[1], std::string("way 5: tag oneway='sometimes' is not a standard value"));
    }

    void lanesAreOneway() {
        auto r = parseMapDocument(
            {chunk(1, kNodes + R"(<way id="5"><nd ref="1"/><nd ref="2"/><tag k="oneway" v="yes"/></way>)")});
        QVERIFY(r.ok());
        QCOMPARE(r->lanes, std::vector<std::int64_t>{5});
        QCOMPARE(r->way(5)->kind, WayKind::Lane);
    }

    void connectivityGraph() {
        auto env = decodeMessage(
            R"({"Protocol":"ISO23725","Version":1,"Timestamp":"2025-03-14T02:15:01.000Z","MapConnectivityV1":[
          {"WayId":4101,"WayType":"Area","AreaProperty":{"DefaultTask":"Offload","Name":"North Waste Dump"},"Connection":[{"WayId":2001}]},
          {"WayId":2001,"WayType":"Road","RoadProperty":{"Length":1840.5,"Name":"North Ramp"},"Connection":[{"WayId":4101},{"WayId":4201}]},
          {"WayId":2002,"WayType":"Road","RoadProperty":{"Length":5000,"Name":"Long way"},"Connection":[{"WayId":4201}]},
          {"WayId":4201,"WayType":"Area","AreaProperty":{"DefaultTask":"Load","Name":"Pit 3 Bench 480"},"Connection":[{"WayId":2001},{"WayId":9}]}]})");
        QVERIFY(env.ok());
        ConnectivityGraph g;
        g.assign(*env->find<MapConnectivityV1>());
        QCOMPARE(g.size(), std::size_t(4));
        QCOMPARE(g.route(4101, 4201), (std::vector<std::int64_t>{4101, 2001, 4201}));
        QVERIFY(g.route(4201, 2002).empty()); // connections are directional
        QCOMPARE(g.danglingConnections().size(), std::size_t(1));
    }
};

QTEST_GUILESS_MAIN(TestIsoMap)
#include "test_iso_map.moc"
