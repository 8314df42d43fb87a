// The whole console on the built-in simulated site, in-process: the 2D site map shows the mine roads,
// machines of the three protocols in their status colours and the OSYRIS pass-count patch, each at its
// projected position, and STOP ALL from the window reaches the stacks.
#include "app/MainWindow.h"
#include "app/SiteLoader.h"
#include "app/SiteRuntime.h"

#include "models/FleetModel.h"
#include "models/MachineState.h"
#include "models/PassCountLayer.h"
#include "models/SiteMapData.h"
#include "tests/support/BuiltProtocols.h"
#include "widgets/SiteMapView.h"

#include <QAction>
#include <QStandardPaths>
#include <QtTest>

#include <vector>

using namespace ocu;

namespace {
bool near(QColor a, QColor b, int tol) {
    return std::abs(a.red() - b.red()) <= tol && std::abs(a.green() - b.green()) <= tol &&
           std::abs(a.blue() - b.blue()) <= tol;
}
// True when some pixel within `radius` of p has colour c.
bool colourAround(const QImage& img, QPoint p, QColor c, int radius, int tol) {
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const QPoint q = p + QPoint(dx, dy);
            if (img.rect().contains(q) && near(img.pixelColor(q), c, tol))
                return true;
        }
    return false;
}
} // namespace

class TestSitePicture : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void mapShowsRoadsMachinesAndPassCounts() {
        auto site = loadSite({});
        QVERIFY(site.ok());
        SiteConfig cfg = std::move(site.value());
        cfg.simulation.ahsTrucks = 3;
        cfg.simulation.osyrisSpeedUp = 60;
        SiteRuntime runtime(cfg);
        runtime.start();
        MainWindow window;
        runtime.populate(window);
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        auto* map = qobject_cast<SiteMapView*>(window.panelWidget(Panel::SiteMap));
        QVERIFY(map);
        // Wait for machines of every protocol, the mine map and a pass-count patch.
        auto machines = [&] { return runtime.findChild<FleetModel*>(); };
        QVERIFY(machines());
        auto countOf = [&](Protocol p) {
            int n = 0;
            for (const auto& m : machines()->machinesSnapshot())
                n += m.protocol == p && m.hasPosition;
            return n;
        };
        QTRY_VERIFY_WITH_TIMEOUT((!ocutest::kWithJaus || countOf(Protocol::Jaus) >= 2) &&
                                     (!ocutest::kWithIso23725 || countOf(Protocol::Iso23725) >= 3) &&
                                     (!ocutest::kWithOsyris || countOf(Protocol::Osyris) >= 2),
                                 20000);
        // Roads (the ISO 23725 map's): the middle of the first road is drawn in the road colour.
        QImage img;
        if (ocutest::kWithIso23725) {
            QTRY_VERIFY_WITH_TIMEOUT(!map->siteMap().features.isEmpty(), 20000);
            const SiteMapData mapData = map->siteMap();
            const MapFeature* road = nullptr;
            for (const auto& f : mapData.features)
                if (f.kind != MapFeatureKind::Area && f.points.size() >= 2) {
                    road = &f;
                    break;
                }
            QVERIFY(road);
            const QPointF mid = (road->points[0] + road->points[1]) / 2;
            map->setView(mid, 2.0);
            img = map->grab().toImage();
            // Zoomed in, a road is drawn at its width in the lighter task colour, with a centre line.
            const QColor roadColour = taskColor(road->defaultTask).lighter(150);
            QVERIFY2(road->width > 0, qPrintable(road->name));
            QVERIFY2(colourAround(img, map->worldToScreen(mid).toPoint(), roadColour, 6, 12),
                     qPrintable(road->name + " " + img.pixelColor(map->worldToScreen(mid).toPoint()).name()));
        }

        // Machines of each protocol in their status colour, close up.
        std::vector<Protocol> built;
        if (ocutest::kWithJaus)
            built.push_back(Protocol::Jaus);
        if (ocutest::kWithIso23725)
            built.push_back(Protocol::Iso23725);
        if (ocutest::kWithOsyris)
            built.push_back(Protocol::Osyris);
        for (Protocol p : built) {
            const FleetModel* fm = machines();
            MachineState m;
            for (const auto& s : fm->machinesSnapshot())
                if (s.protocol == p && s.hasPosition) {
                    m = s;
                    break;
                }
            map->setView({m.e, m.n}, 8.0);
            img = map->grab().toImage(); // no events in between: the model and the picture agree
            const MachineState* now = fm->machine(m.id);
            QVERIFY(now);
            const QColor c = statusColor(fm->statusAt(fm->rowOf(m.id)));
            const int r = static_cast<int>(std::max(now->length, now->width) * 8.0 / 2);
            QVERIFY2(colourAround(img, map->worldToScreen({now->e, now->n}).toPoint(), c, std::max(r, 3), 8),
                     qPrintable(m.id + " " + c.name()));
        }

        // The pass-count patch (the OSYRIS rollers'): a covered cell is drawn in its palette colour.
        if (!ocutest::kWithOsyris) {
            runtime.stop();
            return;
        }
        const PassCountLayer* pc = map->passCountLayer();
        QVERIFY(pc);
        QPointF cellCentre;
        int count = 0;
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                for (int row = 0; row < pc->rows() && !count; row += 3)
                    for (int col = 0; col < pc->columns() && !count; col += 3)
                        if (int n = pc->count(col, row); n > 0) {
                            count = n;
                            cellCentre = pc->origin() +
                                         QPointF((col + 0.5) * pc->cellSize(), (row + 0.5) * pc->cellSize());
                        }
                return count > 0;
            }(),
            20000);
        map->setLayerVisible(SiteMapView::LayerMachines, false); // rollers stand on their own patch
        map->setView(cellCentre, 40.0);
        // The rollers keep compacting while the map is drawn: compare against a picture during which the
        // cell's count did not change (read before and after the grab), so the expected colour is known.
        const int col = int((cellCentre.x() - pc->origin().x()) / pc->cellSize());
        const int row = int((cellCentre.y() - pc->origin().y()) / pc->cellSize());
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                count = pc->count(col, row);
                img = map->grab().toImage();
                return pc->count(col, row) == count;
            }(),
            20000);
        const QColor expected = passCountColor(count, map->passPalette(), map->passTarget());
        QVERIFY2(colourAround(img, map->worldToScreen(cellCentre).toPoint(), expected, 3, 2),
                 qPrintable(QString("count %1 colour %2, drawn %3")
                                .arg(count)
                                .arg(expected.name())
                                .arg(img.pixelColor(map->worldToScreen(cellCentre).toPoint()).name())));
        runtime.stop();
    }
};

QTEST_MAIN(TestSitePicture)
#include "test_site_picture.moc"
