// Issue 17 in the whole console, in-process, on the built-in simulated site with the paving train on the
// shipped LandXML job: the pass-count dock holds the pass-count panel (lift picker, filters), the crew
// messages tab and the compaction areas panel, and fits a 1366 x 768 window; the design is drawn on the 2D
// map and in the 3D view; an area drawn on the map is shown; the areas' statistics follow the counts and the
// filter (as does the overlay); the legend's per-count colours are the overlay's; the coverage report is
// written from the panel and by the headless "coverage_report" command.
#include "app/HeadlessMonitor.h"
#include "app/MainWindow.h"
#include "app/SiteLoader.h"
#include "app/SiteRuntime.h"

#include "models/FleetContext.h"
#include "models/PassCountLayer.h"
#include "models/coverage/CompactionSession.h"
#include "widgets/PassCountPanel.h"
#include "widgets/SiteMapView.h"
#include "widgets/coverage/CompactionMapOverlay.h"
#include "widgets/coverage/CompactionPanel.h"
#include "widgets/osyris/CrewMessagesPanel.h"
#ifdef OCU_HAVE_OCU_VIEW3D
#include "widgets/view3d/RouteOverlay3D.h"
#include "widgets/view3d/Site3DView.h"
#endif

#include <QBuffer>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QPushButton>
#include <QSplitter>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace ocu;

namespace {
bool near(QColor a, QColor b, int tol) {
    return std::abs(a.red() - b.red()) <= tol && std::abs(a.green() - b.green()) <= tol &&
           std::abs(a.blue() - b.blue()) <= tol;
}
int countColour(const QImage& img, QRect r, QColor c, int tol) {
    int n = 0;
    r = r.intersected(img.rect());
    for (int y = r.top(); y <= r.bottom(); ++y)
        for (int x = r.left(); x <= r.right(); ++x)
            n += near(img.pixelColor(x, y), c, tol);
    return n;
}
// Covered % of the named area in the compaction panel's table; -1 when the row shows no statistics.
double coveredPercent(QTableWidget* t, const QString& area) {
    for (int r = 0; r < t->rowCount(); ++r)
        if (t->item(r, 0) && t->item(r, 0)->data(Qt::UserRole).toString() == area) {
            bool ok = false;
            const double v = t->item(r, 1)->text().toDouble(&ok);
            return ok ? v : -1;
        }
    return -2;
}
bool layerHasCounts(const PassCountLayer* pc) {
    for (int row = 0; row < pc->rows(); ++row)
        for (int col = 0; col < pc->columns(); ++col)
            if (pc->count(col, row) > 0)
                return true;
    return false;
}
} // namespace

class TestCompactionConsole : public QObject {
    Q_OBJECT
    QTemporaryDir m_home;

private slots:
    void initTestCase() {
        // Recordings, saved areas and the tile cache go to a temporary home, not the user's.
        QVERIFY(m_home.isValid());
        qputenv("HOME", m_home.path().toLocal8Bit());
        qputenv("XDG_DATA_HOME", m_home.filePath(QStringLiteral("data")).toLocal8Bit());
        qputenv("XDG_CACHE_HOME", m_home.filePath(QStringLiteral("cache")).toLocal8Bit());
        qputenv("XDG_CONFIG_HOME", m_home.filePath(QStringLiteral("config")).toLocal8Bit());
    }

