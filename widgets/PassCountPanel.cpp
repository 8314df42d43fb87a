#include "widgets/PassCountPanel.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPainter>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>

namespace ocu {

namespace {
// 1, 2 or 5 times a power of ten, at least v (an axis end that reads well).
double niceCeil(double v) {
    if (v <= 0)
        return 1;
    const double p = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * p >= v)
            return m * p;
    return 10 * p;
}
QString areaText(double m2) {
    return m2 >= 10000
               ? QStringLiteral("%1 ha").arg(QLocale().toString(m2 / 10000.0, 'f', m2 >= 100000 ? 0 : 1))
               : QStringLiteral("%1 m²").arg(QLocale().toString(m2, 'f', 0));
}
} // namespace

PassCountPanel::HistogramAxis PassCountPanel::histogramAxis() const {
    HistogramAxis a;
    const PassCountSummary s = summary();
    const double cellArea = s.coveredCells > 0 ? s.coveredArea / double(s.coveredCells) : 0.0;
    double maxV = 0;
    for (int c = 1; c <= 9; ++c) {
        const double v = c < s.histogram.size() ? double(s.histogram[c]) * cellArea : 0.0;
        a.values.push_back(v);
        maxV = std::max(maxV, v);
    }
    a.top = niceCeil(maxV);
    a.ticks = {areaText(0), areaText(a.top / 2), areaText(a.top)};
    for (double v : a.values)
        a.barLabels.push_back(v > 0 ? areaText(v) : QString());
    a.xTitle = tr("Passes");
    a.yTitle = tr("Area");
    return a;
}

// Bars per pass count with a y axis (area, m² or ha), the area of each bar above it and the pass counts and
// an axis title below (issue 19 §6).
class PassCountPanel::Histogram : public QWidget {
public:
    explicit Histogram(PassCountPanel* panel) : QWidget(panel), m_panel(panel) { setMinimumHeight(150); }

protected:
    void paintEvent(QPaintEvent*) override {
        QPainter p(this);
        p.fillRect(rect(), palette().base());
        const HistogramAxis a = m_panel->histogramAxis();
        const QFontMetrics fm(font());
        const int lh = fm.height();
        int tickW = fm.horizontalAdvance(a.yTitle);
        for (const QString& t : a.ticks)
            tickW = std::max(tickW, fm.horizontalAdvance(t));
        const QRectF plot(tickW + 10, lh + 4, width() - tickW - 16, height() - 3 * lh - 10);
        if (plot.width() < 40 || plot.height() < 20)
            return;
        const QColor text = palette().text().color();
        QColor grid = text;
        grid.setAlpha(60);
        // y axis: title, ticks at 0, half and the top, light grid lines
        p.setPen(text);
        p.drawText(QRectF(0, 0, tickW + 6, lh), Qt::AlignRight | Qt::AlignVCenter, a.yTitle);
        for (int i = 0; i < 3; ++i) {
            const double y = plot.bottom() - plot.height() * i / 2.0;
            p.setPen(grid);
            p.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
            p.setPen(text);
            p.drawText(QRectF(0, y - lh / 2.0, tickW + 6, lh), Qt::AlignRight | Qt::AlignVCenter, a.ticks[i]);
        }
        p.drawLine(plot.bottomLeft(), plot.topLeft());
        const int n = 9;
        const double bw = plot.width() / n;
        const PassPalette pal = m_panel->palette();
        const PassTarget t = m_panel->target();
        for (int c = 1; c <= n; ++c) {
            const double v = a.values[c - 1];
            const double h = a.top > 0 ? v / a.top * plot.height() : 0.0;
            const QRectF bar(plot.left() + (c - 1) * bw + 2, plot.bottom() - h, bw - 4, h);
            p.fillRect(bar, passCountColor(c, pal, t));
            p.setPen(text);
            if (!a.barLabels[c - 1].isEmpty())
                p.drawText(QRectF(bar.left() - 8, bar.top() - lh - 1, bar.width() + 16, lh),
                           Qt::AlignHCenter | Qt::AlignBottom, a.barLabels[c - 1]);
            p.drawText(QRectF(plot.left() + (c - 1) * bw, plot.bottom() + 2, bw, lh), Qt::AlignCenter,
                       c == 9 ? QStringLiteral("9+") : QString::number(c));
        }
        p.drawText(QRectF(plot.left(), plot.bottom() + lh + 4, plot.width(), lh), Qt::AlignCenter, a.xTitle);
    }

private:
    PassCountPanel* m_panel;
};

