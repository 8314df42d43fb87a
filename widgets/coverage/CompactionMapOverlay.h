#pragma once
// The compaction job on the 2D map: the design's boundary and centre line with station ticks and
// labels every 100 m, the compaction areas with their names, and the polygon tool that draws a new area
// (click adds a point, Backspace removes the last, Enter, a double click or a click on the first point
// closes, Esc cancels; the wheel, the middle button and the arrow keys still move the map). A
// SiteMapOverlay plus an event filter on the view: SiteMapView itself is not changed.
#include "widgets/SiteMapView.h"

#include <QObject>
#include <QPointer>
#include <QPolygonF>

class QLabel;

namespace ocu {

class CompactionView;

class CompactionMapOverlay : public QObject, public SiteMapOverlay {
    Q_OBJECT
public:
    CompactionMapOverlay(SiteMapView* view, CompactionView* session);
    ~CompactionMapOverlay() override;

    void paintOverlay(QPainter& p, const SiteMapView& view) override;

    bool isDrawing() const { return m_drawing; }
    const QPolygonF& drawnPoints() const { return m_points; } // site ENU
    // The hint shown on the map while drawing (points so far, the area's size, the keys).
    QString drawingHint() const;
    // The hint's label over the map (a child widget, so machines moving under it never cover it); hidden
    // when not drawing.
    QLabel* drawingHintLabel() const { return m_hint; }
    // Clicks closer than this to the last point add none (the second click of a double click); closer than
    // kClosePx to the first point (with 3 or more points) they close the polygon.
    static constexpr double kSamePointPx = 4, kClosePx = 8;
    void setHighlightedArea(const QString& name);
    // Frames the named area (or the design's boundary when the name is empty) on the map; false if unknown.
    bool zoomToArea(const QString& name);
    // A station range picked in the panel: outlined on the map (empty: none); zoomToBand frames it.
    void setHighlightedBand(const QPolygonF& siteEN, const QString& label);
    const QPolygonF& highlightedBand() const { return m_band; }
    bool zoomToBand();

    static QColor areaColour() { return QColor(0xb0, 0x00, 0x6e); }
    static QColor centreLineColour() { return QColor(0xe0, 0x70, 0x00); }

public slots:
    void startDrawing();
    void cancelDrawing();

signals:
    void polygonFinished(const QPolygonF& siteEN); // >= 3 points
    void drawingChanged(bool drawing);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    // Colours of one paint: the night palette gets dark boxes and halos with light text.
    struct Ink {
        bool night = false;
        QColor box, halo, station;
    };
    void paintDesign(QPainter& p, const SiteMapView& view, const QRectF& screen, const Ink& ink) const;
    void paintAreas(QPainter& p, const SiteMapView& view, const QRectF& screen, const Ink& ink) const;
    void paintBand(QPainter& p, const SiteMapView& view, const QRectF& screen, const Ink& ink) const;
    void paintDrawing(QPainter& p, const SiteMapView& view) const;
    void finish();
    void updateHint();
    QPointer<SiteMapView> m_view;
    QPointer<CompactionView> m_session;
    bool m_drawing = false;
    QPolygonF m_points;
    QPointF m_hover;
    bool m_haveHover = false;
    QString m_highlight;
    QPolygonF m_band;
    QString m_bandLabel;
    bool zoomToBox(const QRectF& box);
    QPointer<QLabel> m_hint;
};

} // namespace ocu