    void compactionJobInTheConsole() {
        auto site = loadSite({});
        QVERIFY(site.ok());
        SiteConfig cfg = std::move(site.value());
        cfg.simulation.ahsTrucks = 2;
        cfg.simulation.osyrisPavingJob = OCU_SOURCE_DIR "/resources/designs/paving-job.xml";
        cfg.simulation.osyrisSpeedUp = 100;
        cfg.simulation.osyrisLifts = 2;
        cfg.record.enabled = false;
        SiteRuntime runtime(cfg);
        QVERIFY(runtime.start().isEmpty());
        MainWindow window;
        runtime.populate(window);
        window.resize(1366, 768);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));

        // ---- The pass-count dock: pass counts (lift picker, filters) and crew messages as tabs, the areas
        // panel under them; the whole window fits 1366 x 768 with the dock in front.
        QWidget* dockWidget = window.panelWidget(Panel::PassCounts);
        auto* split = qobject_cast<QSplitter*>(dockWidget);
        QVERIFY2(split, dockWidget ? dockWidget->metaObject()->className() : "none");
        auto* tabs = split->findChild<QTabWidget*>();
        QVERIFY(tabs);
        QCOMPARE(tabs->count(), 2);
        auto* passPanel = tabs->widget(0)->findChild<PassCountPanel*>();
        QVERIFY(passPanel);
        QVERIFY(qobject_cast<CrewMessagesPanel*>(tabs->widget(1)));
        auto* areasPanel = split->findChild<CompactionPanel*>();
        QVERIFY(areasPanel);
        QDockWidget* dock = window.dock(Panel::PassCounts);
        dock->show();
        dock->raise();
        QTest::qWait(200);
        QCOMPARE(window.size(), QSize(1366, 768));
        QVERIFY2(window.minimumSizeHint().width() <= 1366 && window.minimumSizeHint().height() <= 768,
                 qPrintable(QStringLiteral("%1x%2")
                                .arg(window.minimumSizeHint().width())
                                .arg(window.minimumSizeHint().height())));
        QVERIFY(passPanel->isVisible());
        QVERIFY(passPanel->liftPicker()->isEnabled()); // the OSYRIS source's lifts and filters are wired
        QVERIFY(areasPanel->isVisible());
        QVERIFY(areasPanel->table()->isVisible());
        QVERIFY2(areasPanel->table()->height() >= 40,
                 qPrintable(QString::number(areasPanel->table()->height())));
        for (QPushButton* b : areasPanel->findChildren<QPushButton*>()) {
            // Every button of the areas panel is inside the dock, not cut off.
            const QRect inDock(b->mapTo(dock, QPoint(0, 0)), b->size());
            QVERIFY2(dock->rect().contains(inDock), qPrintable(b->text()));
        }

        // ---- The design (shipped LandXML, the built-in site's default) on the 2D map.
        auto* session = runtime.findChild<CompactionSession*>();
        QVERIFY(session);
        QVERIFY2(session->design(), qPrintable(session->designWarnings().join(' ')));
        const auto& geo = session->mapGeometry();
        QCOMPARE(geo.centreLines.size(), 1);
        QVERIFY(geo.ticks.size() >= 50); // 5.4 km, a tick every 100 m
        QVERIFY(!geo.boundaries.isEmpty());
        auto* map = qobject_cast<SiteMapView*>(window.panelWidget(Panel::SiteMap));
        QVERIFY(map);
        window.dock(Panel::SiteMap)->raise();
        // Station 1+000 (tick 10): the centre line passes between the tick's ends, drawn in its colour.
        const auto& tick = geo.ticks[10];
        QCOMPARE(tick.station, 1000.0);
        const QPointF onLine = (tick.left + tick.right) / 2;
        map->setView(onLine + QPointF(0, 0), 3.0);
        QImage img = map->grab().toImage();
        const QPoint px = map->worldToScreen(onLine).toPoint();
        QVERIFY2(countColour(img, QRect(px - QPoint(6, 6), QSize(13, 13)),
                             CompactionMapOverlay::centreLineColour(), 10) > 0,
                 qPrintable(img.pixelColor(px).name()));
        // Nothing of the design far off it.
        map->setView(onLine + QPointF(-4000, -4000), 3.0);
        img = map->grab().toImage();
        QCOMPARE(
            countColour(img, img.rect().adjusted(0, 0, 0, -60), CompactionMapOverlay::centreLineColour(), 10),
            0);

        // ---- An area around station 0+100 ... 0+300, 8 m either side (as the map's polygon tool gives it).
        auto ring = [&](double from, double to) {
            QPolygonF left, right;
            for (const auto& t : geo.ticks)
                if (t.station >= from - 1e-6 && t.station <= to + 1e-6) {
                    const QPointF c = (t.left + t.right) / 2;
                    const QPointF dir = (t.left - c) / std::hypot(t.left.x() - c.x(), t.left.y() - c.y());
                    left << c + dir * 8;
                    right.prepend(c - dir * 8);
                }
            return left + right;
        };
        const QPolygonF lot = ring(100, 300);
        QCOMPARE(lot.size(), 6);
        QCOMPARE(session->addArea(QStringLiteral("Lot A"), lot), QString());
        // Shown on the map: its outline in the area colour along its edge.
        map->setView(lot.boundingRect().center(), 3.0);
        img = map->grab().toImage();
        const QPointF edgeMid = (lot[0] + lot[1]) / 2;
        const QPoint e = map->worldToScreen(edgeMid).toPoint();
        QVERIFY2(countColour(img, QRect(e - QPoint(4, 4), QSize(9, 9)), CompactionMapOverlay::areaColour(),
                             12) > 0,
                 qPrintable(img.pixelColor(e).name()));
        // Its name.
        auto* overlay = session->findChild<CompactionMapOverlay*>();
        QVERIFY(overlay);
        QVERIFY(overlay->zoomToArea(QStringLiteral("Lot A")));
        QVERIFY(!map->isAutoFitting());
        QVERIFY(map->scale() > 1.0);

