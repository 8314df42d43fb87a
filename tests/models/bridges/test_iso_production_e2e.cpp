// Production and dispatch end to end over loopback against the simulated AHS: a load task (and the dump
// after it) assigned through the headless monitor is Accepted and Active as the AHS reports; the truck drives
// the route the console sent (every position it reports while driving empty lies on the ways of that route,
// and it moves); the cycle completes with a payload that the production model counts for that truck, its
// shovel and its dump; the headless shift report writes both files and says so.
#include "app/HeadlessMonitor.h"
#include "app/modules/IsoHeadless.h"
#include "app/modules/IsoProduction.h"
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/ProductionModel.h"
#include "models/bridges/IsoBridge.h"
#include "sim/iso23725/SimulatedAhs.h"
#include "tests/support/IsoSimConsole.h"

#include <QBuffer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace ocu;

namespace {

constexpr int kWait = 60000;

sim::SimulatedAhsConfig ahsConfig() {
    return isosim::ahsConfig(2, 10, 60);
}

iso23725::IsoConfig consoleConfig(const std::string& url) {
    return isosim::consoleConfig(url, std::chrono::milliseconds(5000), 1600);
}

// Distance from p to the polyline (or polygon outline) of a map feature.
double distanceTo(const MapFeature& f, QPointF p) {
    double best = 1e12;
    for (int i = 0; i + 1 < f.points.size(); ++i) {
        const QPointF a = f.points[i], b = f.points[i + 1];
        const QPointF ab = b - a;
        const double l2 = QPointF::dotProduct(ab, ab);
        const double t = l2 > 0 ? std::clamp(QPointF::dotProduct(p - a, ab) / l2, 0.0, 1.0) : 0.0;
        const QPointF q = a + t * ab;
        best = std::min(best, std::hypot(p.x() - q.x(), p.y() - q.y()));
    }
    return best;
}

} // namespace

