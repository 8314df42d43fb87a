// The compaction job in the whole console, in-process, on the built-in simulated site with the paving train
// on the shipped LandXML job: the pass-count dock holds the pass-count panel (lift picker, filters), the crew
// messages tab and the compaction areas panel, and fits a 1366 x 768 window; the design is drawn on the 2D
// map and in the 3D view; an area drawn on the map is shown; the areas' statistics follow the counts and the
// filter (as does the overlay); the legend's per-count colours are the overlay's; the coverage report is
// written from the panel and by the headless "coverage_report" command.
#include "app/HeadlessMonitor.h"
#include "app/MainWindow.h"
#include "app/SiteLoader.h"
#include "app/SiteRuntime.h"

#include "models/FleetContext.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/PassCountLayer.h"
#include "models/coverage/CompactionSession.h"
#include "models/coverage/CoverageReport.h"
#include "protocols/common/GeoFrame.h"
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
#include <QInputDialog>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <functional>

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

// Answers the modal dialogs the console opens next, one handler per dialog in order (each closes its
// dialog). Polls, since the dialogs run their own event loops inside the mouse or key event that opens them.
class ModalAnswers : public QObject {
public:
    using Handler = std::function<void(QWidget*)>;
    explicit ModalAnswers(QList<Handler> handlers) : m_handlers(std::move(handlers)) {
        connect(&m_poll, &QTimer::timeout, this, [this] {
            QWidget* w = QApplication::activeModalWidget();
            if (!w || !w->isVisible() || m_handlers.isEmpty())
                return;
            m_handlers.takeFirst()(w);
        });
        m_poll.start(20);
    }
    bool done() const { return m_handlers.isEmpty(); }

private:
    QList<Handler> m_handlers;
    QTimer m_poll;
};
// The area-name dialog: records the name it offers, then answers `name` (OK) or cancels (empty name).
ModalAnswers::Handler nameDialog(const QString& name, QString* offered) {
    return [name, offered](QWidget* w) {
        auto* d = qobject_cast<QInputDialog*>(w);
        if (!d) {
            qWarning("expected the area-name dialog, got %s", w->metaObject()->className());
            w->close();
            return;
        }
        if (offered)
            *offered = d->textValue();
        if (name.isEmpty()) {
            d->reject();
            return;
        }
        d->setTextValue(name);
        d->accept();
    };
}
ModalAnswers::Handler questionDialog(QMessageBox::StandardButton answer, QString* text) {
    return [answer, text](QWidget* w) {
        auto* m = qobject_cast<QMessageBox*>(w);
        if (!m) {
            qWarning("expected a question, got %s", w->metaObject()->className());
            w->close();
            return;
        }
        if (text)
            *text = m->text();
        m->button(answer)->click();
    };
}
} // namespace

class TestCompactionConsole : public QObject {
    Q_OBJECT
    QTemporaryDir m_home;

