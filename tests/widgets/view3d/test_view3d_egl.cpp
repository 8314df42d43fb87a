// Headless 3D: offscreen Qt platform and no X server (DISPLAY unset by ocu_add_test). The scene is rendered
// through the Mesa EGL surfaceless context; pixels at projected positions must show terrain, road and
// machine.
#include "tests/widgets/view3d/SyntheticSite.h"
#include "widgets/view3d/EglOffscreenRenderer.h"
#include "widgets/view3d/SiteSceneRenderer.h"

#include <QtTest>

using namespace ocu;
using namespace ocu::testsite;

class TestView3dEgl : public QObject {
    Q_OBJECT

private:
    static QRgb pixelAt(const QImage& img, QPointF p) {
        return img.pixel(static_cast<int>(p.x()), static_cast<int>(p.y()));
    }
    static QString describe(QRgb p) {
        return QStringLiteral("(%1,%2,%3)").arg(qRed(p)).arg(qGreen(p)).arg(qBlue(p));
    }

private slots:
    void initTestCase() { QVERIFY(qEnvironmentVariable("DISPLAY").isEmpty()); }

    void rendersTerrainRoadAndMachineWithoutX() {
        SiteSceneRenderer scene;
        scene.setScene(makeSite());
        EglOffscreenRenderer egl;
        QVERIFY2(egl.initialize(), qPrintable(egl.errorString()));
        QCOMPARE(egl.backend(), EglOffscreenRenderer::Backend::EglSurfaceless);
        const QImage img = egl.render(scene, QSize(640, 480));
        QCOMPARE(img.size(), QSize(640, 480));
        if (const QString dump = qEnvironmentVariable("OCU_VIEW3D_DUMP"); !dump.isEmpty())
            img.save(dump + QStringLiteral("/egl_site.png")); // for looking at the picture by eye

        const Machine3D m1 = *scene.machine(QStringLiteral("M1"));
        const auto top = scene.project(m1.e, m1.n, m1.u + m1.height);
        QVERIFY(top);
        QVERIFY(QRectF(0, 0, 640, 480).contains(*top));
        QVERIFY2(isMagenta(pixelAt(img, *top)), qPrintable(describe(pixelAt(img, *top))));

        const auto road = scene.project(-60.0, 0.0, scene.terrainHeight(-60.0, 0.0));
        QVERIFY(road);
        QVERIFY2(isRoadGrey(pixelAt(img, *road)), qPrintable(describe(pixelAt(img, *road))));

        const auto ground = scene.project(-70.0, 60.0, scene.terrainHeight(-70.0, 60.0));
        QVERIFY(ground);
        QVERIFY2(isTerrain(pixelAt(img, *ground)), qPrintable(describe(pixelAt(img, *ground))));

        // The pass-count patch is drawn with its legend colours (red column at the east end).
        const auto red = scene.project(28.0, -35.0, scene.terrainHeight(28.0, -35.0));
        QVERIFY(red);
        QCOMPARE(pixelAt(img, *red), qRgb(255, 0, 0)); // unlit: exactly the legend colour
        const auto green = scene.project(19.0, -33.0, scene.terrainHeight(19.0, -33.0));
        QVERIFY(green);
        QCOMPARE(pixelAt(img, *green), qRgb(154, 205, 50));
        // The no-data cell (alpha 0) lets the terrain through.
        const auto noData = scene.project(11.0, -39.0, scene.terrainHeight(11.0, -39.0));
        QVERIFY(noData);
        QVERIFY2(isTerrain(pixelAt(img, *noData)), qPrintable(describe(pixelAt(img, *noData))));

        // The concave area is draped over the hill (subdivided), not hidden under it.
        const auto area = scene.project(80.0, 50.0, scene.terrainHeight(80.0, 50.0));
        QVERIFY(area);
        const QRgb ap = pixelAt(img, *area);
        QVERIFY2(qGreen(ap) > qRed(ap) + 40 && qGreen(ap) > qBlue(ap) + 40, qPrintable(describe(ap)));

        // Opaque everywhere, the sky too (its framebuffer alpha is 0): a picture of the panel alone had a
        // transparent sky. The bytes, not pixelColor(), which reads RGBX as opaque whatever they hold.
        const QImage opaque = img.convertToFormat(QImage::Format_RGBX8888);
        int transparent = 0;
        for (int y = 0; y < opaque.height(); ++y)
            for (int x = 0; x < opaque.width(); ++x)
                transparent += opaque.constScanLine(y)[x * 4 + 3] != 255;
        QCOMPARE(transparent, 0);
        QCOMPARE(QImage(img).convertToFormat(QImage::Format_ARGB32).pixelColor(2, 2).alpha(), 255);

        // Picking works on the same window: the machine under its pixel, nothing on bare ground.
        QCOMPARE(scene.pick(top->x(), top->y()), QStringLiteral("M1"));
        QCOMPARE(scene.pick(ground->x(), ground->y()), QString());
    }