class TestIsoProductionE2e : public QObject {
    Q_OBJECT
private slots:
    void assignedLoadIsDrivenAndCounted() {
        sim::SimulatedAhs ahs(ahsConfig());
        QVERIFY(ahs.start());
        const auto view = ahs.dispatchView();
        AlarmModel alarms;
        CommandGate gate{&alarms};
        IsoBridge bridge(consoleConfig(ahs.url()), GeoFrame(ahsConfig().origin));
        ProductionModel* production = attachProductionModel(&bridge);
        QVERIFY(production);
        QCOMPARE(bridge.findChild<ProductionModel*>(), production);
        gate.addBridge(&bridge);
        alarms.addBridge(&bridge);
        QBuffer out;
        out.open(QIODevice::ReadWrite);
        HeadlessMonitor monitor{nullptr, &alarms, &gate};
        monitor.setOutput(&out);
        registerIsoHeadless(monitor.commands(),
                            {&bridge, production, nullptr, nullptr}); // as the ISO module does
        auto run = [&](const QJsonObject& cmd) {
            QSignalSpy spy(&monitor, &HeadlessMonitor::commandHandled);
            monitor.handleLine(QJsonDocument(cmd).toJson(QJsonDocument::Compact));
            if (spy.isEmpty() && !spy.wait(kWait))
                return QJsonObject{};
            return QJsonDocument::fromJson(spy.first().first().toByteArray()).object();
        };
        // Positions of every truck as the bridge publishes them (ENU in the site frame).
        QHash<QString, QVector<QPointF>> positions;
        connect(&bridge, &FleetBridge::machinesUpdated, this, [&](const QVector<MachineState>& rows) {
            for (const auto& m : rows)
                if (m.hasPosition) {
                    const auto d = bridge.dispatchState(m.id);
                    if (d && d->productionState == QLatin1String("Driving") &&
                        d->assignmentStatus == QLatin1String("Active") && d->task == QLatin1String("Load"))
                        positions[m.id] << QPointF(m.e, m.n);
                }
        });
        QVERIFY(bridge.start().isEmpty());

        const std::string t0 = view.trucks[0].id;
        const QString id0 = QStringLiteral("iso23725:") + QString::fromStdString(t0);
        auto truck = [&] { return bridge.dispatchState(id0); };
        QTRY_VERIFY_WITH_TIMEOUT(truck() && truck()->custodian == QLatin1String("FMS"), kWait);
        QTRY_VERIFY_WITH_TIMEOUT(!bridge.destinations().isEmpty() && !bridge.siteMap().features.isEmpty(),
                                 kWait);
        // Assign while it drives empty, so it turns towards the task at once (a loaded truck dumps first).
        QTRY_VERIFY_WITH_TIMEOUT(truck()->productionState == QLatin1String("Driving"), kWait);
        // The second shovel: the simulated AHS cycles truck 0 to the first on its own, so the drive is the
        // console's route, not the truck's habit.
        const qint64 shovel = view.loadAreas[1];
        const qint64 dumpArea = view.dumpAreas[0];
        QJsonArray tasks{QJsonObject{{QStringLiteral("task"), QStringLiteral("Load")},
                                     {QStringLiteral("destination"), double(shovel)}},
                         QJsonObject{{QStringLiteral("task"), QStringLiteral("Offload")},
                                     {QStringLiteral("destination"), double(dumpArea)}}};
        const QJsonObject r = run({{QStringLiteral("cmd"), QStringLiteral("assign")},
                                   {QStringLiteral("id"), id0},
                                   {QStringLiteral("tasks"), tasks}});
        QVERIFY2(r.value(QStringLiteral("ok")).toBool(), QJsonDocument(r).toJson().constData());
        const QJsonArray sent = r.value(QStringLiteral("tasks")).toArray();
        QCOMPARE(sent.size(), 2);
        const QString loadId = sent[0].toObject().value(QStringLiteral("assignment_id")).toString();
        const QString dumpId = sent[1].toObject().value(QStringLiteral("assignment_id")).toString();

        // Accepted, then Active.
        QTRY_VERIFY_WITH_TIMEOUT(truck()->response(loadId) &&
                                     truck()->response(loadId)->response == QLatin1String("Accepted"),
                                 kWait);
        QVERIFY(truck()->response(dumpId) &&
                truck()->response(dumpId)->response == QLatin1String("Accepted"));
        QTRY_VERIFY_WITH_TIMEOUT(
            truck()->assignmentId == loadId && truck()->assignmentStatus == QLatin1String("Active"), kWait);
        // The route the console sent (RouteV1), with the way it started from and the shovel.
        QVERIFY(truck()->requested.size() == 2 && truck()->requested[0].route.has_value());
        QSet<QString> routeWays{QString::number(shovel)};
        for (qint64 w : *truck()->requested[0].route)
            routeWays << QString::number(std::llabs(w));

        // Loaded at that shovel, dumped at that dump: the cycle completes and is counted.
        QTRY_VERIFY_WITH_TIMEOUT(truck()->assignmentId == dumpId, kWait);
        QTRY_VERIFY_WITH_TIMEOUT(
            production->shift().cycle.cycles >= 1 &&
                [&] {
                    for (const auto& t : production->trucks())
                        if (t.key == id0 && t.loads >= 1 && t.cycle.cycles >= 1)
                            return true;
                    return false;
                }(),
            kWait * 2);
        ProductionTally mine;
        for (const auto& t : production->trucks())
            if (t.key == id0)
                mine = t;
        QVERIFY2(mine.tonnes >= 220 && mine.tonnes < 300 * mine.loads,
                 qPrintable(QString::number(mine.tonnes)));
        QCOMPARE(mine.name, QStringLiteral("HT101"));
        QVERIFY(mine.cycle.average(CycleBreakdown::Load) > 0);
        QVERIFY(mine.cycle.average(CycleBreakdown::Haul) > 0);
        QVERIFY(mine.cycle.average(CycleBreakdown::Spot) > 0);
        bool shovelCounted = false, dumpCounted = false;
        for (const auto& s : production->shovels())
            shovelCounted = shovelCounted || (s.key == QString::number(shovel) && s.loads >= 1);
        for (const auto& d : production->dumps())
            dumpCounted = dumpCounted || (d.key == QString::number(dumpArea) && d.loads >= 1);
        QVERIFY(shovelCounted);
        QVERIFY(dumpCounted);
        QTRY_COMPARE_WITH_TIMEOUT(truck()->assignmentStatus, QStringLiteral("Completed"), kWait);

        // It drove the route: it moved, and every position reported while driving empty to the shovel lies
        // on one of the route's ways (or the shovel's area it spots into).
        const QVector<QPointF>& track = positions.value(id0);
        QVERIFY2(track.size() >= 10, qPrintable(QString::number(track.size())));
        double travelled = 0;
        for (int i = 1; i < track.size(); ++i)
            travelled += std::hypot(track[i].x() - track[i - 1].x(), track[i].y() - track[i - 1].y());
        QVERIFY2(travelled > 200, qPrintable(QString::number(travelled)));
        const SiteMapData map = bridge.siteMap();
        int onRoute = 0;
        for (const QPointF& p : track) {
            double best = 1e12;
            for (const auto& f : map.features)
                if (routeWays.contains(f.id.section(QLatin1Char('/'), -1))) // "<link>/<way id>"
                    best = std::min(best, distanceTo(f, p));
            onRoute += best < 15 ? 1 : 0;
        }
        // The first positions may still be on the way it was on when the console planned (not in RouteV1).
        QVERIFY2(onRoute >= track.size() * 8 / 10,
                 qPrintable(QStringLiteral("%1 of %2").arg(onRoute).arg(track.size())));

        // The shift report, headless: both files written, and said so.
        QTemporaryDir dir;
        const QJsonObject rep = run({{QStringLiteral("cmd"), QStringLiteral("shift_report")},
                                     {QStringLiteral("pdf"), dir.filePath(QStringLiteral("s.pdf"))},
                                     {QStringLiteral("csv"), dir.filePath(QStringLiteral("s.csv"))}});
        QVERIFY2(rep.value(QStringLiteral("ok")).toBool(), QJsonDocument(rep).toJson().constData());
        QVERIFY(rep.value(QStringLiteral("written")).toObject().value(QStringLiteral("pdf")).toBool());
        QVERIFY(rep.value(QStringLiteral("loads")).toInt() >= 1);
        QVERIFY(QFileInfo(dir.filePath(QStringLiteral("s.csv"))).size() > 100);
        // A file that cannot be written: not ok, and which one says so.
        const QJsonObject bad = run({{QStringLiteral("cmd"), QStringLiteral("shift_report")},
                                     {QStringLiteral("csv"), QStringLiteral("/nonexistent-dir/s.csv")}});
        QVERIFY(!bad.value(QStringLiteral("ok")).toBool());
        QVERIFY(!bad.value(QStringLiteral("written")).toObject().value(QStringLiteral("csv")).toBool());
        bridge.stop();
    }
};

QTEST_MAIN(TestIsoProductionE2e)
#include "test_iso_production_e2e.moc"