    // The map's polygon tool driven with the mouse and the keyboard like an operator: started
    // from the areas panel's button (which brings the map to the front), vertices clicked at known site
    // points, Backspace, Esc, Enter, a double click, a click on the first point; the areas it makes in the
    // table, their rings, statistics and outline on the map.
    void drawAreasWithTheMouse(MainWindow& window, SiteMapView* map, CompactionSession* session,
                               CompactionPanel* areasPanel, FleetContext* ctx);

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
        // 200 simulated seconds a second: positions 5 simulated s apart, a roller's 6 m between two of them
        // still under the 10 m step that breaks a traversal (PassCountSettings::maxJump).
        cfg.simulation.osyrisSpeedUp = 200;
        cfg.simulation.osyrisLifts = 2;
        cfg.record.enabled = false;
        SiteRuntime runtime(cfg);
        runtime.start();
        MainWindow window;
        runtime.populate(window);
        window.resize(1366, 768);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));

        // ---- The Compaction workspace: the pass counts (lift picker, filters), the crew messages and the
        // areas panel, each a panel of its own; the whole window fits 1366 x 768 with each of them in front.
        QVERIFY(window.offeredWorkspaces().contains(Workspace::Compaction));
        window.setWorkspace(Workspace::Compaction);
        auto* passPanel = qobject_cast<PassCountPanel*>(window.panelWidget(Panel::PassCounts));
        QVERIFY(passPanel);
        QVERIFY(qobject_cast<CrewMessagesPanel*>(window.panelWidget(QStringLiteral("crew"))));
        auto* areasPanel = qobject_cast<CompactionPanel*>(window.panelWidget(QStringLiteral("areas")));
        QVERIFY(areasPanel);
        for (const char* key : {"passcounts", "crew", "areas"})
            QVERIFY2(window.dock(QLatin1String(key))->toggleViewAction()->isChecked(), key);
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
        QDockWidget* areasDock = window.dock(QStringLiteral("areas"));
        areasDock->raise();
        QTest::qWait(200);
        QVERIFY(areasPanel->isVisible());
        QVERIFY(areasPanel->table()->isVisible());
        QVERIFY2(areasPanel->table()->height() >= 40,
                 qPrintable(QString::number(areasPanel->table()->height())));
        for (QPushButton* b : areasPanel->findChildren<QPushButton*>()) {
            // Every button of the areas panel is inside the dock, not cut off.
            const QRect inDock(b->mapTo(areasDock, QPoint(0, 0)), b->size());
            QVERIFY2(areasDock->rect().contains(inDock), qPrintable(b->text()));
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

        // ---- An area around station 0+000 ... 0+200, 8 m either side (as the map's polygon tool gives it):
        // at the start of the job, where the rollers are within seconds (the paver starts at 0+000 at 5
        // m/min).
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
        const QPolygonF lot = ring(0, 200);
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
        window.dock(QStringLiteral("areas"))
            ->raise(); // the areas panel (its tab group holds the pass counts)
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
        QElapsedTimer tableClock;
        tableClock.start();
        const auto table = session->coverageTable(-1);
        const qint64 tableNs = tableClock.nsecsElapsed();
        tableClock.restart();
        session->coverageTable(-1);
        // Printed, not asserted (a figure of a loaded machine): the refresh on the GUI thread, at most every
        // 2 s.
        qInfo("coverage table with %lld station ranges: %.1f ms, again (bands cached) %.1f ms",
              qlonglong(table.stations.size()), tableNs / 1e6, tableClock.nsecsElapsed() / 1e6);
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
        // The outline in the centre line's colour at a corner of the band (one corner may lie under the
        // legend).
        int outlined = 0;
        for (const QPointF& corner : band) {
            const QPoint c = map->worldToScreen(corner).toPoint();
            outlined += countColour(img, QRect(c - QPoint(5, 5), QSize(11, 11)),
                                    CompactionMapOverlay::centreLineColour(), 12);
        }
        QVERIFY2(outlined > 0, qPrintable(img.pixelColor(map->worldToScreen(band[0]).toPoint()).name()));
        window.dock(QStringLiteral("areas"))->raise();
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

        drawAreasWithTheMouse(window, map, session, areasPanel, runtime.findChild<FleetContext*>());
        if (QTest::currentTestFailed())
            return;
        qInfo("areas drawn with the mouse after %lld ms", clock.elapsed());

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
        // Of a rolled stretch some 170 m long (the rollers have been over station 0+160 ... 0+180), whose
        // GeoTIFF is more than its header.
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                const auto t = session->coverageTable(-1);
                return t.stations.size() > 8 && t.stations[8].coveragePercent > 0;
            }(),
            60000);
        qInfo("rolled past 0+160 after %lld ms", clock.elapsed());
        QTemporaryDir out;
        const QString text = areasPanel->writeReport(out.filePath(QStringLiteral("gui.pdf")));
        QVERIFY2(text.contains(QStringLiteral("PDF, CSV, GEOTIFF")), qPrintable(text));
        for (const char* f : {"gui.pdf", "gui.csv", "gui.tif"})
            QVERIFY2(QFileInfo(out.filePath(QString::fromLatin1(f))).size() > 1000, f);
        // ... and by the headless command.
        QBuffer sink;
        sink.open(QIODevice::WriteOnly);
        HeadlessMonitor* mon = runtime.attachHeadless(&sink);
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

