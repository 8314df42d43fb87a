#pragma once
// The live 2D site map, drawn with QPainter on the raster engine.
//
// Performance design (perf-anchors.md §4): everything that does not move with the machines (map roads,
// lanes, areas, the background raster, the pass-count overlay) is rendered into a cached static layer
// (SiteMapViewStaticCache.cpp) kept per scale, size and content: a pan shifts it by whole pixels and draws
// only the exposed strips, a pass-count change redraws only the changed cells' patch, and only a zoom, a
// resize, a data or palette change redraws it whole. Each frame blits it and draws the live layers on top:
// trails (1 px opaque pens: the raster engine's fast path), footprints as cached symbols, labels (machine
// names and the road and area names, decluttered together), overlays, selection and hover. Level of detail:
// footprints below 4 px become 5 px squares, glyphs and labels appear only when big enough, map names only
// when the feature is large on screen, features outside the view are culled; thousands of ways on screen are
// drawn as aliased 1 px lines straight into the pixels (MapLineRaster).
#include "models/MachineState.h"
#include "models/OwnPosition.h"
#include "models/PassCountLayer.h"
#include "models/SiteMapData.h"
#include "protocols/common/GeoFrame.h"
#include "widgets/MapLabelLayout.h"
#include "widgets/MapSymbols.h"
#include "widgets/MapTrails.h"
#include "widgets/PassCountOverlay.h"

#include <QElapsedTimer>
#include <QHash>
#include <QImage>
#include <QPointer>
#include <QTimer>
#include <QWidget>
#include <memory>

namespace ocu {

class FleetModel;
class FleetSelection;
class SiteMapView;

// Drawing of another feature above the map and the trails (e.g. the dispatch route, widgets/dispatch/).
class SiteMapOverlay {
public:
    virtual ~SiteMapOverlay() = default;
    // Every frame, after the trails: what changes from frame to frame (labels, moving parts).
    virtual void paintOverlay(QPainter& p, const SiteMapView& view) = 0;
    // Into the view's cached static layer, over the site plan and under the trails and machines: what
    // changes only with the overlay's own content and the view, so a 10 Hz frame does not draw it again.
    // The painter may be clipped to a part of the layer (a pan's strip). Call
    // SiteMapView::staticOverlayChanged() whenever it would draw something else.
    virtual void paintStatic(QPainter& p, const SiteMapView& view) {
        (void)p;
        (void)view;
    }
};
class MapBackground;
class MapLineRaster;

class SiteMapView : public QWidget {
    Q_OBJECT
public:
    enum Layer : unsigned {
        LayerMap = 1u << 0,
        LayerMapNames = 1u << 1,
        LayerMachines = 1u << 2,
        LayerLabels = 1u << 3,
        LayerTrails = 1u << 4,
        LayerOwnPosition = 1u << 5,
        LayerPassCount = 1u << 6,
        LayerLegend = 1u << 7,
        LayerScaleBar = 1u << 8,
        LayerNorthArrow = 1u << 9,
        LayerCursor = 1u << 10,
        LayerAll = 0x7ffu
    };

    explicit SiteMapView(QWidget* parent = nullptr);
    ~SiteMapView() override;

    void setFleet(FleetModel* fleet, FleetSelection* selection);
    void setSiteMap(const SiteMapData& map);
    const SiteMapData& siteMap() const { return m_map; }
    // Not owned; must outlive the view or be reset to nullptr. Call passCountChanged() after edits.
    void setPassCountLayer(const PassCountLayer* layer);
    const PassCountLayer* passCountLayer() const { return m_pass; }
    void setGeoFrame(const GeoFrame& frame) {
        m_frame = frame;
        update();
    }

    void setLayerVisible(Layer layer, bool visible);
    bool isLayerVisible(Layer layer) const { return (m_layers & layer) != 0; }
    void setPassPalette(PassPalette palette);
    PassPalette passPalette() const { return m_palette; }
    void setPassTarget(PassTarget target);
    PassTarget passTarget() const { return m_target; }
    void setTrailLength(int points) { m_trails.setCapacity(points); }

    // View: centre in site ENU metres, scale in pixels per metre.
    QPointF center() const { return m_center; }
    double scale() const { return m_scale; }
    void setView(QPointF centerEN, double pixelsPerMetre);
    void zoomBy(double factor, QPointF anchorPx);
    void panByPixels(QPointF delta);
    void centerOnMachine(const QString& id);
    void fitToContent();
    void setFollow(bool follow);
    bool isFollowing() const { return m_follow; }

