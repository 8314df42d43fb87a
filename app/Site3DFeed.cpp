#include "app/Site3DFeed.h"

#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "widgets/OnScreenWatcher.h"
#include "widgets/view3d/Site3DView.h"

#include <QTimer>

namespace ocu {

static Rgb rgb(const QColor& c) {
    return Rgb{static_cast<std::uint8_t>(c.red()), static_cast<std::uint8_t>(c.green()),
               static_cast<std::uint8_t>(c.blue())};
}

Site3DFeed::Site3DFeed(Site3DView* view, FleetModel* fleet, FleetSelection* selection, QObject* parent)
    : QObject(parent), m_view(view), m_fleet(fleet), m_machineTimer(new QTimer(this)),
      m_passTimer(new QTimer(this)) {
    connect(fleet, &FleetModel::machinesChanged, this, [this] { m_machinesDirty = true; });
    connect(fleet, &FleetModel::machineAdded, this, [this] { m_machinesDirty = true; });
    connect(fleet, &FleetModel::machineRemoved, this, [this] { m_machinesDirty = true; });
    connect(fleet, &FleetModel::machineStaleChanged, this, [this] { m_machinesDirty = true; });
    // On screen, not just visible: a dock in a tab group behind another (the console's default layout) stays
    // isVisible() with nothing of it on screen, and gets no hide event (the hidden 3D tab took
    // ~2 % of a core preparing 1,000 machines 10 times a second). The same OnScreenWatcher as the video and
    // teleop panels tells; nothing is prepared while off screen, what changed meanwhile stays
    // dirty and is pushed at once when the panel comes in front. Machines go out at most every 100 ms and
    // only when the fleet changed, so the view never draws faster than the data arrive.
    m_onScreen = new OnScreenWatcher(view);
    connect(m_machineTimer, &QTimer::timeout, this, [this] {
        if (m_machinesDirty && m_onScreen->onScreen())
            pushMachines();
    });
    connect(m_passTimer, &QTimer::timeout, this, [this] {
        if (m_passDirty && m_onScreen->onScreen())
            pushPassCount();
    });
    auto follow = [this](bool onScreen) {
        if (!onScreen) {
            m_machineTimer->stop();
            m_passTimer->stop();
            return;
        }
        if (m_passDirty)
            pushPassCount();
        if (m_machinesDirty)
            pushMachines();
        m_machineTimer->start(100);
        m_passTimer->start(1000);
    };
    connect(m_onScreen, &OnScreenWatcher::changed, this, follow);
    if (m_onScreen->onScreen())
        follow(true);
    if (selection) {
        connect(view, &Site3DView::machinePicked, selection, &FleetSelection::setCurrent);
        connect(selection, &FleetSelection::currentMachineChanged, view, &Site3DView::setSelectedMachine);
    }
    rebuildScene();
}

void Site3DFeed::setSiteMap(const SiteMapData& map) {
    m_map = map;
    rebuildScene();
}

void Site3DFeed::setTerrain(const TerrainGrid3D& grid) {
    m_terrain = grid;
    rebuildScene();
}

void Site3DFeed::setPassCountLayer(const PassCountLayer* layer) {
    if (layer != m_layer)
        m_layerRevision = 0; // another grid: its revisions say nothing about the last one pushed
    m_layer = layer;
    m_passDirty = true;
}

void Site3DFeed::setPassPalette(PassPalette palette) {
    if (palette == m_palette)
        return;
    m_palette = palette;
    m_layerRevision = 0; // same counts, new colours
    m_passDirty = m_layer != nullptr;
}

void Site3DFeed::setPassTarget(PassTarget target) {
    if (target.min == m_target.min && target.max == m_target.max)
        return;
    m_target = target;
    m_layerRevision = 0;
    m_passDirty = m_layer != nullptr;
}

void Site3DFeed::passCountChanged() {
    m_passDirty = true;
}

int Site3DFeed::machinePushCount() const {
    return m_machinePushes;
}

void Site3DFeed::pushMachines() {
    if (!m_view)
        return;
    ++m_machinePushes;
    m_machinesDirty = false;
    std::vector<Machine3D> out;
    const auto& machines = m_fleet->machinesSnapshot();
    out.reserve(static_cast<std::size_t>(machines.size()));
    for (int row = 0; row < machines.size(); ++row) {
        const MachineState& s = machines[row];
        if (!s.hasPosition)
            continue;
        const MachineSize d = defaultMachineSize(s.type);
        Machine3D m;
        m.id = s.id;
        m.shape = machineShapeFor(s.type);
        m.e = s.e;
        m.n = s.n;
        m.u = s.u;
        m.headingDeg = s.headingDeg;
        m.length = s.length > 0 ? s.length : d.length;
        m.width = s.width > 0 ? s.width : d.width;
        m.height = s.height > 0 ? s.height : d.height;
        const int modelRow = m_fleet->rowOf(s.id);
        m.colour = rgb(statusColor(modelRow >= 0 ? m_fleet->statusAt(modelRow) : statusOf(s, false)));
        m.label = s.name;
        out.push_back(std::move(m));
    }
    m_view->updateMachines(out);
}

void Site3DFeed::pushPassCount() {
    if (!m_view || !m_layer)
        return;
    m_passDirty = false;
    if (m_layer->revision() == m_layerRevision)
        return;
    m_layerRevision = m_layer->revision();
    PassCountRaster r;
    r.originE = m_layer->origin().x();
    r.originN = m_layer->origin().y();
    r.cellSize = m_layer->cellSize();
    r.cols = m_layer->columns();
    r.rows = m_layer->rows();
    if (r.cols <= 0 || r.rows <= 0 || static_cast<qint64>(r.cols) * r.rows > 16'000'000)
        return;
    std::vector<std::uint16_t> counts;
    m_layer->countsIn(QRect(0, 0, r.cols, r.rows), counts);
    r.rgba.assign(static_cast<std::size_t>(r.cols) * r.rows * 4, 0);
    for (std::size_t i = 0; i < counts.size() && i * 4 + 3 < r.rgba.size(); ++i) {
        if (counts[i] == 0)
            continue;
        const QColor c = passCountColor(counts[i], m_palette, m_target);
        r.rgba[i * 4] = static_cast<std::uint8_t>(c.red());
        r.rgba[i * 4 + 1] = static_cast<std::uint8_t>(c.green());
        r.rgba[i * 4 + 2] = static_cast<std::uint8_t>(c.blue());
        r.rgba[i * 4 + 3] = 255;
    }
    // The legend of the 2D map's palette: one swatch per count (9+ for the last), or the three classes.
    std::vector<LegendEntry> legend;
    if (m_palette == PassPalette::Discrete) {
        for (int c = 1; c <= 9; ++c)
            legend.push_back({c == 9 ? QStringLiteral("9+") : QString::number(c),
                              rgb(passCountColor(c, m_palette, m_target))});
    } else {
        const PassTarget t{2, 3}; // representative counts of the three classes (as the 2D legend)
        legend = {{tr("below %1").arg(m_target.min), rgb(passCountSummaryColor(1, t))},
                  {tr("%1–%2").arg(m_target.min).arg(m_target.max), rgb(passCountSummaryColor(2, t))},
                  {tr("above %1").arg(m_target.max), rgb(passCountSummaryColor(4, t))}};
    }
    m_view->setPassCount(r, legend);
}

void Site3DFeed::rebuildScene() {
    if (!m_view)
        return;
    Scene3D scene;
    QRectF b = m_map.bounds();
    // Machines outside the map (UGVs, the road works) must stand on the ground too.
    for (const MachineState& s : m_fleet->machinesSnapshot())
        if (s.hasPosition)
            b = b.isNull() ? QRectF(s.e - 1, s.n - 1, 2, 2) : b.united(QRectF(s.e - 1, s.n - 1, 2, 2));
    if (b.isNull())
        b = QRectF(-200, -200, 400, 400);
    b = b.adjusted(-60, -60, 60, 60);
    scene.terrain.minE = b.left();
    scene.terrain.maxE = b.right();
    scene.terrain.minN = b.top();
    scene.terrain.maxN = b.bottom();
    scene.terrain.grid = m_terrain;
    for (const MapFeature& f : m_map.features) {
        Way3D w;
        w.kind = f.kind == MapFeatureKind::Area   ? WayKind::Area
                 : f.kind == MapFeatureKind::Lane ? WayKind::Lane
                                                  : WayKind::Road;
        w.colour = rgb(taskColor(f.defaultTask));
        w.width = f.width > 0 ? f.width : (w.kind == WayKind::Lane ? 4.0 : 8.0);
        for (const QPointF& p : f.points)
            w.points.push_back({p.x(), p.y(), 0});
        // A zone without a task (the AOZ, a site boundary) is drawn as its outline: filled, it would cover
        // the terrain and everything in it with one grey sheet.
        if (w.kind == WayKind::Area && f.defaultTask.isEmpty() && w.points.size() >= 3) {
            w.kind = WayKind::Lane;
            w.width = 3.0;
            w.colour = Rgb{235, 200, 40};
            w.points.push_back(w.points.front());
        }
        scene.ways.push_back(std::move(w));
    }
    m_view->setScene(scene);
    m_machinesDirty = true;
    m_layerRevision = 0;
    m_passDirty = m_layer != nullptr;
}

} // namespace ocu
