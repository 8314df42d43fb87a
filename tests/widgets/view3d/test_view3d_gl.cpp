// Interactive path under xvfb-run (xcb platform, Mesa llvmpipe through GLX): VTK inside the Qt 6
// QOpenGLWidget. Proves: the machine's colour is at its projected pixel, a click there picks it (signal +
// selection), mouse drags reach the VTK interactor style, the follow camera keeps a moving machine centred,
// and a window grab() contains the 3D picture.
#include "tests/widgets/view3d/SyntheticSite.h"
#include "widgets/view3d/EglOffscreenRenderer.h"
#include "widgets/view3d/Site3DView.h"
#include "widgets/view3d/SiteSceneRenderer.h"
#include "widgets/view3d/VtkOpenGLWidget.h"

#include <QApplication>
#include <QLabel>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QSignalSpy>
#include <QTabWidget>
#include <QVBoxLayout>
#include <QtTest>

using namespace ocu;
using namespace ocu::testsite;

namespace {

QString describe(QRgb p) {
    return QStringLiteral("(%1,%2,%3)").arg(qRed(p)).arg(qGreen(p)).arg(qBlue(p));
}

QRgb pixelAt(const QImage& img, QPointF p) {
    return img.pixel(static_cast<int>(p.x()), static_cast<int>(p.y()));
}

void sendMouse(QWidget* w, QEvent::Type type, QPointF pos, Qt::MouseButton button, Qt::MouseButtons buttons) {
    QMouseEvent e(type, pos, w->mapToGlobal(pos), button, buttons, Qt::NoModifier);
    QApplication::sendEvent(w, &e);
}

} // namespace

class TestView3dGl : public QObject {
    Q_OBJECT

private:
    std::unique_ptr<Site3DView> m_view;