    void machinesMoveWithoutRebuildingTheScene() {
        SiteSceneRenderer scene;
        scene.setScene(makeSite());
        EglOffscreenRenderer egl;
        QVERIFY2(egl.initialize(), qPrintable(egl.errorString()));
        egl.render(scene, QSize(400, 300));
        const auto builds = scene.sceneBuildCount();
        const auto layouts = scene.machineLayoutCount();

        std::vector<Machine3D> machines = scene.scene().machines;
        const Machine3D before = machines[0];
        machines[0].e = -60.0;
        machines[0].n = 60.0;
        machines[0].u = 500.0; // ignored: machines are put on the terrain
        scene.updateMachines(machines);
        QVERIFY(qAbs(scene.machine(QStringLiteral("M1"))->u - scene.terrainHeight(-60.0, 60.0)) < 1e-9);
        QCOMPARE(scene.sceneBuildCount(), builds);
        QCOMPARE(scene.machineLayoutCount(), layouts); // same set of ids: arrays updated in place

        const QImage img = egl.render(scene, QSize(400, 300));
        const auto now = scene.project(-60.0, 60.0, scene.machine(QStringLiteral("M1"))->u + before.height);
        const auto old = scene.project(before.e, before.n, before.u + before.height);
        QVERIFY(now && old);
        QVERIFY2(isMagenta(pixelAt(img, *now)), qPrintable(describe(pixelAt(img, *now))));
        QVERIFY2(!isMagenta(pixelAt(img, *old)), qPrintable(describe(pixelAt(img, *old))));

        // A new id changes the set: one re-layout, and the new machine is drawn.
        machines.push_back(machine("M3", 0.0, 50.0, 90.0, kCyan));
        scene.updateMachines(machines);
        QCOMPARE(scene.machineLayoutCount(), layouts + 1);
        const QImage img2 = egl.render(scene, QSize(400, 300));
        const Machine3D m3 = *scene.machine(QStringLiteral("M3"));
        const auto p3 = scene.project(m3.e, m3.n, m3.u + m3.height);
        QVERIFY(p3);
        QVERIFY2(isCyan(pixelAt(img2, *p3)), qPrintable(describe(pixelAt(img2, *p3))));
    }

    void passCountUpdateRecolours() {
        SiteSceneRenderer scene;
        scene.setScene(makeSite());
        EglOffscreenRenderer egl;
        QVERIFY2(egl.initialize(), qPrintable(egl.errorString()));
        egl.render(scene, QSize(640, 480));
        PassCountRaster r = scene.scene().passCount;
        for (std::size_t o = 0; o < r.rgba.size(); o += 4) {
            r.rgba[o] = 255;
            r.rgba[o + 1] = 0;
            r.rgba[o + 2] = 255; // everything fuchsia now
        }
        const auto builds = scene.sceneBuildCount();
        scene.setPassCount(r, {{QStringLiteral("6"), {255, 0, 255}}});
        QCOMPARE(scene.sceneBuildCount(), builds);
        const QImage img = egl.render(scene, QSize(640, 480));
        const auto p = scene.project(19.0, -33.0, scene.terrainHeight(19.0, -33.0));
        QVERIFY(p);
        QCOMPARE(pixelAt(img, *p), qRgb(255, 0, 255));
    }

