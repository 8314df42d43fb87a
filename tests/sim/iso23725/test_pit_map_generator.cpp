// The simulated AHS's pit map on its own (no sockets): for several layouts the generated ways, areas and
// connectivity are consistent with each other, node coordinates agree with their ENU positions, the map
// service's documents parse back to the same map with the counts its summary announces, and generation is
// deterministic.
#include "sim/iso23725/PitMapGenerator.h"

#include "protocols/iso23725/MapModel.h"

#include "protocols/common/GeoFrame.h"

#include <QtTest>

#include <cmath>
#include <set>

using namespace ocu;
using namespace ocu::iso23725;
using namespace ocu::sim;

namespace {

constexpr std::int64_t kNow = 1'741'918'507'412; // 2025-03-14T02:15:07.412Z

ConnectivityGraph graphOf(const PitMap& pit) {
    ConnectivityGraph g;
    g.assign(pit.connectivity);
    return g;
}

bool connected(const ConnectivityGraph& g, std::int64_t from, std::int64_t to) {
    auto next = g.successors(from);
    return std::find(next.begin(), next.end(), to) != next.end();
}

} // namespace

class TestPitMapGenerator : public QObject {
    Q_OBJECT
private slots:
    void layouts_data() {
        QTest::addColumn<int>("shovels");
        QTest::addColumn<int>("dumps");
        QTest::newRow("1 shovel, 1 dump") << 1 << 1;
        QTest::newRow("2 shovels, 2 dumps (default)") << 2 << 2;
        QTest::newRow("4 shovels, 3 dumps") << 4 << 3;
        QTest::newRow("0 and 0 mean one of each") << 0 << 0;
    }

    // Every place the fleet needs exists once, with the kind and task its role implies.
    void layouts() {
        QFETCH(int, shovels);
        QFETCH(int, dumps);
        const PitMap pit = generatePitMap({shovels, dumps, {}}, kNow);
        const auto ns = std::size_t(std::max(1, shovels)), nd = std::size_t(std::max(1, dumps));
        QCOMPARE(pit.loadAreas.size(), ns);
        QCOMPARE(pit.loadRoads.size(), ns);
        QCOMPARE(pit.dumpAreas.size(), nd + 1); // plus the crusher, last
        QCOMPARE(pit.dumpRoads.size(), nd + 1);
        QCOMPARE(pit.map.ways.at(pit.dumpAreas.back()).name(), std::string("Primary crusher"));
        for (auto id : pit.loadAreas) {
            QCOMPARE(pit.map.ways.at(id).kind, WayKind::Area);
            QCOMPARE(pit.map.ways.at(id).defaultTask(), std::string("load"));
        }
        for (auto id : pit.dumpAreas) {
            QCOMPARE(pit.map.ways.at(id).kind, WayKind::Area);
            QCOMPARE(pit.map.ways.at(id).defaultTask(), std::string("offload"));
        }
        QCOMPARE(pit.map.ways.at(pit.parkArea).defaultTask(), std::string("park"));
        // The ramp is two one-way lanes (§8: node order is the travel direction), downhill and uphill.
        const auto& down = pit.map.ways.at(pit.rampDown);
        const auto& up = pit.map.ways.at(pit.rampUp);
        QCOMPARE(down.kind, WayKind::Lane);
        QCOMPARE(up.kind, WayKind::Lane);
        QVERIFY(pit.map.nodes.at(down.nodes.front()).enu.u > pit.map.nodes.at(down.nodes.back()).enu.u);
        QVERIFY(pit.map.nodes.at(up.nodes.front()).enu.u < pit.map.nodes.at(up.nodes.back()).enu.u);
        // Every way's nodes exist; areas are closed rings; no node is left over.
        std::set<std::int64_t> used;
        for (const auto& [id, w] : pit.map.ways) {
            QVERIFY2(w.nodes.size() >= 2, qPrintable(QString::number(id)));
            for (auto n : w.nodes) {
                QVERIFY2(pit.map.nodes.count(n), qPrintable(QStringLiteral("way %1 node %2").arg(id).arg(n)));
                used.insert(n);
            }
            if (w.kind == WayKind::Area)
                QCOMPARE(w.nodes.front(), w.nodes.back());
            QCOMPARE(w.changeset, std::optional<std::int64_t>(pit.changeSetWay));
        }
        QCOMPARE(used.size(), pit.map.nodes.size());
    }