void TestCompactionConsole::drawAreasWithTheMouse(MainWindow& window, SiteMapView* map,
                                                  CompactionSession* session, CompactionPanel* areasPanel,
                                                  FleetContext* ctx) {
    QVERIFY(ctx);
    auto* overlay = session->findChild<CompactionMapOverlay*>();
    QVERIFY(overlay);
    QPushButton* draw = nullptr;
    for (QPushButton* b : areasPanel->findChildren<QPushButton*>())
        if (b->text() == QLatin1String("Draw area"))
            draw = b;
    QVERIFY(draw);
    const auto& geo = session->mapGeometry();
    // Site points across the centre line: `off` metres left (+) or right (-) of it at a 100 m tick.
    auto at = [&](double station, double off) {
        for (const auto& t : geo.ticks)
            if (std::abs(t.station - station) < 1e-6) {
                const QPointF c = (t.left + t.right) / 2;
                const QPointF d = t.left - c;
                return c + d / std::hypot(d.x(), d.y()) * off;
            }
        qFatal("no tick at %f", station);
    };
    auto areaNames = [&] {
        QStringList n;
        for (const auto& a : session->mapGeometry().areas)
            n << a.first;
        return n;
    };
    auto rowOf = [&](const QString& name) {
        for (int r = 0; r < areasPanel->table()->rowCount(); ++r)
            if (areasPanel->table()->item(r, 0)->data(Qt::UserRole).toString() == name)
                return r;
        return -1;
    };
    const QStringList before = areaNames();
    const int areasBefore = session->areaCount();

    // ---- The 3D tab is in front of the map (the operator has tabbed it there): "Draw area" brings the map
    // back and gives it the keyboard.
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    window.tabifyDockWidget(window.dock(Panel::SiteMap), window.dock(Panel::Site3D));
    window.dock(Panel::Site3D)->show();
    window.dock(Panel::Site3D)->raise();
    // (A dock behind another tab stays isVisible(), with nothing of it on screen.)
    QTRY_VERIFY(map->visibleRegion().isEmpty());
    QTest::mouseClick(draw, Qt::LeftButton);
    QVERIFY(overlay->isDrawing());
    QCOMPARE(draw->text(), QStringLiteral("Cancel drawing"));
    QTRY_VERIFY(!map->visibleRegion().isEmpty());
    QTRY_VERIFY(map->hasFocus());

    // Frame stations 0+000 ... 0+300 (the rollers have been over the start of 0+000 ... 0+200 by now).
    const QPolygonF lotM{at(0, 10), at(100, 12), at(200, 10), at(200, -10), at(0, -10)};
    QRectF box = lotM.boundingRect().united(QRectF(at(300, 10), at(300, -10)).normalized());
    const double scale = std::min(0.8 * map->width() / box.width(), 0.8 * map->height() / box.height());
    QVERIFY2(scale > 0.5, qPrintable(QString::number(scale))); // a pixel is at most 2 m
    map->panByPixels({0, 0}); // the operator's view: no auto-fitting while we click
    map->setView(box.center(), scale);
    auto px = [&](QPointF world) { return map->worldToScreen(world).toPoint(); };
    for (const QPointF& w : lotM)
        QVERIFY(map->rect().contains(px(w)));
    const double pixelMetres = 1.0 / scale;

    // A machine is selected: clicks of the tool must not reach the map (a click on empty ground would
    // clear the selection, a drag would pan).
    const QString machine = ctx->fleet()->machinesSnapshot().first().id;
    ctx->selection()->setCurrent(machine);
    const QPointF centre = map->center();

    // ---- Esc cancels: two points, Enter cannot close yet (the hint says how many are needed), Esc.
    QTest::mouseClick(map, Qt::LeftButton, {}, px(at(0, 10)));
    QTest::mouseClick(map, Qt::LeftButton, {}, px(at(100, 12)));
    QCOMPARE(overlay->drawnPoints().size(), 2);
    QVERIFY2(overlay->drawingHint().startsWith(QStringLiteral("New area: 2 points (3 needed)")),
             qPrintable(overlay->drawingHint()));
    QTest::keyClick(map, Qt::Key_Return);
    QVERIFY(overlay->isDrawing());
    QCOMPARE(overlay->drawnPoints().size(), 2);
    QTest::keyClick(map, Qt::Key_Escape);
    QVERIFY(!overlay->isDrawing());
    QVERIFY(overlay->drawnPoints().isEmpty());
    QCOMPARE(draw->text(), QStringLiteral("Draw area"));
    QCOMPARE(session->areaCount(), areasBefore);
    QCOMPARE(ctx->selection()->currentId(), machine); // Esc was the tool's, not the map's "clear selection"
    QCOMPARE(map->center(), centre);
    QVERIFY(overlay->drawingHint().isEmpty());
    QVERIFY(!overlay->drawingHintLabel()->isVisible());

    // ---- Draw "Lot M": three points, a stray one taken back with Backspace, the fourth, and a double click
    // on the fifth (as the platform delivers it: press, release, press, double click, release).
    QTest::mouseClick(draw, Qt::LeftButton);
    QTRY_VERIFY(map->hasFocus());
    for (int i = 0; i < 3; ++i)
        QTest::mouseClick(map, Qt::LeftButton, {}, px(lotM[i]));
    QTest::mouseClick(map, Qt::LeftButton, {}, px(at(100, -14))); // stray
    QCOMPARE(overlay->drawnPoints().size(), 4);
    QTest::keyClick(map, Qt::Key_Backspace);
    QCOMPARE(overlay->drawnPoints().size(), 3);
    QTest::mouseClick(map, Qt::LeftButton, {}, px(lotM[3]));
    // Feedback while drawing: the hint with the points and the area so far, the points on the map.
    QVERIFY2(overlay->drawingHint().startsWith(QStringLiteral("New area: 4 points, ")),
             qPrintable(overlay->drawingHint()));
    QMouseEvent hover(QEvent::MouseMove, QPointF(px(lotM[4])), map->mapToGlobal(QPointF(px(lotM[4]))),
                      Qt::NoButton, Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(map, &hover);
    // (The live machines, their labels and the legend may cover a point: hidden for the look.)
    for (auto l : {SiteMapView::LayerMachines, SiteMapView::LayerLabels, SiteMapView::LayerLegend})
        map->setLayerVisible(l, false);
    QImage img = map->grab().toImage();
    for (auto l : {SiteMapView::LayerMachines, SiteMapView::LayerLabels, SiteMapView::LayerLegend})
        map->setLayerVisible(l, true);
    // (A label over the map: the machines moving about are drawn under it, never over it.)
    QLabel* hintLabel = overlay->drawingHintLabel();
    QVERIFY(hintLabel && hintLabel->isVisible());
    QCOMPARE(hintLabel->text(), overlay->drawingHint());
    const QRect hint = hintLabel->geometry();
    QVERIFY2(map->rect().contains(hint),
             qPrintable(QStringLiteral("%1 x %2").arg(hint.width()).arg(hint.height())));
    QVERIFY(countColour(img, hint.adjusted(2, 2, -2, -2), QColor(255, 255, 230), 4) > hint.width() * 2);
    for (int i = 0; i < 4; ++i)
        QVERIFY2(countColour(img, QRect(px(lotM[i]) - QPoint(2, 2), QSize(5, 5)), QColor(0xd0, 0x00, 0x80),
                             30) > 3,
                 qPrintable(QString::number(i)));
    QCOMPARE(ctx->selection()->currentId(), machine);
    QCOMPARE(map->center(), centre);

    QString offered;
    {
        ModalAnswers answers({nameDialog(QStringLiteral("Lot M"), &offered)});
        const QPoint last = px(lotM[4]);
        QTest::mouseClick(map, Qt::LeftButton, {}, last);
        QTest::mousePress(map, Qt::LeftButton, {}, last);
        QTest::mouseDClick(map, Qt::LeftButton, {}, last); // the name dialog runs inside
        QTest::mouseRelease(map, Qt::LeftButton, {}, last);
        QVERIFY(answers.done());
    }
    QVERIFY(!overlay->isDrawing());
    QVERIFY2(!before.contains(offered) && offered.startsWith(QStringLiteral("Area ")), qPrintable(offered));
    QCOMPARE(session->areaCount(), areasBefore + 1);
    QCOMPARE(ctx->selection()->currentId(), machine);
    QCOMPARE(map->center(), centre);
    // In the table, by its name ...
    const int row = rowOf(QStringLiteral("Lot M"));
    QVERIFY(row >= 0);
    QCOMPARE(areasPanel->table()->item(row, 0)->text(), QStringLiteral("Lot M"));
    QVERIFY2(areasPanel->statusLabel()->text().contains(QStringLiteral("Lot M")),
             qPrintable(areasPanel->statusLabel()->text()));
    // ... its ring the clicked points (5: the double click added no second copy of the last), each within
    // a pixel's worth of metres ...
    QPolygonF ring;
    for (const auto& a : session->mapGeometry().areas)
        if (a.first == QLatin1String("Lot M"))
            ring = a.second;
    QCOMPARE(ring.size(), lotM.size());
    for (int i = 0; i < lotM.size(); ++i)
        QVERIFY2(std::hypot(ring[i].x() - lotM[i].x(), ring[i].y() - lotM[i].y()) <= pixelMetres,
                 qPrintable(QStringLiteral("vertex %1 is %2 m off (a pixel is %3 m)")
                                .arg(i)
                                .arg(std::hypot(ring[i].x() - lotM[i].x(), ring[i].y() - lotM[i].y()))
                                .arg(pixelMetres)));
    // ... and its outline on the map in the area colour, along every edge (the live machines, their labels
    // and the legend may cover a part of it: they are hidden for the look).
    for (auto l : {SiteMapView::LayerMachines, SiteMapView::LayerLabels, SiteMapView::LayerLegend})
        map->setLayerVisible(l, false);
    img = map->grab().toImage();
    for (auto l : {SiteMapView::LayerMachines, SiteMapView::LayerLabels, SiteMapView::LayerLegend})
        map->setLayerVisible(l, true);
    for (int i = 0; i < lotM.size(); ++i)
        for (double f : {0.25, 0.5, 0.75}) {
            const QPoint e = px(lotM[i] + (lotM[(i + 1) % lotM.size()] - lotM[i]) * f);
            QVERIFY2(
                countColour(img, QRect(e - QPoint(3, 3), QSize(7, 7)), CompactionMapOverlay::areaColour(),
                            12) > 0,
                qPrintable(QStringLiteral("edge %1 at %2: %3").arg(i).arg(f).arg(img.pixelColor(e).name())));
        }

    // ---- Its statistics: covered % of the top view equals a count of the cells whose centres lie in the
    // ring, made here from the same pass-count snapshot (the table refreshed with no new snapshot between).
    QTRY_VERIFY_WITH_TIMEOUT(coveredPercent(areasPanel->table(), QStringLiteral("Lot M")) > 0, 60000);
    std::shared_ptr<const osyris::PassCountSnapshot> snap;
    for (int attempt = 0; attempt < 100; ++attempt) {
        snap = session->job().snapshot;
        areasPanel->refresh();
        if (session->job().snapshot == snap)
            break;
        snap.reset();
    }
    QVERIFY(snap);
    const CoverageJob job = session->job();
    const GeoFrame worksite(job.worksiteOrigin);
    QPolygonF local; // the ring in the counts' frame (ENU of the worksite origin)
    for (const auto& a : session->areas())
        if (a.name == QLatin1String("Lot M"))
            for (const GeoPoint& g : a.ring) {
                const EnuPoint p = worksite.toLocal({g.lat, g.lon, job.worksiteOrigin.alt});
                local << QPointF(p.e, p.n);
            }
    QCOMPARE(local.size(), 5);
    const double cs = snap->cellSize();
    const QRectF lb = local.boundingRect();
    qint64 cells = 0, covered = 0, atTarget = 0;
    for (auto cy = std::int32_t(std::floor(lb.top() / cs)); cy <= std::int32_t(std::ceil(lb.bottom() / cs));
         ++cy)
        for (auto cx = std::int32_t(std::floor(lb.left() / cs));
             cx <= std::int32_t(std::ceil(lb.right() / cs)); ++cx) {
            if (!local.containsPoint(QPointF((cx + 0.5) * cs, (cy + 0.5) * cs), Qt::OddEvenFill))
                continue;
            ++cells;
            const int c = snap->countAtCell(cx, cy);
            covered += c > 0;
            atTarget += c >= snap->targetMin() && c <= snap->targetMax();
        }
    // About 200 m x 20 m.
    QVERIFY2(std::abs(cells * cs * cs - 4200) < 200, qPrintable(QString::number(cells * cs * cs)));
    QVERIFY(covered > 0);
    const double wantCovered = 100.0 * double(covered) / double(cells);
    const double shown = coveredPercent(areasPanel->table(), QStringLiteral("Lot M"));
    QVERIFY2(std::abs(shown - wantCovered) <= 0.05 + 1e-9,
             qPrintable(QStringLiteral("table %1 %, counted %2 of %3 cells = %4 %")
                            .arg(shown)
                            .arg(covered)
                            .arg(cells)
                            .arg(wantCovered)));
    const double shownTarget =
        areasPanel->table()->item(rowOf(QStringLiteral("Lot M")), 2)->text().toDouble();
    QVERIFY(std::abs(shownTarget - 100.0 * double(atTarget) / double(cells)) <= 0.05 + 1e-9);
    qInfo("Lot M: %lld of %lld cells covered (%.1f %%), %lld at target", covered, cells, wantCovered,
          atTarget);

    // ---- A second area closed by a click on its first point; the name the operator types exists: the
    // console asks before replacing it, "No" goes back to the name.
    const QPolygonF lotN{at(200, 10), at(300, 10), at(300, -10), at(200, -10)};
    QTest::mouseClick(draw, Qt::LeftButton);
    for (const QPointF& w : lotN)
        QTest::mouseClick(map, Qt::LeftButton, {}, px(w));
    QCOMPARE(overlay->drawnPoints().size(), 4);
    QString question;
    {
        ModalAnswers answers({nameDialog(QStringLiteral("Lot M"), &offered),
                              questionDialog(QMessageBox::No, &question),
                              nameDialog(QStringLiteral("Lot N"), &offered)});
        QTest::mouseClick(map, Qt::LeftButton, {}, px(lotN[0]) + QPoint(3, -2)); // on the first point
        QVERIFY(answers.done());
    }
    QVERIFY(!overlay->isDrawing());
    QVERIFY2(question.contains(QStringLiteral("Lot M")), qPrintable(question));
    QCOMPARE(offered, QStringLiteral("Lot M")); // the second dialog keeps what was typed
    QCOMPARE(session->areaCount(), areasBefore + 2);
    QVERIFY(rowOf(QStringLiteral("Lot N")) >= 0);
    for (const auto& a : session->mapGeometry().areas) {
        if (a.first == QLatin1String("Lot M"))
            QCOMPARE(a.second.size(), 5); // not replaced
        if (a.first == QLatin1String("Lot N"))
            QCOMPARE(a.second.size(), 4);
    }

    // ---- Enter closes; cancelling the name discards the outline.
    QTest::mouseClick(draw, Qt::LeftButton);
    for (const QPointF& w : {at(0, 4), at(100, 4), at(100, -4)})
        QTest::mouseClick(map, Qt::LeftButton, {}, px(w));
    {
        ModalAnswers answers({nameDialog(QString(), &offered)});
        QTest::keyClick(map, Qt::Key_Return);
        QVERIFY(answers.done());
    }
    QVERIFY(!overlay->isDrawing());
    QCOMPARE(session->areaCount(), areasBefore + 2);
    QCOMPARE(areasPanel->statusLabel()->text(), QStringLiteral("The drawn area was discarded."));

    // ---- The button cancels too.
    QTest::mouseClick(draw, Qt::LeftButton);
    QTest::mouseClick(map, Qt::LeftButton, {}, px(at(0, 4)));
    QTest::mouseClick(draw, Qt::LeftButton);
    QVERIFY(!overlay->isDrawing());
    QCOMPARE(session->areaCount(), areasBefore + 2);
    QCOMPARE(ctx->selection()->currentId(), machine);
    QCOMPARE(map->center(), centre);
}

QTEST_MAIN(TestCompactionConsole)
#include "test_compaction_console.moc"
