#pragma once
// Pass-count summary (issue 6 §5; anchors-features.md §4.3-4.4): % of the covered area below / within /
// above the target range, covered area, a histogram per pass count, palette choice and target range.
// The summary is recomputed at most once per second while the layer changes.
#include "models/PassCountLayer.h"

#include <QStringList>
#include <QTimer>
#include <QVector>
#include <QWidget>

class QComboBox;
class QLabel;
class QSpinBox;

namespace ocu {

class PassCountPanel : public QWidget {
    Q_OBJECT
public:
    explicit PassCountPanel(QWidget* parent = nullptr);

    // Not owned.
    void setLayer(const PassCountLayer* layer);
    PassCountSummary summary() const { return m_summary; }
    PassPalette palette() const;
    PassTarget target() const;
    void setTarget(PassTarget t);
    void setPalette(PassPalette p);

    QLabel* summaryLabel() const { return m_summaryLabel; }

    // What the histogram draws (issue 19 §6): the area per pass count 1..9+ (m²), the y axis end and its
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
};

} // namespace ocu