PassCountPanel::PassCountPanel(QWidget* parent)
    : QWidget(parent), m_palette(new QComboBox(this)), m_min(new QSpinBox(this)), m_max(new QSpinBox(this)),
      m_summaryLabel(new QLabel(this)), m_histogram(new Histogram(this)) {
    m_palette->addItem(tr("Pass count (discrete)"), int(PassPalette::Discrete));
    m_palette->addItem(tr("Summary (below / within / above)"), int(PassPalette::Summary));
    m_min->setRange(1, 50);
    m_max->setRange(1, 50);
    m_min->setValue(3);
    m_max->setValue(5);
    auto* targetRow = new QHBoxLayout;
    targetRow->addWidget(m_min);
    targetRow->addWidget(new QLabel(QStringLiteral("–"), this));
    targetRow->addWidget(m_max);
    auto* form = new QFormLayout;
    form->addRow(tr("Palette"), m_palette);
    form->addRow(tr("Target passes"), targetRow);
    auto* lay = new QVBoxLayout(this);
    lay->addLayout(form);
    lay->addWidget(m_summaryLabel);
    lay->addWidget(m_histogram);
    lay->addStretch(1);
    m_summaryLabel->setTextFormat(Qt::RichText);

    m_throttle.setSingleShot(true);
    m_throttle.setInterval(1000);
    connect(&m_throttle, &QTimer::timeout, this, &PassCountPanel::recompute);
    connect(m_palette, &QComboBox::currentIndexChanged, this, [this] {
        m_histogram->update();
        emit paletteChanged(palette());
    });
    auto targetEdited = [this] {
        if (m_max->value() < m_min->value())
            m_max->setValue(m_min->value());
        recompute();
        emit targetChanged(target());
    };
    connect(m_min, &QSpinBox::valueChanged, this, targetEdited);
    connect(m_max, &QSpinBox::valueChanged, this, targetEdited);
    recompute();
}

void PassCountPanel::setLayer(const PassCountLayer* layer) {
    m_layer = layer;
    recompute();
}

PassPalette PassCountPanel::palette() const {
    return PassPalette(m_palette->currentData().toInt());
}

PassTarget PassCountPanel::target() const {
    return {m_min->value(), m_max->value()};
}

void PassCountPanel::setTarget(PassTarget t) {
    const QSignalBlocker b1(m_min), b2(m_max);
    m_min->setValue(t.min);
    m_max->setValue(std::max(t.min, t.max));
    recompute();
    emit targetChanged(target());
}

void PassCountPanel::setPalette(PassPalette p) {
    m_palette->setCurrentIndex(m_palette->findData(int(p)));
}

void PassCountPanel::layerChanged() {
    if (!m_throttle.isActive())
        m_throttle.start();
}

void PassCountPanel::recompute() {
    m_summary = m_layer ? summarize(*m_layer, target()) : PassCountSummary{};
    if (!m_layer || m_summary.coveredCells == 0) {
        m_summaryLabel->setText(tr("No pass-count data"));
    } else {
        const PassTarget t = target();
        m_summaryLabel->setText(
            tr("<table><tr><td><span style='color:%1'>■</span> below %2</td><td align=right>%3 %</td></tr>"
               "<tr><td><span style='color:%4'>■</span> within %5–%6</td><td align=right>%7 %</td></tr>"
               "<tr><td><span style='color:%8'>■</span> above %6</td><td align=right>%9 %</td></tr>"
               "<tr><td>covered area</td><td align=right>%10 m²</td></tr></table>")
                .arg(passCountSummaryColor(1, {2, 3}).name())
                .arg(t.min)
                .arg(m_summary.belowPct, 0, 'f', 1)
                .arg(passCountSummaryColor(2, {2, 3}).name())
                .arg(t.min)
                .arg(t.max)
                .arg(m_summary.withinPct, 0, 'f', 1)
                .arg(passCountSummaryColor(4, {2, 3}).name())
                .arg(m_summary.abovePct, 0, 'f', 1)
                .arg(m_summary.coveredArea, 0, 'f', 0));
    }
    m_histogram->update();
}

} // namespace ocu
