// SiteMapView, issue 19 §7 (load): data-driven repaints coalesced to a capped rate, and the per-frame caches
// that keep a frame with 1,000 machines free of string building and allocation. The rest of the view is in
// SiteMapView.cpp and SiteMapViewSymbols.cpp.
#include "widgets/SiteMapView.h"

#include <cmath>

namespace ocu {

void SiteMapView::setMaxDataFrameRate(double hz) {
    m_maxDataHz = std::isfinite(hz) && hz > 0 ? hz : 0.0;
    if (m_maxDataHz == 0 && m_dataRepaint.isActive()) {
        m_dataRepaint.stop();
        update();
    }
}

void SiteMapView::requestDataRepaint() {
    // New positions arrive in several batches per data period (one per protocol bridge and coalescer
    // drain); painting each would redraw 1,000 machines many times a second for no visible gain.
    if (m_dataRepaint.isActive())
        return; // a repaint is already due and will show this change too
    const qint64 intervalMs = m_maxDataHz > 0 ? qint64(std::ceil(1000.0 / m_maxDataHz)) : 0;
    const qint64 since = m_lastPaint.isValid() ? m_lastPaint.elapsed() : intervalMs;
    if (since >= intervalMs) {
        update();
        return;
    }
    m_dataRepaint.start(int(intervalMs - since));
}

const QImage& SiteMapView::machineLabelImage(const QString& text, qreal dpr) {
    // Keyed by the text alone (the colour and kind are fixed for machine labels): no key string is built per
    // label and frame.
    if (dpr != m_machineLabelsDpr || m_machineLabels.size() > 8000) {
        m_machineLabels.clear();
        m_machineLabelsDpr = dpr;
    }
    auto it = m_machineLabels.constFind(text);
    if (it == m_machineLabels.constEnd())
        it = m_machineLabels.insert(text, labelImage(text, MapLabelLayout::Kind::Machine, Qt::black, dpr));
    return *it;
}

} // namespace ocu
