#include "widgets/PassCountPanel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDateTimeEdit>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
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
// an axis title below.
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
      m_summaryLabel(new QLabel(this)), m_histogram(new Histogram(this)), m_filters(new QGroupBox(this)),
      m_lift(new QComboBox(this)), m_vibration(new QComboBox(this)), m_direction(new QComboBox(this)),
      m_speedMin(new QDoubleSpinBox(this)), m_speedMax(new QDoubleSpinBox(this)),
      m_timeWindow(new QCheckBox(this)), m_timeFrom(new QDateTimeEdit(this)),
      m_timeTo(new QDateTimeEdit(this)), m_liftThickness(new QDoubleSpinBox(this)), m_gaps(new QLabel(this)) {
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
    form->addRow(tr("Lift"), m_lift);

    // Lifts and filters: what the engine counts; the overlay and the statistics follow.
    static_cast<QGroupBox*>(m_filters)->setTitle(tr("Filters"));
    m_vibration->addItem(tr("Vibrating only"), int(PassCountFilter::Vibration::On));
    m_vibration->addItem(tr("Static only"), int(PassCountFilter::Vibration::Off));
    m_vibration->addItem(tr("Vibrating and static"), int(PassCountFilter::Vibration::Any));
    m_direction->addItem(tr("Both directions"), int(PassCountFilter::Direction::Any));
    m_direction->addItem(tr("Forward only"), int(PassCountFilter::Direction::Forward));
    m_direction->addItem(tr("Backward only"), int(PassCountFilter::Direction::Backward));
    for (QDoubleSpinBox* b : {m_speedMin, m_speedMax}) {
        b->setRange(0, 30);
        b->setDecimals(1);
        b->setSingleStep(0.5);
        b->setSuffix(tr(" km/h"));
        b->setSpecialValueText(tr("any"));
    }
    m_timeWindow->setText(tr("Time window"));
    for (QDateTimeEdit* e : {m_timeFrom, m_timeTo}) {
        e->setDisplayFormat(QStringLiteral("yyyy-MM-dd HH:mm"));
        e->setCalendarPopup(true);
        e->setEnabled(false);
    }
    m_timeFrom->setDateTime(QDateTime::currentDateTime().addSecs(-8 * 3600));
    m_timeTo->setDateTime(QDateTime::currentDateTime().addSecs(3600));
    m_liftThickness->setRange(0, 100);
    m_liftThickness->setDecimals(0);
    m_liftThickness->setSuffix(tr(" cm"));
    m_liftThickness->setSpecialValueText(tr("one lift"));
    m_liftThickness->setToolTip(tr("Lifts are elevation bands of this thickness in the machines' heights"));
    auto* speedRow = new QHBoxLayout;
    speedRow->addWidget(m_speedMin);
    speedRow->addWidget(new QLabel(QStringLiteral("–"), this));
    speedRow->addWidget(m_speedMax);
    auto* timeRow = new QHBoxLayout;
    timeRow->addWidget(m_timeFrom);
    timeRow->addWidget(new QLabel(QStringLiteral("–"), this));
    timeRow->addWidget(m_timeTo);
    auto* filterForm = new QFormLayout(m_filters);
    filterForm->addRow(tr("Vibration"), m_vibration);
    filterForm->addRow(tr("Direction"), m_direction);
    filterForm->addRow(tr("Speed"), speedRow);
    filterForm->addRow(m_timeWindow, timeRow);
    filterForm->addRow(tr("Lift thickness"), m_liftThickness);
    m_gaps->setWordWrap(true);
    m_gaps->hide();
    m_filters->hide();
    m_lift->setEnabled(false);
    m_lift->addItem(tr("Top-most lift"), -1);
    m_applyFilter.setSingleShot(true);
    m_applyFilter.setInterval(400);
    connect(&m_applyFilter, &QTimer::timeout, this, &PassCountPanel::applyFilter);
    for (QComboBox* c : {m_vibration, m_direction})
        connect(c, &QComboBox::currentIndexChanged, this, [this] { m_applyFilter.start(); });
    for (QDoubleSpinBox* b : {m_speedMin, m_speedMax, m_liftThickness})
        connect(b, &QDoubleSpinBox::valueChanged, this, [this] { m_applyFilter.start(); });
    connect(m_timeWindow, &QCheckBox::toggled, this, [this](bool on) {
        m_timeFrom->setEnabled(on);
        m_timeTo->setEnabled(on);
        m_applyFilter.start();
    });
    for (QDateTimeEdit* e : {m_timeFrom, m_timeTo})
        connect(e, &QDateTimeEdit::dateTimeChanged, this, [this] { m_applyFilter.start(); });
    connect(m_lift, &QComboBox::activated, this, [this] {
        if (m_controls)
            m_controls->setViewLift(m_lift->currentData().toInt());
        recompute();
    });

    auto* lay = new QVBoxLayout(this);
    lay->addLayout(form);
    lay->addWidget(m_filters);
    lay->addWidget(m_gaps);
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

void PassCountPanel::setControls(PassCountControls* controls) {
    m_controls = controls;
    m_filters->setVisible(controls != nullptr);
    m_lift->setEnabled(controls != nullptr);
    if (controls) {
        const QSignalBlocker block(this);
        setFilter(controls->passCountFilter());
        m_applyFilter.stop(); // what the source has is shown, nothing to apply
    }
    recompute();
}

PassCountFilter PassCountPanel::filter() const {
    PassCountFilter f;
    f.vibration = PassCountFilter::Vibration(m_vibration->currentData().toInt());
    f.direction = PassCountFilter::Direction(m_direction->currentData().toInt());
    f.speedMin = m_speedMin->value() / 3.6;
    f.speedMax = m_speedMax->value() / 3.6;
    if (m_timeWindow->isChecked()) {
        f.timeFromMs = m_timeFrom->dateTime().toMSecsSinceEpoch();
        f.timeToMs = m_timeTo->dateTime().toMSecsSinceEpoch();
    }
    f.liftThickness = m_liftThickness->value() / 100.0;
    if (m_controls)
        f.liftBase = m_controls->passCountFilter().liftBase;
    return f;
}

void PassCountPanel::setFilter(const PassCountFilter& f) {
    m_vibration->setCurrentIndex(m_vibration->findData(int(f.vibration)));
    m_direction->setCurrentIndex(m_direction->findData(int(f.direction)));
    m_speedMin->setValue(f.speedMin * 3.6);
    m_speedMax->setValue(f.speedMax * 3.6);
    m_timeWindow->setChecked(f.timeFromMs > 0 || f.timeToMs > 0);
    if (f.timeFromMs > 0)
        m_timeFrom->setDateTime(QDateTime::fromMSecsSinceEpoch(f.timeFromMs));
    if (f.timeToMs > 0)
        m_timeTo->setDateTime(QDateTime::fromMSecsSinceEpoch(f.timeToMs));
    m_liftThickness->setValue(f.liftThickness * 100.0);
}

void PassCountPanel::applyFilter() {
    if (m_controls)
        m_controls->setPassCountFilter(filter());
}

void PassCountPanel::refreshLifts() {
    const QVector<PassCountLiftInfo> lifts =
        m_controls ? m_controls->passCountLifts() : QVector<PassCountLiftInfo>{};
    const int shown = m_controls ? m_controls->viewLift() : -1;
    QStringList labels{tr("Top-most lift")};
    for (int i = 0; i < lifts.size(); ++i)
        labels << tr("Lift %1 (z %2 – %3 m)")
                      .arg(i + 1)
                      .arg(QLocale().toString(lifts[i].bottom, 'f', 2),
                           QLocale().toString(lifts[i].top, 'f', 2));
    bool same = labels.size() == m_lift->count();
    for (int i = 0; same && i < labels.size(); ++i)
        same = m_lift->itemText(i) == labels[i];
    if (!same) {
        const QSignalBlocker block(m_lift);
        m_lift->clear();
        for (int i = 0; i < labels.size(); ++i)
            m_lift->addItem(labels[i], i - 1);
    }
    m_lift->setCurrentIndex(std::clamp(shown + 1, 0, m_lift->count() - 1));
    const QStringList gaps = m_controls ? m_controls->passCountGaps() : QStringList{};
    m_gaps->setVisible(!gaps.isEmpty());
    m_gaps->setText(gaps.join(QLatin1Char('\n')));
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
    refreshLifts();
    // Incremental for tiled layers (per-tile histograms cached by tile identity), at most once a second
    // while the counts change (layerChanged()).
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
