#pragma once
// Label decluttering for the 2D map: labels are offered in priority order; each takes the first
// of its candidate rectangles that overlaps no label placed before it, or yields (is not drawn). A uniform
// grid of buckets keeps this linear in the number of labels (1,000 machines per frame).
#include <QRectF>
#include <QString>
#include <QVector>
#include <vector>

namespace ocu {

class MapLabelLayout {
public:
    enum class Kind : quint8 { Machine, Road, Area };
    struct Placed {
        QRectF rect; // screen px, axis-aligned bounds of what is drawn (a rotated label: its bounding box)
        Kind kind = Kind::Machine;
        QString text;
        int priority = 0;    // lower = more important
        double angleDeg = 0; // road names: along the road (screen, clockwise from +x)
    };

    void reset(const QRectF& viewport, double cellPx = 64);
    // True when `r` lies inside the viewport and overlaps nothing placed so far.
    bool fits(const QRectF& r) const;
    // Places r unconditionally (call after fits()).
    void place(const QRectF& r, Kind kind, const QString& text, int priority, double angleDeg = 0);
    // Blocks an area for later labels without recording a label (e.g. a legend).
    void block(const QRectF& r);
    const QVector<Placed>& placed() const { return m_placed; }

private:
    template <typename F> void forCells(const QRectF& r, F&& f) const;
    QRectF m_viewport;
    double m_cell = 64;
    int m_cols = 0, m_rows = 0;
    std::vector<std::vector<int>> m_buckets; // indices into m_rects
    QVector<QRectF> m_rects;
    QVector<Placed> m_placed;
};

} // namespace ocu
