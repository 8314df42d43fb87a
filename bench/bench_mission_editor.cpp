// bench_mission_editor: the mission plan editor while the operator drags one waypoint of a 1,000-point route
// on the 2D map at 1920x1080 (offscreen raster engine). One frame = one mouse move handled by the editor (the
// plan's move with its undo merge, the panel's table row, length and ETA, the layer's point) and the whole
// map painted (paintScene into an image, as a repaint would; the static layer is cached, as while dragging).
//  * BM_DragWaypoint/0: the whole route in view (a 1 km lawnmower pattern: markers, no numbers, no circles).
//  * BM_DragWaypoint/1: zoomed in on the dragged waypoint (numbers and tolerance circles drawn).
// The time per iteration is the frame time (ms); the budget is 16 ms (60 Hz).
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/jaus/JausVehicleBridge.h"
#include "models/jaus/MissionPlan.h"
#include "widgets/SiteMapView.h"
#include "widgets/jaus/MissionPanel.h"
#include "widgets/jaus/MissionPlanEditor.h"
#include "widgets/jaus/MissionPlanLayer.h"

#include <QApplication>
#include <QImage>
#include <QMap>
#include <QMouseEvent>
#include <QPainter>
#include <benchmark/benchmark.h>

#include <cmath>

using namespace ocu;

namespace {

const GeoPoint kOrigin{48.137, 11.575, 500};

class NoStackBridge final : public JausVehicleBridge {
public:
    QMap<quint16, JausVehicle> vehicles;
    JausConsoleIdentity identity() const override { return {}; }
    QList<quint16> subsystems() const override { return vehicles.keys(); }
    std::optional<JausVehicle> subsystem(quint16 id) const override {
        return vehicles.contains(id) ? std::optional<JausVehicle>(vehicles.value(id)) : std::nullopt;
    }
    CommandResult drive(quint16, const JausDrive&) override { return CommandResult::failure("none"); }
    CommandResult stopDriving(quint16) override { return CommandResult::failure("none"); }
    void stopAll(OutcomeCallback done) override { done({}); }
    void stopMachine(const QString&, OutcomeCallback done) override { done({}); }
    void clearStop(const QString&, OutcomeCallback done) override { done({}); }
};

void send(QWidget* w, QEvent::Type type, QPointF pos) {
    QMouseEvent e(type, pos, w->mapToGlobal(pos), type == QEvent::MouseMove ? Qt::NoButton : Qt::LeftButton,
                  type == QEvent::MouseButtonRelease ? Qt::NoButton : Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(w, &e);
}

void BM_DragWaypoint(benchmark::State& state) {
    const bool zoomed = state.range(0) != 0;
    NoStackBridge bridge;
    JausVehicle v;
    v.subsystem = 1;
    v.callSign = QStringLiteral("UGV-1");
    v.link = JausLink::Up;
    bridge.vehicles.insert(1, v);
    FleetModel fleet;
    FleetSelection selection(&fleet);
    SiteMapView map;
    map.setGeoFrame(GeoFrame(kOrigin));
    map.resize(1920, 1080);
    MissionPanel panel(&bridge, &selection);
    panel.attachMap(&map, GeoFrame(kOrigin));
    panel.setVehicle(1);
    // 1,000 waypoints: 20 rows of 50 across 1 km x 950 m.
    const GeoFrame frame(kOrigin);
    QVector<MissionWaypoint> route;
    for (int row = 0; row < 20; ++row)
        for (int k = 0; k < 50; ++k) {
            const double e = (row % 2 ? 49 - k : k) * 20.0 - 490, n = row * 50.0 - 475;
            const GeoPoint g = frame.toGeodetic({e, n, 0});
            route << MissionWaypoint{g.lat, g.lon, 1.5, 2.0};
        }
    panel.plan()->replace(route, QStringLiteral("bench"));
    const int dragged = 525;
    const EnuPoint at = frame.toLocal({route[dragged].lat, route[dragged].lon, 0});
    QImage img(1920, 1080, QImage::Format_ARGB32_Premultiplied);
    {
        QPainter p(&img);
        map.setView(zoomed ? QPointF(at.e, at.n) : QPointF(0, 0), zoomed ? 8.0 : 1.0);
        map.paintScene(p, img.size()); // the static layer, built once
    }
    panel.editor()->setEditing(true);
    const QPointF start = map.worldToScreen({at.e, at.n});
    send(&map, QEvent::MouseButtonPress, start);
    if (panel.editor()->selected() != dragged) {
        state.SkipWithError("the press did not pick the waypoint");
        return;
    }
    int i = 0;
    for (auto _ : state) {
        ++i;
        send(&map, QEvent::MouseMove, start + QPointF(40 * std::sin(i * 0.1), 30 * std::cos(i * 0.07)));
        QPainter p(&img);
        map.paintScene(p, img.size());
    }
    send(&map, QEvent::MouseButtonRelease, start);
    state.SetLabel(zoomed ? "zoomed in, 8 px/m" : "whole route, 1 px/m");
}
BENCHMARK(BM_DragWaypoint)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

} // namespace

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
