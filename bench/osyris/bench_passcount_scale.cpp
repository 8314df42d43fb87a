// A whole job's pass counts, engine side: a 10 km x 12 m paving job with 0.34 m cells and 3 lifts (~3 M
// cells). Prints (never asserts) the figures: ingest, memory of the counts, snapshot cost, the 2D map's
// pass-count overlay redraw at 1920x1080 at several zooms (cold: tiles rendered; warm: cached tiles; after a
// change), and the restart from the ribbon store (SQLite file: open + recount). Wall and process CPU time.
//   QT_QPA_PLATFORM=offscreen ./build/bench/bench_passcount_scale
#include "models/bridges/OsyrisPassCountLayer.h"
#include "protocols/osyris/PassCountGrid.h"
#include "protocols/osyris/RibbonStore.h"
#include "widgets/PassCountOverlay.h"
#include "widgets/SiteMapView.h"

#include <QApplication>
#include <QDir>
#include <QImage>
#include <QPainter>
#include <QTemporaryDir>
#include <QWindow>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <numbers>

using namespace ocu;
using namespace ocu::osyris;

namespace {
struct Timer {
    std::chrono::steady_clock::time_point w = std::chrono::steady_clock::now();
    std::clock_t c = std::clock();
    double wallMs() const {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - w).count();
    }
    double cpuMs() const { return 1000.0 * double(std::clock() - c) / CLOCKS_PER_SEC; }
};

// The centre line: 4 km east, a 2 km arc of radius 2 km to the left, 4 km straight on (10 km).
void centre(double s, double& x, double& y, double& h) {
    const double r = 2000;
    if (s <= 4000) {
        x = s, y = 0, h = 0;
    } else if (s <= 6000) {
        const double a = (s - 4000) / r;
        x = 4000 + r * std::sin(a), y = r - r * std::cos(a), h = a;
    } else {
        const double a = 1.0;
        x = 4000 + r * std::sin(a) + (s - 6000) * std::cos(a);
        y = r - r * std::cos(a) + (s - 6000) * std::sin(a);
        h = a;
    }
}

constexpr double kLength = 10000, kStep = 0.5;
constexpr int kLifts = 3;
constexpr double kLift = 0.05, kBase = 100;

// Machine m (lane m: 6 m wide, centre at -3 / +3 m) passes forward and back `passes` times per lift.
void ribbon(std::uint8_t lane, int passes, RibbonStore* store, PassCountGrid* grid) {
    std::uint32_t slot = 0;
    const double off = lane == 1 ? -3.0 : 3.0;
    for (int lift = 0; lift < kLifts; ++lift)
        for (int pass = 0; pass < passes; ++pass) {
            const bool fwd = pass % 2 == 0;
            for (double d = 0; d <= kLength; d += kStep) {
                const double s = fwd ? d : kLength - d;
                double x, y, h;
                centre(s, x, y, h);
                CmPos p;
                p.x = float(x - std::sin(h) * off);
                p.y = float(y + std::cos(h) * off);
                p.z = float(kBase + (lift + 0.5) * kLift);
                p.yaw = float(h - std::numbers::pi / 2);
                p.dx = 6.0f;
                p.speed = 1.2;
                p.flags = kPosValid | kPosAccuracyHigh | kPosVibrating | (fwd ? kPosForward : kPosBackward);
                p.slot = slot++;
                if (store)
                    store->put(lane, {p, {}});
                if (grid)
                    grid->addPosition(lane, p);
            }
        }
}

