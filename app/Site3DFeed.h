#pragma once
// Feeds the 3D view from the fleet model, the site map and the pass-count layer: machines through the
// fast path at most 10 times a second, the map as a full scene rebuild when its revision changes, the
// pass-count raster at most once a second, in the 2D map's palette. Selection goes both ways through the
// shared FleetSelection.
#include "models/PassCountLayer.h"
#include "models/SiteMapData.h"
#include "widgets/view3d/Scene3D.h"

#include <QObject>
#include <QPointer>

class QTimer;

namespace ocu {

class FleetModel;
class FleetSelection;
class OnScreenWatcher;
class Site3DView;

class Site3DFeed : public QObject {
    Q_OBJECT
public:
    Site3DFeed(Site3DView* view, FleetModel* fleet, FleetSelection* selection, QObject* parent = nullptr);

    void setSiteMap(const SiteMapData& map);
    // The ground from the site's DEM; an invalid grid = flat ground under the map.
    void setTerrain(const TerrainGrid3D& grid);
    void setPassCountLayer(const PassCountLayer* layer);
    // The 2D map's palette and target (the operator's choice in the pass-count panel): the 3D surface is
    // coloured cell for cell like the 2D overlay, by passCountColor(). Either recolours at the next push.
    void setPassPalette(PassPalette palette);
    void setPassTarget(PassTarget target);
    PassPalette passPalette() const { return m_palette; }
    PassTarget passTarget() const { return m_target; }
    void passCountChanged();
    // How often machines were pushed to the view (not while it is hidden).
    int machinePushCount() const;

private:
    void pushMachines();
    void pushPassCount();
    void rebuildScene();

    QPointer<Site3DView> m_view;
    FleetModel* m_fleet;
    SiteMapData m_map;
    TerrainGrid3D m_terrain;
    const PassCountLayer* m_layer = nullptr;
    quint64 m_layerRevision = 0;
    PassTarget m_target;
    PassPalette m_palette = PassPalette::Discrete; // the 2D map's default
    QTimer* m_machineTimer;
    QTimer* m_passTimer;
    OnScreenWatcher* m_onScreen = nullptr; // the view's
    bool m_machinesDirty = true;
    bool m_passDirty = false;
    int m_machinePushes = 0;
};

} // namespace ocu
