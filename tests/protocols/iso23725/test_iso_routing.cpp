// Routing over MapConnectivityV1: directed, by road Length, to a way or the nearest of an
// area's ways; unreachable and unknown destinations say why; an operator's route is checked link by link.
#include "protocols/iso23725/Routing.h"

#include <QtTest>

using namespace ocu::iso23725;

namespace {

ConnectivityItem road(std::int64_t id, double length, std::vector<std::int64_t> to) {
    ConnectivityItem i;
    i.wayId = id;
    i.wayType = "Road";
    i.roadLength = length;
    for (auto t : to)
        i.connection.push_back(WayRef{t});
    return i;
}
ConnectivityItem area(std::int64_t id, const char* task, std::vector<std::int64_t> to) {
    ConnectivityItem i;
    i.wayId = id;
    i.wayType = "Area";
    i.areaDefaultTask = task;
    for (auto t : to)
        i.connection.push_back(WayRef{t});
    return i;
}

// Dump 4101 <-> road 2001 <-> load 4201; a long road 2002 and a short detour 2003+2004 from 4201 to park
// 4301; 4301 -> 2005 is a one-way exit that leads nowhere back; 4401 has no way in.
MapConnectivityV1 site() {
    MapConnectivityV1 c;
    c.items = {area(4101, "Offload", {2001}),
               road(2001, 1840.5, {4101, 4201}),
               area(4201, "Load", {2001, 2002, 2003}),
               road(2002, 900, {4301}),
               road(2003, 300, {2004}),
               road(2004, 350, {4301}),
               area(4301, "Park", {2005}),
               road(2005, 100, {}),
               area(4401, "Load", {2001})};
    return c;
}

} // namespace

class TestIsoRouting : public QObject {
    Q_OBJECT
private slots:
    void shortestByLengthNotHops() {
        RouteGraph g(site());
        auto r = shortestRoute(g, 4201, 4301);
        QVERIFY2(r.ok, r.error.c_str());
        QCOMPARE(r.ways, (std::vector<std::int64_t>{4201, 2003, 2004, 4301}));
        QCOMPARE(r.length, 650.0);
        QCOMPARE(r.routeV1(), (std::vector<WayRef>{{2003}, {2004}}));
    }

    void directedEdgesAreHonoured() {
        RouteGraph g(site());
        // 4301 only leaves by 2005, which connects to nothing: no way back to the dump.
        auto r = shortestRoute(g, 4301, 4101);
        QVERIFY(!r.ok);
        QCOMPARE(r.error, std::string("way 4101 unreachable from way 4301 over MapConnectivityV1"));
        // Nobody drives into 4401.
        QVERIFY(!shortestRoute(g, 4101, 4401).ok);
        // ...but out of it, yes.
        auto out = shortestRoute(g, 4401, 4101);
        QVERIFY(out.ok);
        QCOMPARE(out.ways, (std::vector<std::int64_t>{4401, 2001, 4101}));
        QCOMPARE(out.length, 1840.5);
    }

    void unknownWaysAreNamed() {
        RouteGraph g(site());
        QCOMPARE(shortestRoute(g, 9, 4101).error, std::string("start way 9 is not in MapConnectivityV1"));
        QCOMPARE(shortestRoute(g, 4101, 9).error,
                 std::string("destination way 9 is not in MapConnectivityV1"));
        QVERIFY(!RouteGraph().contains(4101));
        QVERIFY(!shortestRoute(RouteGraph(), 1, 2).ok);
    }

    void sameWayIsARouteOfOne() {
        RouteGraph g(site());
        auto r = shortestRoute(g, 4201, 4201);
        QVERIFY(r.ok);
        QCOMPARE(r.ways, (std::vector<std::int64_t>{4201}));
        QVERIFY(r.routeV1().empty());
    }

    void nearestOfSeveralDestinations() {
        RouteGraph g(site());
        QCOMPARE(g.areasWithTask("Load"), (std::vector<std::int64_t>{4201, 4401}));
        // From the dump: 4201 is reachable, 4401 is not; the route goes to 4201.
        auto r = shortestRoute(g, 4101, g.areasWithTask("Load"));
        QVERIFY(r.ok);
        QCOMPARE(r.ways.back(), std::int64_t(4201));
        QVERIFY(!shortestRoute(g, 4101, std::vector<std::int64_t>{}).ok);
    }

    void operatorRouteChecked() {
        RouteGraph g(site());
        QCOMPARE(checkRoute(g, 4201, {{2003}, {2004}}, 4301), std::string());
        QCOMPARE(checkRoute(g, 4201, {{2002}}, 4301), std::string());
        QCOMPARE(checkRoute(g, 4201, {{-2003}, {2004}}, 4301), std::string()); // Q6: by absolute id
        QCOMPARE(checkRoute(g, 4201, {{2004}}, 4301),
                 std::string("route breaks: way 2004 is not reachable from way 4201 (MapConnectivityV1)"));
        QCOMPARE(checkRoute(g, 4201, {{7}}, 4301), std::string("route way 7 is not in MapConnectivityV1"));
    }

    void duplicateWayLastWinsAndDanglingIgnored() {
        auto c = site();
        c.items.push_back(road(2002, 10, {4301, 999})); // re-listed shorter, plus a dangling connection
        RouteGraph g(c);
        QCOMPARE(g.size(), std::size_t(9));
        auto r = shortestRoute(g, 4201, 4301);
        QCOMPARE(r.ways, (std::vector<std::int64_t>{4201, 2002, 4301}));
        QCOMPARE(r.length, 10.0);
    }
};

QTEST_APPLESS_MAIN(TestIsoRouting)
#include "test_iso_routing.moc"