    VtkOpenGLWidget* gl() const { return qobject_cast<VtkOpenGLWidget*>(m_view->viewWidget()); }
    QImage frame() const { return gl()->grabFramebuffer(); } // renders the current scene

private slots:
    void init() {
        m_view = std::make_unique<Site3DView>();
        m_view->resize(800, 600);
        m_view->setScene(makeSite());
        m_view->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_view.get(), 30000)); // an X server round trip
        QCOMPARE(m_view->backend(), Site3DView::Backend::OpenGLWidget);
        QVERIFY(gl() != nullptr);
        QTRY_VERIFY_WITH_TIMEOUT(gl()->isInitialized(), 30000);
    }
    void cleanup() { m_view.reset(); }

    void machineColourAtProjectedPixelAndPick() {
        const QImage img = frame();
        QCOMPARE(img.size(), m_view->viewPixelSize());
        SiteSceneRenderer& scene = m_view->sceneRenderer();
        const Machine3D m1 = *scene.machine(QStringLiteral("M1"));
        const auto p = scene.project(m1.e, m1.n, m1.u + m1.height);
        QVERIFY(p);
        QVERIFY2(isMagenta(pixelAt(img, *p)), qPrintable(describe(pixelAt(img, *p))));
        const auto road = scene.project(-60.0, 0.0, scene.terrainHeight(-60.0, 0.0));
        QVERIFY(road);
        QVERIFY2(isRoadGrey(pixelAt(img, *road)), qPrintable(describe(pixelAt(img, *road))));

        // A real click on the widget goes through the adapter's event handling and the picker.
        QSignalSpy picked(m_view.get(), &Site3DView::machinePicked);
        QTest::mouseClick(gl(), Qt::LeftButton, Qt::NoModifier, p->toPoint());
        QCOMPARE(picked.count(), 1);
        QCOMPARE(picked.at(0).at(0).toString(), QStringLiteral("M1"));
        QCOMPARE(m_view->selectedMachine(), QStringLiteral("M1"));

        // Clicking bare ground picks nothing.
        const auto ground = scene.project(-70.0, 60.0, scene.terrainHeight(-70.0, 60.0));
        QVERIFY(ground);
        QTest::mouseClick(gl(), Qt::LeftButton, Qt::NoModifier, ground->toPoint());
        QCOMPARE(picked.count(), 1);

        // The window grab (what --screenshot saves) contains the 3D picture too.
        const QImage shot = m_view->grab().toImage();
        if (const QString dump = qEnvironmentVariable("OCU_VIEW3D_DUMP"); !dump.isEmpty())
            shot.save(dump + QStringLiteral("/panel_gl.png"));
        const QPointF inWindow = *p + QPointF(gl()->mapTo(m_view.get(), QPoint(0, 0)));
        QVERIFY2(isMagenta(pixelAt(shot, inWindow)), qPrintable(describe(pixelAt(shot, inWindow))));
    }

    // A double-click on a machine in the GL view selects it and the camera follows it.
    void doubleClickSelectsAndFollows() {
        frame();
        SiteSceneRenderer& scene = m_view->sceneRenderer();
        const Machine3D m1 = *scene.machine(QStringLiteral("M1"));
        const auto p = scene.project(m1.e, m1.n, m1.u + m1.height);
        QVERIFY(p);
        QSignalSpy activated(m_view.get(), &Site3DView::machineActivated);
        QTest::mouseDClick(gl(), Qt::LeftButton, Qt::NoModifier, p->toPoint());
        QCOMPARE(activated.count(), 1);
        QCOMPARE(activated.at(0).at(0).toString(), QStringLiteral("M1"));
        QCOMPARE(m_view->selectedMachine(), QStringLiteral("M1"));
        QCOMPARE(m_view->cameraMode(), CameraMode::FollowSelected);
    }

    void mouseDragRotatesTheCamera() {
        frame();
        SiteSceneRenderer& scene = m_view->sceneRenderer();
        const auto before = scene.project(80.0, 80.0, scene.terrainHeight(80.0, 80.0));
        QVERIFY(before);
        sendMouse(gl(), QEvent::MouseButtonPress, QPointF(400, 300), Qt::LeftButton, Qt::LeftButton);
        for (int i = 1; i <= 10; ++i)
            sendMouse(gl(), QEvent::MouseMove, QPointF(400 + 15 * i, 300), Qt::NoButton, Qt::LeftButton);
        sendMouse(gl(), QEvent::MouseButtonRelease, QPointF(550, 300), Qt::LeftButton, Qt::NoButton);
        frame();
        const auto after = scene.project(80.0, 80.0, scene.terrainHeight(80.0, 80.0));
        QVERIFY(after);
        QVERIFY2(QLineF(*before, *after).length() > 20.0, "a drag must orbit the camera");
    }

    void followCameraKeepsTheMachineCentred() {
        m_view->setSelectedMachine(QStringLiteral("M2"));
        m_view->setCameraMode(CameraMode::FollowSelected);
        SiteSceneRenderer& scene = m_view->sceneRenderer();
        std::vector<Machine3D> machines = scene.scene().machines;
        const QPointF centre(m_view->viewPixelSize().width() / 2.0, m_view->viewPixelSize().height() / 2.0);
        std::optional<QPointF> fixedBefore;
        for (int step = 0; step < 6; ++step) {
            Machine3D& m2 = machines[1];
            m2.e += 12.0;
            m2.n += 7.0;
            m2.u = groundU(m2.e, m2.n);
            m2.headingDeg = 60.0;
            m_view->updateMachines(machines);
            const QImage img = frame();
            const Machine3D placed = *scene.machine(QStringLiteral("M2")); // u is on the terrain
            const auto p = scene.project(placed.e, placed.n, placed.u + placed.height / 2.0);
            QVERIFY(p);
            QVERIFY2(QLineF(*p, centre).length() < 3.0,
                     qPrintable(QStringLiteral("machine at %1,%2").arg(p->x()).arg(p->y())));
            QVERIFY2(isCyan(pixelAt(img, centre)), qPrintable(describe(pixelAt(img, centre))));
            // The world moves under the camera: a fixed ground point does not stay put.
            const auto fixed = scene.project(0.0, 0.0, scene.terrainHeight(0.0, 0.0));
            QVERIFY(fixed);
            if (fixedBefore)
                QVERIFY(QLineF(*fixed, *fixedBefore).length() > 1.0);
            fixedBefore = fixed;
        }
    }

    // Moving the panel into another top-level window recreates Qt's GL context; VTK must follow.
    void survivesContextRecreationOnReparent() {
        frame();
        QWidget other;
        other.resize(800, 640);
        auto* layout = new QVBoxLayout(&other);
        Site3DView* view = m_view.release();
        QSignalSpy contextGone(qobject_cast<VtkOpenGLWidget*>(view->viewWidget())->context(),
                               &QOpenGLContext::aboutToBeDestroyed);
        layout->addWidget(view);
        other.show();
        QVERIFY(QTest::qWaitForWindowExposed(&other, 30000));
        auto* glw = qobject_cast<VtkOpenGLWidget*>(view->viewWidget());
        QTRY_VERIFY_WITH_TIMEOUT(glw->isInitialized(), 30000);
        const QImage img = glw->grabFramebuffer();
        QCOMPARE(contextGone.count(), 1); // the old context really went away
        SiteSceneRenderer& scene = view->sceneRenderer();
        const Machine3D m1 = *scene.machine(QStringLiteral("M1"));
        const auto p = scene.project(m1.e, m1.n, m1.u + m1.height);
        QVERIFY(p);
        QVERIFY2(isMagenta(pixelAt(img, *p)), qPrintable(describe(pixelAt(img, *p))));
        // `other` owns the view now and deletes it.
    }

    // Headless fallback when EGL is unavailable but an X server is: VTK's own offscreen X window.
    // A 3D panel in a tab that is not raised creates no QOpenGLWidget (a window holding one is
    // composed through OpenGL on every repaint, which cost the GUI thread and Mesa's threads with the 2D map
    // shown); raising the tab creates it and draws.
    void noGlWidgetUntilTheTabIsRaised() {
        QTabWidget tabs;
        tabs.resize(800, 600);
        tabs.addTab(new QLabel(QStringLiteral("2D")), QStringLiteral("2D"));
        auto* view = new Site3DView;
        view->setScene(makeSite());
        tabs.addTab(view, QStringLiteral("3D"));
        tabs.show();
        QVERIFY(QTest::qWaitForWindowExposed(&tabs, 30000));
        QTest::qWait(200);
        QCOMPARE(view->findChild<VtkOpenGLWidget*>(), nullptr);
        QCOMPARE(view->renderCount(), std::uint64_t(0));
        tabs.setCurrentIndex(1);
        QTRY_VERIFY_WITH_TIMEOUT(view->findChild<VtkOpenGLWidget*>() != nullptr, 30000);
        QTRY_VERIFY_WITH_TIMEOUT(view->renderCount() > 0, 30000);
    }
    void xOffscreenFallbackRendersTheScene() {
        qputenv("OCU_VIEW3D_NO_EGL", "1");
        EglOffscreenRenderer offscreen;
        const bool ok = offscreen.initialize();
        qunsetenv("OCU_VIEW3D_NO_EGL");
        QVERIFY2(ok, qPrintable(offscreen.errorString()));
        QCOMPARE(offscreen.backend(), EglOffscreenRenderer::Backend::XOffscreen);
        m_view.reset(); // a vtkRenderer lives in one window at a time: use a scene of our own
        SiteSceneRenderer scene;
        scene.setScene(makeSite());
        const QImage img = offscreen.render(scene, QSize(640, 480));
        QCOMPARE(img.size(), QSize(640, 480));
        const Machine3D m1 = *scene.machine(QStringLiteral("M1"));
        const auto p = scene.project(m1.e, m1.n, m1.u + m1.height);
        QVERIFY(p);
        QVERIFY2(isMagenta(pixelAt(img, *p)), qPrintable(describe(pixelAt(img, *p))));
        const auto road = scene.project(-60.0, 0.0, scene.terrainHeight(-60.0, 0.0));
        QVERIFY(road);
        QVERIFY2(isRoadGrey(pixelAt(img, *road)), qPrintable(describe(pixelAt(img, *road))));
    }
};

int main(int argc, char** argv) {
    Site3DView::prepareDefaultFormat(); // before QApplication, as the application does
    QApplication app(argc, argv);
    TestView3dGl test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_view3d_gl.moc"