    void flatPlaneWhenNoElevations() {
        Scene3D s = makeSite();
        s.terrain.points.clear();
        s.terrain.planeU = 2.0;
        for (Machine3D& m : s.machines)
            m.u = 2.0;
        SiteSceneRenderer scene;
        scene.setScene(s);
        QCOMPARE(scene.terrainHeight(12.0, -7.0), 2.0);
        EglOffscreenRenderer egl;
        const QImage img = egl.render(scene, QSize(400, 300));
        QVERIFY2(!img.isNull(), qPrintable(egl.errorString()));
        const auto ground = scene.project(-70.0, 60.0, 2.0);
        QVERIFY(ground);
        QVERIFY2(isTerrain(pixelAt(img, *ground)), qPrintable(describe(pixelAt(img, *ground))));
    }

    void degenerateInputIsDrawnWithoutCrashing() {
        SiteSceneRenderer scene;
        scene.setScene(Scene3D{}); // nothing at all: the default flat plane
        EglOffscreenRenderer egl;
        QVERIFY(!egl.render(scene, QSize(200, 150)).isNull());
        QCOMPARE(scene.pick(100, 75), QString());

        Scene3D s = makeSite();
        s.terrain.points.push_back({std::nan(""), 0.0, 0.0});
        s.terrain.points.push_back({0.0, INFINITY, 0.0});
        Way3D single;
        single.points = {{1, 1, 0}};
        Way3D repeated;
        repeated.points = {{5, 5, 0}, {5, 5, 0}, {5, 5, 0}};
        Way3D line;
        line.kind = WayKind::Area;
        line.points = {{0, 0, 0}, {10, 0, 0}};
        Way3D noWidth;
        noWidth.points = {{0, 0, 0}, {10, 0, 0}};
        noWidth.width = std::nan("");
        s.ways.insert(s.ways.end(), {single, repeated, line, noWidth});
        s.passCount.rgba.resize(7); // inconsistent with cols*rows*4: ignored
        s.machines[1].e = std::nan("");
        scene.setScene(s);
        const QImage img = egl.render(scene, QSize(640, 480));
        QVERIFY(!img.isNull());
        // The good data survives: Delaunay terrain, M1 drawn and pickable; M2 (bad pose) hidden, not
        // pickable.
        QVERIFY(qAbs(scene.terrainHeight(-70.0, 60.0) - groundU(-70.0, 60.0)) < 0.5);
        const Machine3D m1 = *scene.machine(QStringLiteral("M1"));
        const auto p1 = scene.project(m1.e, m1.n, m1.u + m1.height);
        QVERIFY(p1);
        QVERIFY2(isMagenta(pixelAt(img, *p1)), qPrintable(describe(pixelAt(img, *p1))));
        QCOMPARE(scene.pick(p1->x(), p1->y()), QStringLiteral("M1"));
        QVERIFY(!scene.machine(QStringLiteral("M2")));
        // The pass-count patch is gone (raster refused), so its red column shows terrain.
        const auto red = scene.project(28.0, -35.0, scene.terrainHeight(28.0, -35.0));
        QVERIFY(red);
        QVERIFY2(isTerrain(pixelAt(img, *red)), qPrintable(describe(pixelAt(img, *red))));
    }

    void defaultSizesByEquipmentType() {
        const MachineSize truck = defaultMachineSize(QStringLiteral("Haul Truck"));
        const MachineSize roller = defaultMachineSize(QStringLiteral("tandem roller"));
        const MachineSize ugv = defaultMachineSize(QStringLiteral("UGV"));
        QVERIFY(truck.height > roller.height && roller.height > ugv.height);
        QVERIFY(truck.length > roller.length);
        QCOMPARE(defaultMachineSize(QStringLiteral("paver")).width, 3.2);
        QVERIFY(defaultMachineSize(QString()).length > 0.0); // unknown type still gets a visible box
    }

    void clearMessageWithoutEglAndWithoutDisplay() {
        qputenv("OCU_VIEW3D_NO_EGL", "1");
        EglOffscreenRenderer egl;
        const bool ok = egl.initialize();
        qunsetenv("OCU_VIEW3D_NO_EGL");
        QVERIFY(!ok);
        QCOMPARE(egl.backend(), EglOffscreenRenderer::Backend::None);
        QVERIFY2(egl.errorString().contains(QStringLiteral("DISPLAY")), qPrintable(egl.errorString()));
        SiteSceneRenderer scene;
        scene.setScene(makeSite());
        QVERIFY(egl.render(scene, QSize(100, 100)).isNull());
    }
};

QTEST_MAIN(TestView3dEgl)
#include "test_view3d_egl.moc"
