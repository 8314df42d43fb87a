#include "widgets/PassCountPanel.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QSpinBox>
#include <QVBoxLayout>

namespace ocu {

class PassCountPanel::Histogram : public QWidget {
public:
    explicit Histogram(PassCountPanel* panel) : QWidget(panel), m_panel(panel) { setMinimumHeight(90); }

protected:
    void paintEvent(QPaintEvent*) override {
        QPainter p(this);
        p.fillRect(rect(), palette().base());
        const PassCountSummary s = m_panel->summary();
        if (s.histogram.size() < 10)
            return;
        qint64 maxV = 1;
        for (int c = 1; c <= 9; ++c)
            maxV = std::max(maxV, s.histogram[c]);
        const int n = 9;
        const double bw = double(width() - 8) / n;
        const int base = height() - 16;
        const PassPalette pal = m_panel->palette();
        const PassTarget t = m_panel->target();
        for (int c = 1; c <= 9; ++c) {
            const double h = double(s.histogram[c]) / double(maxV) * (base - 4);
            const QRectF bar(4 + (c - 1) * bw + 1, base - h, bw - 2, h);
            p.fillRect(bar, passCountColor(c, pal, t));
            p.setPen(palette().text().color());
            p.drawText(QRectF(4 + (c - 1) * bw, base, bw, 16), Qt::AlignCenter,
                       c == 9 ? QStringLiteral("9+") : QString::number(c));
        }
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
