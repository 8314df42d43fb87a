// `ocu --screenshot 3d.png --view 3d` on the built-in simulated site, twice: with no X
// server at all (offscreen platform, EGL surfaceless) and under Xvfb (xcb platform, QOpenGLWidget). The
// picture must show terrain, the haul roads and machines, found by their colours.
#include "tests/support/BuiltProtocols.h"

#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

namespace {

struct Census {
    int terrain = 0, road = 0, autonomous = 0, ok = 0, total = 0;
};

// Lit surfaces are the base colour scaled by the lighting: compare chromaticity and allow brightness to vary.
bool shadeOf(QColor px, QColor base, double tol) {
    const double s = px.redF() + px.greenF() + px.blueF();
    const double t = base.redF() + base.greenF() + base.blueF();
    if (s < 0.05 || t < 0.05)
        return false;
    const double dr = px.redF() / s - base.redF() / t, dg = px.greenF() / s - base.greenF() / t;
    const double k = s / t;
    return std::abs(dr) < tol && std::abs(dg) < tol && k > 0.45 && k < 1.6;
}

Census census(const QImage& img) {
    Census c;
    const QColor terrain(150, 140, 110), road(0x8c, 0x6d, 0x46), autonomous(0x1e, 0x6f, 0xe8),
        ok(0x2e, 0xb8, 0x2e);
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const QColor px = img.pixelColor(x, y);
            ++c.total;
            if (shadeOf(px, autonomous, 0.05))
                ++c.autonomous;
            else if (shadeOf(px, ok, 0.05))
                ++c.ok;
            else if (shadeOf(px, road, 0.02))
                ++c.road;
            else if (shadeOf(px, terrain, 0.02))
                ++c.terrain;
        }
    return c;
}

} // namespace

class TestOcu3dScreenshot : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

    QImage shoot(bool xvfb) {
        const QString png = m_dir.filePath(xvfb ? "3d-xvfb.png" : "3d-offscreen.png");
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove("DISPLAY");
        env.insert("XDG_CONFIG_HOME", m_dir.path());
        env.insert("XDG_CACHE_HOME", m_dir.path()); // the map tile cache
        // The simulated site's data is on screen well before the window is (0.3 s of settling suffices even
        // at nice 10 beside two CPU hogs); 2 s leaves a wide margin without a 6 s wait per picture.
        const QStringList args{"--screenshot", png, "--view", "3d", "--size", "1280x900", "--settle", "2"};
        if (xvfb) {
            env.insert("QT_QPA_PLATFORM", "xcb");
            p.setProcessEnvironment(env);
            p.start("xvfb-run",
                    QStringList{"-a", "-s", "-screen 0 1600x1000x24 -nolisten tcp", OCU_BINARY} + args);
        } else {
            env.insert("QT_QPA_PLATFORM", "offscreen");
            p.setProcessEnvironment(env);
            p.start(OCU_BINARY, args);
        }
        if (!p.waitForFinished(90000)) {
            p.kill();
            p.waitForFinished();
        }
        if (p.exitCode() != 0)
            qWarning("%s", p.readAllStandardError().constData());
        return QImage(png);
    }

    void check(const QImage& img) {
        QVERIFY(!img.isNull());
        const Census c = census(img);
        qInfo("pixels: terrain %d, road %d, autonomous machines %d, ok machines %d of %d", c.terrain, c.road,
              c.autonomous, c.ok, c.total);
        QVERIFY2(c.terrain > c.total / 50, "terrain");
        if (ocutest::kWithIso23725) // the haul roads are the ISO 23725 map's
            QVERIFY2(c.road > 200, "haul roads");
        QVERIFY2(c.autonomous + c.ok > 8, "machines");
    }

private slots:
    void withoutAnyXServer() { check(shoot(false)); }
    void underXvfb() { check(shoot(true)); }
};

QTEST_GUILESS_MAIN(TestOcu3dScreenshot)
#include "test_ocu_3d_screenshot.moc"