    QPointF worldToScreen(QPointF en) const;
    QPointF screenToWorld(QPointF px) const;
    // Topmost machine under the pixel (footprint or 8 px pick radius), or empty.
    QString machineAt(QPointF px) const;

    // ---- Navigation ----
    void zoomToFleet();                        // every positioned machine (Home)
    void zoomToSelection();                    // the selected machines (S); nothing selected: the fleet
    bool zoomToArea(const QString& featureId); // a map feature (area, road) by id; false when unknown
    QString areaAt(QPointF px) const;          // innermost area feature under the pixel, or empty
    // Until the operator pans, zooms or centres, the view keeps fitting the site and every machine that
    // appears outside it (start-up: machines arrive over seconds).
    bool isAutoFitting() const { return m_autoFit; }
    void refitIfAuto() {
        if (m_autoFit)
            fitToContent();
    }
    // Machines outside the view, shown as arrows at the edge (grouped per 32 px of edge).
    struct EdgeIndicator {
        QPointF pos;         // screen px, on the edge
        double angleDeg = 0; // direction from the view centre to the machines (screen, 0 = right, clockwise)
        int count = 0;
        StatusCategory worst = StatusCategory::Ok;
        QString firstId; // clicking the arrow centres on this machine
    };
    const QVector<EdgeIndicator>& edgeIndicators() const { return m_edges; }

    // ---- Symbols and labels ----
    // Labels placed in the last frame (machine names, road and area names), none overlapping another.
    const QVector<MapLabelLayout::Placed>& labelPlacements() const { return m_labels.placed(); }
    // For overlays, from paintOverlay(): text the overlay draws at `screenRect` (screen px); the machines'
    // labels and the road and area names of this frame keep clear of it (no two labels overlap —
    // a station label of the compaction design or the dispatch route's label were covered by machine labels).
    void reserveLabelArea(const QRectF& screenRect) const { m_reservedLabels.push_back(screenRect); }
    const QVector<QRectF>& reservedLabelAreas() const { return m_reservedLabels; }
    QString hoveredMachine() const { return m_hoverId; }
    MapSymbolCache& symbolCache() { return m_symbols; }

    // ---- Background raster ----
    void setBackground(std::shared_ptr<const MapBackground> background);
    std::shared_ptr<const MapBackground> background() const { return m_background; }
    // Loads a GeoTIFF/MBTiles file off the GUI thread; ends in backgroundLoaded or backgroundFailed.
    void loadBackground(const QString& path);
    void setBackgroundVisible(bool visible);
    bool isBackgroundVisible() const { return m_backgroundVisible; }
    // The night palette (a dark window palette) dims the site plan and background and draws
    // dark labels with light text, so the map does not glare in a dark cab. Follows the palette by itself.
    bool isNight() const { return m_night; }

    // Draws the whole scene (what paintEvent does) into any painter, e.g. an offscreen QImage.
    void paintScene(QPainter& p, const QSize& size);
    // Overlays (not owned; remove before deleting), drawn in order after the trails.
    void addOverlay(SiteMapOverlay* overlay);
    void removeOverlay(SiteMapOverlay* overlay);
    // An overlay's paintStatic() would draw something else: the static layer is redrawn.
    void staticOverlayChanged();
    // While on, a left click on a map area emits areaClicked and leaves the selection alone.
    void setAreaPicking(bool on);
    bool isAreaPicking() const { return m_areaPicking; }

    // Frame statistics of the last paintScene (for benchmarks and the status bar).
    struct FrameStats {
        bool staticRebuilt = false;    // the whole static layer was redrawn
        bool staticUpdated = false;    // only a part: a pan's exposed strips or a changed pass-count patch
        bool trailsIntoTarget = false; // trails written into the painter's own image (SiteMapViewPerf.cpp)
        int machinesDrawn = 0;
        int featuresDrawn = 0;
    };
    FrameStats lastFrame() const { return m_stats; }

