#pragma once
// Pass-count summary (anchors-features.md §4.3-4.4): % of the covered area below / within /
// above the target range, covered area, a histogram per pass count, palette choice and target range.
// The summary is recomputed at most once per second while the layer changes.
#include "models/PassCountControls.h"
#include "models/PassCountLayer.h"

#include <QStringList>
#include <QTimer>
#include <QVector>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QDateTimeEdit;
class QDoubleSpinBox;
class QLabel;
class QSpinBox;

namespace ocu {

class PassCountPanel : public QWidget {
    Q_OBJECT
public:
    explicit PassCountPanel(QWidget* parent = nullptr);

    // Not owned.
    void setLayer(const PassCountLayer* layer);
    const PassCountLayer* layer() const { return m_layer; }
    // Lifts and filters of the layer's source; null hides the controls. Not owned.
    void setControls(PassCountControls* controls);
    // The filter the controls show (applied to the source after a short pause in editing).
    PassCountFilter filter() const;
    void setFilter(const PassCountFilter& f);
    QComboBox* liftPicker() const { return m_lift; }
    PassCountSummary summary() const { return m_summary; }
    PassPalette palette() const;
    PassTarget target() const;
    void setTarget(PassTarget t);
    void setPalette(PassPalette p);

    QLabel* summaryLabel() const { return m_summaryLabel; }

    // What the histogram draws: the area per pass count 1..9+ (m²), the y axis end and its
    // tick texts (0, half, top), the text above each bar (empty for no area) and the axis titles.
    struct HistogramAxis {
        QVector<double> values;
        double top = 1;
        QStringList ticks;
        QStringList barLabels;
        QString xTitle, yTitle;
    };
    HistogramAxis histogramAxis() const;

public slots:
    void layerChanged(); // throttled recompute
    void recompute();    // now

signals:
    void paletteChanged(ocu::PassPalette palette);
    void targetChanged(ocu::PassTarget target);

private:
    class Histogram;
    const PassCountLayer* m_layer = nullptr;
    PassCountSummary m_summary;
    QComboBox* m_palette;
    QSpinBox* m_min;
    QSpinBox* m_max;
    QLabel* m_summaryLabel;
    Histogram* m_histogram;
    QTimer m_throttle;
    // Lifts and filters
    void refreshLifts();
    void applyFilter();
    PassCountControls* m_controls = nullptr;
    QWidget* m_filters;
    QComboBox* m_lift;
    QComboBox* m_vibration;
    QComboBox* m_direction;
    QDoubleSpinBox* m_speedMin;
    QDoubleSpinBox* m_speedMax;
    QCheckBox* m_timeWindow;
    QDateTimeEdit* m_timeFrom;
    QDateTimeEdit* m_timeTo;
    QDoubleSpinBox* m_liftThickness;
    QLabel* m_gaps;
    QTimer m_applyFilter;
};

} // namespace ocu