    // §9.1: the connectivity names only ways of the map, lists every road and area the fleet uses with its
    // length or task, and lets a truck get from every dump to every shovel and back, and to the park.
    void connectivityMatchesTheWays() {
        const PitMap pit = generatePitMap({3, 2, {}}, kNow);
        const auto g = graphOf(pit);
        QVERIFY(g.danglingConnections().empty());
        for (const auto& item : pit.connectivity.items) {
            QVERIFY(pit.map.ways.count(item.wayId));
            const auto& way = pit.map.ways.at(item.wayId);
            if (item.wayType == "Road") {
                QVERIFY(way.kind != WayKind::Area);
                QVERIFY(item.roadLength);
                QVERIFY(std::fabs(*item.roadLength - pit.wayLength(item.wayId)) <= 0.05);
                QCOMPARE(item.roadName, std::optional<std::string>(way.name()));
            } else {
                QCOMPARE(way.kind, WayKind::Area);
                QCOMPARE(item.areaName, std::optional<std::string>(way.name()));
            }
        }
        for (auto load : pit.loadAreas)
            for (auto dump : pit.dumpAreas) {
                QVERIFY2(!g.route(dump, load).empty(),
                         qPrintable(QStringLiteral("%1 -> %2").arg(dump).arg(load)));
                QVERIFY2(!g.route(load, dump).empty(),
                         qPrintable(QStringLiteral("%1 -> %2").arg(load).arg(dump)));
            }
        QVERIFY(!g.route(pit.loadAreas.front(), pit.parkArea).empty());
        QVERIFY(!g.route(pit.parkArea, pit.loadAreas.back()).empty());
        // The lanes are one way: nothing leads from the bottom of the down lane back up it.
        QVERIFY(!connected(g, pit.rampDown, pit.rampUp));
        QVERIFY(connected(g, pit.rampDown, pit.loadRoads.front()));
        QVERIFY(connected(g, pit.loadRoads.front(), pit.rampUp));
    }

    // A haul cycle's route over the map: consecutive legs are connected ways whose ends meet within a few
    // metres, and the route's length is the sum of its ways plus those junctions.
    void haulRouteFollowsConnectedWays() {
        const PitMap pit = generatePitMap({2, 2, {}}, kNow);
        const auto g = graphOf(pit);
        const std::vector<RouteLeg> toDump = {
            {pit.loadRoads[1], true}, {pit.rampUp, false}, {pit.dumpRoads[0], false}};
        const std::vector<RouteLeg> toLoad = {
            {pit.dumpRoads[0], true}, {pit.rampDown, false}, {pit.loadRoads[1], false}};
        for (const auto& legs : {toDump, toLoad}) {
            const Route r = pit.route(legs);
            QCOMPARE(r.legWays().size(), legs.size());
            double sum = 0;
            for (std::size_t i = 0; i < legs.size(); ++i) {
                const auto pts = pit.wayPoints(legs[i].wayId, legs[i].reversed);
                for (std::size_t k = 0; k + 1 < pts.size(); ++k)
                    sum += std::hypot(pts[k + 1].e - pts[k].e, pts[k + 1].n - pts[k].n);
                if (i + 1 < legs.size()) {
                    QVERIFY(connected(g, legs[i].wayId, legs[i + 1].wayId));
                    const auto next = pit.wayPoints(legs[i + 1].wayId, legs[i + 1].reversed);
                    const double gap =
                        std::hypot(next.front().e - pts.back().e, next.front().n - pts.back().n);
                    QVERIFY2(gap <= 10, qPrintable(QStringLiteral("junction gap %1 m").arg(gap)));
                    sum += gap;
                }
            }
            QVERIFY(std::fabs(r.length() - sum) < 1e-6);
            // The route starts on its first way and ends on its last.
            QCOMPARE(r.poseAt(0)->wayId, legs.front().wayId);
            QCOMPARE(r.poseAt(r.length())->wayId, legs.back().wayId);
        }
    }

