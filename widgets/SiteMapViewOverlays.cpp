// SiteMapView: what is drawn over the map: the pass-count layer and its legend, the scale bar, the north
// arrow, the cursor read-out, and the overlays other features register (the dispatch route, the compaction
// design).
#include "widgets/SiteMapView.h"

#include <QPainter>
#include <cmath>

namespace ocu {

namespace {
double niceLength(double metres) {
    const double p = std::pow(10.0, std::floor(std::log10(metres)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * p >= metres)
            return m * p;
    return 10 * p;
}
} // namespace

void SiteMapView::addOverlay(SiteMapOverlay* overlay) {
    if (overlay && !m_overlays.contains(overlay))
        m_overlays.push_back(overlay);
    staticOverlayChanged(); // its static part
}

void SiteMapView::removeOverlay(SiteMapOverlay* overlay) {
    if (m_overlays.removeAll(overlay) > 0)
        staticOverlayChanged();
}

void SiteMapView::staticOverlayChanged() {
    invalidateStatic();
    update();
}

void SiteMapView::drawPassCount(QPainter& p, const QSize& size) {
    // A tile pyramid of cached images (PassCountOverlay), any zoom, only changed tiles redrawn.
    m_passOverlay.draw(p, *m_pass, m_palette, m_target, visibleWorld(size),
                       QRectF(QPointF(0, 0), QSizeF(size)), m_inPaintEvent ? m_passBudgetMs : 0);
    m_passOverlayPending = m_passOverlay.stats().pending > 0;
    if (m_passOverlayPending && !m_passMoreQueued) {
        // The next frame at once (not behind the data-rate cap): the operator waits for these tiles.
        m_passMoreQueued = true;
        QTimer::singleShot(0, this, [this] {
            m_passMoreQueued = false;
            update();
        });
    }
    m_passImageRevision = m_pass->revision(); // what the static layer shows (ensureStaticLayer)
    m_passImagePalette = m_palette;
    m_passImageTarget = m_target;
}

// The legend's entries: the nine pass counts, or the three classes against the target (with their short
// forms for the one-row legend of a small map).
struct LegendEntries {
    QStringList labels, shortLabels;
    QVector<QColor> colours;
};

namespace {

// A legend that would take more than this share of the map's height becomes one row (a small map, such as
// the UGV workspace's above the drive controls, keeps its picture).
constexpr double kLegendMaxHeightShare = 0.4;

struct LegendLayout {
    QRect box;
    bool oneRow = false;
    int lineHeight = 0;
    int swatch = 0; // one-row: the width of each colour cell
};

LegendLayout layOutLegend(const QFontMetrics& fm, const QString& title, const LegendEntries& e,
                          const QSize& size) {
    LegendLayout l;
    l.lineHeight = fm.height() + 2;
    const int columnH = l.lineHeight * (int(e.labels.size()) + 1) + 8;
    l.oneRow = columnH > size.height() * kLegendMaxHeightShare;
    if (!l.oneRow) {
        int w = fm.horizontalAdvance(title) + 12;
        for (const QString& s : e.labels)
            w = std::max(w, fm.horizontalAdvance(s) + 34);
        l.box = QRect(8, size.height() - columnH - 30, w, columnH);
        return l;
    }
    for (const QString& s : e.shortLabels)
        l.swatch = std::max(l.swatch, fm.horizontalAdvance(s) + 8);
    const int h = l.lineHeight + 8;
    const int w = 6 + fm.horizontalAdvance(title) + 6 + l.swatch * int(e.shortLabels.size()) + 6;
    l.box = QRect(8, size.height() - h - 30, w, h);
    return l;
}

} // namespace

LegendEntries SiteMapView::legendEntries() const {
    LegendEntries e;
    if (m_palette == PassPalette::Discrete) {
        for (int c = 1; c <= 9; ++c) {
            e.labels << (c == 9 ? QStringLiteral("9+") : QString::number(c));
            e.colours << passCountDiscreteColor(c);
        }
        e.shortLabels = e.labels;
    } else {
        e.labels << tr("below (<%1)").arg(m_target.min)
                 << tr("within %1–%2").arg(m_target.min).arg(m_target.max)
                 << tr("above (>%1)").arg(m_target.max);
        e.shortLabels << QStringLiteral("<%1").arg(m_target.min)
                      << QStringLiteral("%1–%2").arg(m_target.min).arg(m_target.max)
                      << QStringLiteral(">%1").arg(m_target.max);
        const PassTarget t{2, 3}; // representative counts for the three classes
        e.colours << passCountSummaryColor(1, t) << passCountSummaryColor(2, t)
                  << passCountSummaryColor(4, t);
    }
    return e;
}

QString SiteMapView::legendTitle() const {
    return tr("Passes · target %1–%2").arg(m_target.min).arg(m_target.max);
}

void SiteMapView::drawLegend(QPainter& p, const QSize& size) {
    const LegendEntries e = legendEntries();
    QFont font = p.font();
    font.setPointSizeF(8);
    font.setBold(false);
    p.setFont(font);
    const QFontMetrics fm(font);
    const QString title = legendTitle();
    const LegendLayout l = layOutLegend(fm, title, e, size);
    const QRect box = l.box;
    p.setRenderHint(QPainter::Antialiasing, false);
    // Night palette: a dark box with light text like the machine labels (a white box glared at night).
    p.fillRect(box, m_night ? QColor(30, 30, 34, 235) : QColor(255, 255, 255, 230));
    p.setPen(QPen(m_night ? QColor(0x90, 0x90, 0x90) : QColor(Qt::gray), 0));
    p.drawRect(box);
    const QColor text = m_night ? QColor(0xe6, 0xe6, 0xe0) : QColor(Qt::black);
    p.setPen(text);
    p.drawText(box.left() + 6, box.top() + 4 + fm.ascent(), title);
    if (l.oneRow) {
        // Each count's colour with its number in it, in black or white by the colour's lightness.
        int x = box.left() + 6 + fm.horizontalAdvance(title) + 6;
        for (int i = 0; i < e.shortLabels.size(); ++i, x += l.swatch) {
            const QRect cell(x, box.top() + 3, l.swatch, l.lineHeight + 2);
            p.fillRect(cell, e.colours[i]);
            p.setPen(e.colours[i].lightnessF() > 0.55 ? QColor(Qt::black) : QColor(Qt::white));
            p.drawText(cell, Qt::AlignCenter, e.shortLabels[i]);
        }
    } else {
        for (int i = 0; i < e.labels.size(); ++i) {
            const int y = box.top() + 4 + l.lineHeight * (i + 1);
            p.fillRect(QRect(box.left() + 6, y + 1, 18, l.lineHeight - 4), e.colours[i]);
            p.drawText(box.left() + 30, y + fm.ascent(), e.labels[i]);
        }
    }
    p.setRenderHint(QPainter::Antialiasing, true);
}

QRectF SiteMapView::legendRect(const QSize& size) const {
    QFont font = this->font();
    font.setPointSizeF(8);
    return layOutLegend(QFontMetrics(font), legendTitle(), legendEntries(), size).box;
}

void SiteMapView::drawScaleBar(QPainter& p, const QSize& size) {
    const double metres = niceLength(120.0 / m_scale);
    const double px = metres * m_scale;
    const QPointF end(size.width() - 16, size.height() - 30);
    const QPointF start = end - QPointF(px, 0);
    p.setPen(QPen(m_night ? QColor(0xe6, 0xe6, 0xe0) : QColor(Qt::black), 2)); // legible on the dimmed ground
    p.drawLine(start, end);
    p.drawLine(start, start - QPointF(0, 6));
    p.drawLine(end, end - QPointF(0, 6));
    const QString text =
        metres >= 1000 ? QStringLiteral("%1 km").arg(metres / 1000) : QStringLiteral("%1 m").arg(metres);
    p.drawText(QRectF(start.x(), end.y() - 22, px, 16), Qt::AlignCenter, text);
}

void SiteMapView::drawNorthArrow(QPainter& p, const QSize& size) {
    const QPointF c(size.width() - 28, 34);
    QPolygonF arrow;
    arrow << c + QPointF(0, -18) << c + QPointF(8, 10) << c + QPointF(0, 4) << c + QPointF(-8, 10);
    p.setPen(QPen(m_night ? QColor(0xe6, 0xe6, 0xe0) : QColor(Qt::black), 0));
    p.setBrush(m_night ? QColor(0xc8, 0xc8, 0xc4) : QColor(0x30, 0x30, 0x30));
    p.drawPolygon(arrow);
    p.setBrush(Qt::NoBrush);
    p.drawText(QRectF(c.x() - 8, c.y() + 10, 16, 16), Qt::AlignCenter, QStringLiteral("N"));
}

void SiteMapView::drawCursor(QPainter& p, const QSize& size) {
    if (m_cursorPx.x() < 0)
        return;
    const QPointF w = screenToWorld(m_cursorPx);
    const GeoPoint g = m_frame.toGeodetic({w.x(), w.y(), 0});
    const QString text = QStringLiteral("E %1 m  N %2 m   %3°  %4°")
                             .arg(w.x(), 0, 'f', 1)
                             .arg(w.y(), 0, 'f', 1)
                             .arg(g.lat, 0, 'f', 7)
                             .arg(g.lon, 0, 'f', 7);
    const QFontMetrics fm(p.font());
    const QRect box(0, size.height() - fm.height() - 6, fm.horizontalAdvance(text) + 12, fm.height() + 6);
    p.fillRect(box, m_night ? QColor(30, 30, 34, 220) : QColor(255, 255, 255, 210));
    p.setPen(m_night ? QColor(0xe6, 0xe6, 0xe0) : QColor(Qt::black));
    p.drawText(box.adjusted(6, 3, 0, 0), Qt::AlignLeft | Qt::AlignTop, text);
}

} // namespace ocu