#ifdef OCU_HAVE_OCU_VIEW3D
        // ---- In the 3D view: the centre line, the boundaries and the areas as line overlays.
        auto* v3d = window.dock(Panel::Site3D)->findChild<Site3DView*>();
        QVERIFY(v3d);
        // (The dispatch preview has a route overlay of its own, a direct child of the view.)
        int designLines = 0;
        for (RouteOverlay3D* o : v3d->findChildren<RouteOverlay3D*>())
            designLines += o->parent() != v3d;
        QCOMPARE(designLines, int(geo.centreLines.size() + geo.boundaries.size() + session->areas().size()));
#endif

        // ---- The areas' statistics follow the counts (the rollers reach the lot) ...
        window.dock(Panel::PassCounts)->raise();
        QElapsedTimer clock;
        clock.start();
        QTRY_VERIFY_WITH_TIMEOUT(coveredPercent(areasPanel->table(), QStringLiteral("Lot A")) > 0, 90000);
        const PassCountLayer* pc = map->passCountLayer();
        QVERIFY(pc);
        QVERIFY(layerHasCounts(pc));
        qInfo("Lot A covered after %lld ms", clock.elapsed());

        // ---- Per station range (the Stations tab): every 20 m of the 5.4 km alignment, 6 m either side;
        // the ranges the rollers passed have coverage; a picked range is outlined on the map, a double click
        // frames it, and leaving the tab takes the outline away.
        QTableWidget* stations = areasPanel->stationTable();
        areasPanel->tabs()->setCurrentIndex(1);
        QVERIFY(stations->isVisible());
        QTRY_VERIFY_WITH_TIMEOUT(stations->rowCount() >= 270, 10000);
        QCOMPARE(stations->item(0, 0)->text(), QStringLiteral("0+000"));
        QCOMPARE(stations->item(1, 0)->toolTip(), QStringLiteral("0+020 – 0+040"));
        int coveredRow = -1;
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                for (int r = 0; r < stations->rowCount(); ++r)
                    if (stations->item(r, 1) && stations->item(r, 1)->text().toDouble() > 0) {
                        coveredRow = r;
                        return true;
                    }
                return false;
            }(),
            30000);
        const auto table = session->coverageTable(-1);
        QCOMPARE(table.stations.size(), stations->rowCount());
        QCOMPARE(table.stationStep, 20.0);
        stations->selectRow(coveredRow);
        const QPolygonF band = overlay->highlightedBand();
        QVERIFY(band.size() >= 4);
        QCOMPARE(band, table.stations[coveredRow].band);
        // The band lies across the centre line: its width about 12 m (6 m either side).
        QVERIFY2(band.boundingRect().width() + band.boundingRect().height() >= 12 &&
                     band.boundingRect().width() + band.boundingRect().height() <= 12 + 20 + 20,
                 qPrintable(
                     QString("%1 x %2").arg(band.boundingRect().width()).arg(band.boundingRect().height())));
        window.dock(Panel::SiteMap)->raise();
        QVERIFY(overlay->zoomToBand());
        QVERIFY(map->scale() > 5.0);
        img = map->grab().toImage();
        const QPoint bandCorner = map->worldToScreen(band[0]).toPoint();
        QVERIFY2(countColour(img, QRect(bandCorner - QPoint(5, 5), QSize(11, 11)),
                             CompactionMapOverlay::centreLineColour(), 12) > 0,
                 qPrintable(img.pixelColor(bandCorner).name()));
        window.dock(Panel::PassCounts)->raise();
        if (qEnvironmentVariableIsSet("OCU_TEST_SHOTS")) // for the docs: the picked range on the map
            window.grab().save(QString::fromLocal8Bit(qgetenv("OCU_TEST_SHOTS")) +
                               "/compaction-stations.png");
        areasPanel->tabs()->setCurrentIndex(0);
        QVERIFY(overlay->highlightedBand().isEmpty());
        // ... and the filter: a speed window no roller reaches (at least 25 km/h) leaves nothing counted, in
        // the overlay's layer and in the areas' statistics alike; without it the counts come back.
        QDoubleSpinBox* speedMin = nullptr;
        for (QDoubleSpinBox* b : passPanel->findChildren<QDoubleSpinBox*>())
            if (b->suffix() == QStringLiteral(" km/h") && !speedMin)
                speedMin = b; // the first is the lower bound
        QVERIFY(speedMin);
        speedMin->setValue(25);
        QTRY_VERIFY_WITH_TIMEOUT(!layerHasCounts(pc), 60000);
        QTRY_COMPARE_WITH_TIMEOUT(coveredPercent(areasPanel->table(), QStringLiteral("Lot A")), 0.0, 30000);
        QCOMPARE(passPanel->filter().speedMin, 25 / 3.6);
        speedMin->setValue(0);
        QTRY_VERIFY_WITH_TIMEOUT(coveredPercent(areasPanel->table(), QStringLiteral("Lot A")) > 0, 60000);
        QVERIFY(layerHasCounts(pc));
        qInfo("filter on and off after %lld ms", clock.elapsed());

        // ---- The legend's per-count swatches are the overlay's colours (its palette function).
        map->setLayerVisible(SiteMapView::LayerMachines, false);
        map->setView(onLine + QPointF(-4000, -4000), 3.0); // no cells, no design: the legend alone
        img = map->grab().toImage();
        const QRect legendArea(0, img.height() / 3, 260, img.height() * 2 / 3);
        for (int c = 1; c <= 9; ++c)
            QVERIFY2(countColour(img, legendArea, passCountColor(c, PassPalette::Discrete, map->passTarget()),
                                 0) >= 40,
                     qPrintable(QString::number(c)));

        // ---- The report from the panel (PDF + CSV + GeoTIFF with one base name) ...
        QTemporaryDir out;
        const QString text = areasPanel->writeReport(out.filePath(QStringLiteral("gui.pdf")));
        QVERIFY2(text.contains(QStringLiteral("PDF, CSV, GEOTIFF")), qPrintable(text));
        for (const char* f : {"gui.pdf", "gui.csv", "gui.tif"})
            QVERIFY2(QFileInfo(out.filePath(QString::fromLatin1(f))).size() > 1000, f);
        // ... and by the headless command.
        auto* ctx = runtime.findChild<FleetContext*>();
        QVERIFY(ctx);
        QBuffer sink;
        sink.open(QIODevice::WriteOnly);
        HeadlessMonitor* mon = HeadlessMonitor::attach(ctx, &sink);
        const QJsonObject cmd{{QStringLiteral("cmd"), QStringLiteral("coverage_report")},
                              {QStringLiteral("req"), 7},
                              {QStringLiteral("pdf"), out.filePath(QStringLiteral("h.pdf"))},
                              {QStringLiteral("csv"), out.filePath(QStringLiteral("h.csv"))},
                              {QStringLiteral("geotiff"), out.filePath(QStringLiteral("h.tif"))},
                              {QStringLiteral("area"), QStringLiteral("Lot A")},
                              {QStringLiteral("lift"), QStringLiteral("all")}};
        const QByteArray line = mon->handleLine(QJsonDocument(cmd).toJson(QJsonDocument::Compact));
        const QJsonObject res = QJsonDocument::fromJson(line).object();
        QVERIFY2(res.value(QStringLiteral("ok")).toBool(), line.constData());
        QCOMPARE(res.value(QStringLiteral("req")).toInt(), 7);
        const QJsonObject written = res.value(QStringLiteral("written")).toObject();
        for (const char* k : {"pdf", "csv", "geotiff"})
            QVERIFY2(written.value(QString::fromLatin1(k)).toBool(), k);
        QVERIFY(res.value(QStringLiteral("csv_rows")).toInt() > 0);
        // The counted data's time range (the simulated positions are stamped now).
        const QDateTime from =
            QDateTime::fromString(res.value(QStringLiteral("data_from")).toString(), Qt::ISODate);
        const QDateTime to =
            QDateTime::fromString(res.value(QStringLiteral("data_to")).toString(), Qt::ISODate);
        QVERIFY2(from.isValid() && to.isValid() && from <= to, line.constData());
        QVERIFY2(std::abs(to.secsTo(QDateTime::currentDateTimeUtc())) < 600, line.constData());
        bool lotReported = false;
        for (const auto& a : res.value(QStringLiteral("areas")).toArray())
            lotReported |= a.toObject().value(QStringLiteral("name")).toString() == QLatin1String("Lot A");
        QVERIFY2(lotReported, line.constData());
        runtime.stop();
    }
};

QTEST_MAIN(TestCompactionConsole)
#include "test_compaction_console.moc"