    // ---- Load (SiteMapViewPerf.cpp) ----
    // Repaints caused by data (positions, staleness, own fix, pass counts) are coalesced to at most this
    // rate (default 10 Hz: the fastest data rate); the operator's own actions (pan, zoom, hover, selection)
    // repaint at once. 0 = no cap.
    void setMaxDataFrameRate(double hz);
    double maxDataFrameRate() const { return m_maxDataHz; }
    int framesPainted() const { return m_framesPainted; } // paintEvent calls so far
    // An on-screen frame renders pass-count tiles for at most this long (the rest follow on the
    // next frames, stand-ins shown meanwhile); 0 = all at once. paintScene() called directly (reports,
    // benchmarks) always renders everything. See docs/decisions/pass-count-frame-budget.md.
    void setPassOverlayFrameBudget(double ms) { m_passBudgetMs = ms; }
    double passOverlayFrameBudget() const { return m_passBudgetMs; }
    // False while pass-count tiles of the current view are still owed (a repaint is scheduled).
    bool passOverlayComplete() const { return !m_passOverlayPending; }
    const PassCountOverlay::Stats& passOverlayStats() const { return m_passOverlay.stats(); }

public slots:
    void passCountChanged();
    void setOwnFix(const ocu::OwnFix& fix);

signals:
    void cursorMoved(QPointF en, double lat, double lon);
    void machineActivated(const QString& id); // double click
    void contextMenuRequested(const QString& id, QPoint globalPos);
    void followChanged(bool follow);
    void areaClicked(const QString& featureId);
    void backgroundLoaded(const QString& path);
    void backgroundFailed(const QString& message); // names the file and the reason

protected:
    void paintEvent(QPaintEvent* e) override;
    void resizeEvent(QResizeEvent* e) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void mouseReleaseEvent(QMouseEvent* e) override;
    void mouseDoubleClickEvent(QMouseEvent* e) override;
    void wheelEvent(QWheelEvent* e) override;
    void keyPressEvent(QKeyEvent* e) override;
    void contextMenuEvent(QContextMenuEvent* e) override;
    void leaveEvent(QEvent* e) override;
    void changeEvent(QEvent* e) override;

private:
    // Size drawn for a machine that reports none (m).
    static constexpr double kDefaultLength = 4.0;
    static constexpr double kDefaultWidth = 2.0;
    static constexpr double kFitRadius = 50000.0; // m from the site origin: machines beyond are not fitted
    static constexpr int kDenseWays = 1000;       // more features on screen: ways drawn as aliased 1 px lines

    // Data (SiteMapView.cpp).
    void onMachinesChanged(const QStringList& ids);
    void onMachineRemoved(const QString& id);
    // View transform and input (SiteMapViewInput.cpp).
    void followCurrent();
    QRectF visibleWorld(const QSize& size) const;
    void userTookOver() { m_autoFit = false; }
    bool clickEdgeIndicator(QPointF px);
    // Static layer cache: what is redrawn and where (SiteMapViewStaticCache.cpp).
    void ensureStaticLayer(const QSize& size, qreal dpr);
    void renderStaticRegion(const QSize& size, const QRect& devicePx);
    QRect passCountPatch(const QSize& size, qreal dpr) const; // device px changed since the cached counts
    void invalidateStatic() { m_staticValid = false; }
    // Static layer content: background raster, site map features, night dimming (SiteMapViewLayers.cpp).
    // `cull`: the world rectangle the painter's clip shows; `lines`: dense ways go straight into its pixels.
    void drawStatic(QPainter& p, const QSize& size, const QRectF& cull, MapLineRaster* lines);
    int visibleFeatureCount(const QRectF& world) const;
    void drawBackgroundRaster(QPainter& p, const QSize& size);
    void dimStaticForNight(QPainter& p, const QRectF& region);
    // Symbols and labels (SiteMapViewSymbols.cpp).
    struct MachineLabel {
        QPointF centre;
        double radius = 0; // half the symbol's larger side (px)
        int priority = 0;
        int row = 0;
    };
    struct MapLabelCandidate {
        QVector<QPair<QPointF, double>> spots; // centre (px) and angle (deg), tried in order
        QString text;
        MapLabelLayout::Kind kind = MapLabelLayout::Kind::Road;
        QColor colour;
        int priority = 0;
    };
    void drawTrails(QPainter& p, const QRectF& visibleWorld);
    void drawMachines(QPainter& p, const QRectF& visibleWorld);
    void drawOwnPosition(QPainter& p);
    void drawEdgeIndicators(QPainter& p);
    void collectMapLabels(const QSize& size);
    void layoutAndDrawLabels(QPainter& p, const QSize& size, QVector<MachineLabel>& machines);
    QImage labelImage(const QString& text, MapLabelLayout::Kind kind, const QColor& colour, qreal dpr);
    void drawHoverCard(QPainter& p, const QSize& size);
    // Overlays: pass counts, legend, scale bar, north arrow, cursor (SiteMapViewOverlays.cpp).
    void drawPassCount(QPainter& p, const QSize& size);
    void drawLegend(QPainter& p, const QSize& size);
    QRectF legendRect(const QSize& size) const;
    struct LegendEntries legendEntries() const;
    QString legendTitle() const;
    void drawScaleBar(QPainter& p, const QSize& size);
    void drawNorthArrow(QPainter& p, const QSize& size);
    void drawCursor(QPainter& p, const QSize& size);
    // Load: capped repaints, per-frame caches (SiteMapViewPerf.cpp).
    void requestDataRepaint();
    // Valid until the next call.
    const QImage& machineLabelImage(int row, const QString& text, qreal dpr);
    // Many trails (aliased 1 px) are rasterised straight into the painter's image after the static layer's
    // blit (painterImage), else into a copy of the static layer blitted instead of it (drawTrailsIntoBase);
    // few are drawn antialiased by drawTrails().
    QImage* painterImage(QPainter& p, QVector<QRect>& clipDevicePx) const;
    void rasterTrails(QImage& img, const QVector<QRect>& clipDevicePx, const QTransform& toDevice,
                      const QRectF& visibleWorld);
    bool drawTrailsIntoBase(const QRectF& visibleWorld, qreal dpr);