    // Nodes carry WGS84 (rounded to 1e-7 degrees and centimetres) and ENU around the layout's origin; both
    // must describe the same place. Heights are the origin's plus the ENU up (a flat pit), so they part from
    // the ellipsoid by the earth's curvature: a few centimetres over the pit's kilometre.
    void nodeCoordinatesAgreeWithTheirEnu() {
        const GeoPoint origin{-23.36, 119.73, 500.0};
        const PitMap pit = generatePitMap({2, 2, origin}, kNow);
        const GeoFrame frame(origin);
        QCOMPARE(pit.map.origin.lat, origin.lat);
        for (const auto& [id, n] : pit.map.nodes) {
            QVERIFY(n.ele);
            const EnuPoint p = frame.toLocal({n.lat, n.lon, *n.ele});
            QVERIFY2(std::hypot(p.e - n.enu.e, p.n - n.enu.n) < 0.03 && std::fabs(p.u - n.enu.u) < 0.15,
                     qPrintable(QStringLiteral("node %1 off by %2 m")
                                    .arg(id)
                                    .arg(std::hypot(p.e - n.enu.e, p.n - n.enu.n))));
        }
    }

    // The map service's documents (§10.6): as many as the summary announces, each at most the chunk size,
    // and together the same nodes, ways and tags.
    void mapServiceDocumentsParseBack_data() {
        QTest::addColumn<int>("chunkElements");
        QTest::newRow("default: four documents") << 0;
        QTest::newRow("50 elements each") << 50;
    }
    void mapServiceDocumentsParseBack() {
        QFETCH(int, chunkElements);
        const PitMap pit = generatePitMap({2, 2, {}}, kNow);
        const auto chunks = pit.osmChunks(std::size_t(chunkElements));
        const MapSummaryV1 s = pit.summary(std::size_t(chunkElements));
        QCOMPARE(s.documentCount, std::int64_t(chunks.size()));
        QCOMPARE(s.nodeCount, std::int64_t(pit.map.nodes.size()));
        QCOMPARE(s.wayCount, std::int64_t(pit.map.ways.size()));
        QCOMPARE(s.timestamp.unixMs, std::optional<std::int64_t>(kNow));
        const std::size_t total = pit.map.nodes.size() + pit.map.ways.size();
        if (chunkElements == 0)
            QCOMPARE(chunks.size(), std::size_t(4));
        else
            QCOMPARE(chunks.size(), (total + std::size_t(chunkElements) - 1) / std::size_t(chunkElements));
        auto parsed = parseMapDocument(chunks, s);
        QVERIFY2(parsed, parsed ? "" : parsed.error().c_str());
        QVERIFY2(parsed->warnings.empty(), parsed->warnings.empty() ? "" : parsed->warnings.front().c_str());
        QCOMPARE(parsed->nodes.size(), pit.map.nodes.size());
        QCOMPARE(parsed->ways.size(), pit.map.ways.size());
        for (const auto& [id, w] : pit.map.ways) {
            const MapWay* back = parsed->way(id);
            QVERIFY(back);
            QCOMPARE(back->nodes, w.nodes);
            QCOMPARE(back->tags, w.tags);
            QCOMPARE(back->kind, w.kind);
        }
        for (const auto& [id, n] : pit.map.nodes) {
            const auto& b = parsed->nodes.at(id);
            QCOMPARE(b.lat, n.lat);
            QCOMPARE(b.lon, n.lon);
            QCOMPARE(b.ele, n.ele);
        }
    }

    void generationIsDeterministic() {
        const PitMap a = generatePitMap({3, 2, {}}, kNow);
        const PitMap b = generatePitMap({3, 2, {}}, kNow);
        QVERIFY(a.osmChunks(0) == b.osmChunks(0));
        QVERIFY(a.connectivity == b.connectivity);
        QCOMPARE(a.loadAreas, b.loadAreas);
        QCOMPARE(a.dumpAreas, b.dumpAreas);
    }

    // An edit moves both change sets and the modification time: the summary tells an FMS to fetch again.
    void editMovesTheChangeSets() {
        PitMap pit = generatePitMap({2, 2, {}}, kNow);
        const MapSummaryV1 before = pit.summary(0);
        pit.edited(kNow + 60'000);
        const MapSummaryV1 after = pit.summary(0);
        QCOMPARE(after.changeSetMap, before.changeSetMap + 1);
        QCOMPARE(after.changeSetWay, before.changeSetWay + 1);
        QCOMPARE(after.timestamp.unixMs, std::optional<std::int64_t>(kNow + 60'000));
        QCOMPARE(after.nodeCount, before.nodeCount);
    }
};

QTEST_GUILESS_MAIN(TestPitMapGenerator)
#include "test_pit_map_generator.moc"
