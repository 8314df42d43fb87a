#pragma once
// The compaction job on the 2D map (issue 17): the design's boundary and centre line with station ticks and
// labels every 100 m, the compaction areas with their names, and the polygon tool that draws a new area
// (click adds a point, Backspace removes the last, Enter or a double click closes, Esc cancels). A
// SiteMapOverlay plus an event filter on the view: SiteMapView itself is not changed.
#include "widgets/SiteMapView.h"

#include <QObject>
#include <QPointer>
#include <QPolygonF>

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
    void finish();
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
};

} // namespace ocu