    QPointer<FleetModel> m_fleet;
    QPointer<FleetSelection> m_selection;
    SiteMapData m_map;
    QVector<QRectF> m_featureBounds;
    const PassCountLayer* m_pass = nullptr;
    GeoFrame m_frame;
    OwnFix m_own;

    unsigned m_layers = LayerAll;
    PassPalette m_palette = PassPalette::Discrete;
    PassTarget m_target;

    QSize m_viewSize; // the size the transform refers to (widget size, or the size given to paintScene)
    QPointF m_center{0, 0};
    double m_scale = 1.0; // px per metre
    bool m_follow = false;
    bool m_autoFitted = false;

    // Static layer cache and its key.
    QImage m_static;
    bool m_staticValid = false;
    QPointF m_staticCenter;
    double m_staticScale = 0;
    QPointF m_staticDrift;   // device px the cached image is off the exact view after whole-pixel pans
    int m_staticVisible = 0; // features in the cached view (dense drawing and names depend on it)
    // Pass-count colour image (one pixel per cell, row 0 = southernmost at the bottom).
    PassCountOverlay m_passOverlay; // tile pyramid (widgets/PassCountOverlay.h)
    quint64 m_passImageRevision = 0;
    PassPalette m_passImagePalette = PassPalette::Discrete;
    PassTarget m_passImageTarget{-1, -1};
    double m_passBudgetMs = 8; // half a 60 Hz frame: the rest of the map still fits in 16 ms
    bool m_inPaintEvent = false;
    bool m_passOverlayPending = false;
    bool m_passMoreQueued = false;

    MapTrails m_trails; // 120 points each (SiteMapView's constructor)

    // Interaction.
    bool m_dragging = false;
    bool m_dragMoved = false;
    QPointF m_dragLast;
    QPointF m_cursorPx{-1, -1};
    FrameStats m_stats;
    QVector<SiteMapOverlay*> m_overlays;
    bool m_areaPicking = false;

    // Symbols, labels, navigation, background, night palette.
    bool m_autoFit = true;
    MapSymbolCache m_symbols;
    MapLabelLayout m_labels;
    mutable QVector<QRectF> m_reservedLabels; // overlays' text of the frame being painted
    QVector<MapLabelCandidate> m_mapLabels;   // of the static layer's view
    QHash<QString, QImage> m_labelImages;
    QVector<EdgeIndicator> m_edges;
    QString m_hoverId;
    std::shared_ptr<const MapBackground> m_background;
    bool m_backgroundVisible = true;
    quint64 m_backgroundRequest = 0;
    bool m_night = false;

    // Load: capped data-driven repaints, per-frame caches.
    double m_maxDataHz = 10.0;
    QTimer m_dataRepaint; // single shot: the next data-driven repaint when one came too soon
    QElapsedTimer m_lastPaint;
    int m_framesPainted = 0;
    QHash<QString, QImage> m_machineLabels; // machine name label per text, at m_machineLabelsDpr
    struct RowLabel {
        QString text;
        QImage image;
    };
    QVector<RowLabel> m_rowLabels; // the label last drawn per fleet row
    qreal m_machineLabelsDpr = 0;
    QImage m_frameBase; // static layer + trails (drawTrailsIntoBase)
};

} // namespace ocu