PassCountSettings settings() {
    PassCountSettings s;
    s.liftThickness = kLift;
    s.liftBase = kBase;
    s.plausibility.maxWidthM = 6.5;
    return s;
}
} // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QTemporaryDir dir;
    const std::string db = QDir(dir.path()).filePath(QStringLiteral("ribbons.sqlite")).toStdString();

    // Ribbons into the SQLite store (what a console holds after the job), then counted.
    {
        auto st = RibbonStore::open(db);
        if (!st) {
            std::fprintf(stderr, "%s\n", st.error().c_str());
            return 1;
        }
        ribbon(1, 4, st.value().get(), nullptr);
        ribbon(2, 4, st.value().get(), nullptr);
        st.value()->commit();
        std::printf("ribbon store: %llu positions (2 machines, 3 lifts, 4 passes each)\n",
                    (unsigned long long)st.value()->totalCount());
    }
    PassCountGrid grid(settings());
    {
        Timer t;
        ribbon(1, 4, nullptr, &grid);
        ribbon(2, 4, nullptr, &grid);
        std::printf("ingest: %.0f ms wall, %.0f ms CPU\n", t.wallMs(), t.cpuMs());
    }
    std::uint64_t cells = 0;
    auto snap = grid.snapshot();
    for (int l = 0; l < snap->liftCount(); ++l)
        cells += snap->summary(l).coveredCells;
    std::printf(
        "cells with counts: %llu over %d lifts; tiles: %zu top view + per lift; counts memory %.1f MB "
        "(%.1f bytes per counted cell)\n",
        (unsigned long long)cells, snap->liftCount(), snap->tiles().size(), grid.memoryBytes() / 1048576.0,
        double(grid.memoryBytes()) / double(std::max<std::uint64_t>(cells, 1)));
    {
        Timer t;
        for (int i = 0; i < 100; ++i)
            snap = grid.snapshot();
        std::printf("snapshot: %.3f ms wall per snapshot\n", t.wallMs() / 100);
    }

    // The overlay at 1920x1080.
    OsyrisPassCountLayer layer(0.34, QPointF(0, 0));
    layer.setSnapshot(snap);
    SiteMapView view;
    view.resize(1920, 1080);
    for (auto l : {SiteMapView::LayerMachines, SiteMapView::LayerLabels, SiteMapView::LayerTrails,
                   SiteMapView::LayerOwnPosition, SiteMapView::LayerCursor})
        view.setLayerVisible(l, false);
    view.setPassCountLayer(&layer);
    QImage target(1920, 1080, QImage::Format_ARGB32_Premultiplied);
    struct Zoom {
        const char* name;
        double widthM;
        double e, n;
    } zooms[] = {{"whole job (8 km)", 8200, 4500, 2000},
                 {"1 km", 1000, 4800, 300},
                 {"100 m", 100, 5000, 480},
                 {"10 m", 10, 5000, 480}};
    for (const Zoom& z : zooms) {
        const double ppm = 1920.0 / z.widthM;
        view.setView({z.e, z.n}, ppm);
        Timer cold;
        {
            QPainter p(&target);
            view.paintScene(p, target.size());
        }
        const double coldMs = cold.wallMs();
        Timer warm;
        const int n = 20;
        for (int i = 0; i < n; ++i) {
            view.setView({z.e + (i % 2) * 1e-6, z.n}, ppm); // a different view: the static layer is redrawn
            QPainter p(&target);
            view.paintScene(p, target.size());
        }
        const double warmMs = warm.wallMs() / n, warmCpu = warm.cpuMs() / n;
        // A roller passes 50 m more: new snapshot, changed tiles only.
        {
            std::uint32_t slot = 10'000'000;
            for (double d = 4800; d <= 4850; d += kStep) {
                double x, y, h;
                centre(d, x, y, h);
                CmPos p;
                p.x = float(x);
                p.y = float(y);
                p.z = float(kBase + 2.5 * kLift);
                p.dx = 2.0f;
                p.flags = kPosValid | kPosAccuracyHigh | kPosVibrating | kPosForward;
                p.slot = slot++;
                grid.addPosition(9, p);
            }
            layer.setSnapshot(grid.snapshot());
        }
        Timer changed;
        {
            QPainter p(&target);
            view.paintScene(p, target.size());
        }
        std::printf("overlay %-17s: cold %.1f ms, warm %.2f ms wall / %.2f ms CPU, after a change %.1f ms\n",
                    z.name, coldMs, warmMs, warmCpu, changed.wallMs());
    }

    // An on-screen frame renders tiles for at most SiteMapView's budget (8 ms) and stands in for the rest;
    // the following frames finish the view. The whole job's first view and a palette change, frame by frame.
    {
        const double budget = view.passOverlayFrameBudget();
        const double w = 8200, h = w * 1080 / 1920;
        const QRectF world(4500 - w / 2, 2000 - h / 2, w, h), screen(0, 0, 1920, 1080);
        PassCountOverlay ov;
        auto run = [&](const char* what, PassPalette palette) {
            int frames = 0;
            double longest = 0, first = 0;
            Timer all;
            do {
                Timer f;
                QPainter p(&target);
                ov.draw(p, layer, palette, {3, 5}, world, screen, budget);
                p.end();
                const double ms = f.wallMs();
                if (frames++ == 0)
                    first = ms;
                longest = std::max(longest, ms);
            } while (ov.stats().pending > 0 && frames < 10000);
            std::printf(
                "overlay %s, %.0f ms budget: %d frames until complete, first %.1f ms, longest %.1f ms, "
                "all %.0f ms\n",
                what, budget, frames, first, longest, all.wallMs());
        };
        run("whole job, first view", PassPalette::Discrete);
        run("whole job, palette changed", PassPalette::Summary);

        // The same through the map widget on screen (offscreen platform): whole frames (static layer,
        // overlay, blit), painted synchronously one after the other until the overlay is complete.
        SiteMapView shown;
        shown.resize(1920, 1080);
        for (auto l : {SiteMapView::LayerMachines, SiteMapView::LayerLabels, SiteMapView::LayerTrails,
                       SiteMapView::LayerOwnPosition, SiteMapView::LayerCursor})
            shown.setLayerVisible(l, false);
        shown.setView({4500, 2000}, 1920.0 / 8200);
        shown.show();
        for (Timer wait;
             !(shown.windowHandle() && shown.windowHandle()->isExposed()) && wait.wallMs() < 5000;)
            QCoreApplication::processEvents();
        QCoreApplication::processEvents();
        shown.setPassCountLayer(&layer); // the frames below paint synchronously; no events in between
        auto frames = [&](const char* what) {
            int n = 0;
            double longest = 0;
            Timer all;
            do {
                Timer f;
                shown.repaint();
                longest = std::max(longest, f.wallMs());
                ++n;
            } while (!shown.passOverlayComplete() && n < 10000);
            std::printf("map frames at 1920x1080, %s: %d frames, longest %.1f ms, all %.0f ms\n", what, n,
                        longest, all.wallMs());
        };
        frames("whole job, first view");
        shown.setPassPalette(PassPalette::Summary);
        frames("whole job, palette changed");
        shown.setPassTarget({2, 4});
        frames("whole job, target changed");
    }

    // Restart: open the store and recount everything.
    {
        Timer t;
        auto st = RibbonStore::open(db);
        const double openMs = t.wallMs();
        PassCountGrid g(settings());
        g.advanceAll(*st.value());
        std::printf(
            "restart from the ribbon store: %.0f ms wall (open %.0f ms), %.0f ms CPU, %llu positions\n",
            t.wallMs(), openMs, t.cpuMs(), (unsigned long long)st.value()->totalCount());
    }
    return 0;
}
