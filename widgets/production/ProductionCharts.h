#pragma once
// The production charts, built from a ProductionModel and used by the live view and the shift
// report alike: tonnes over the shift against the plan, and the cycle-time breakdown per truck. Qt Charts
// stays behind this header.
#include <QImage>
#include <QSize>

class QGraphicsWidget;
class QWidget;

namespace ocu {

class ProductionModel;

// A live chart widget that rebuilds itself whenever the model changes.
enum class ProductionChart { TonnesVsPlan, CycleBreakdown };
QWidget* createProductionChartView(ProductionChart kind, const ProductionModel* model,
                                   QWidget* parent = nullptr);

// The chart as an image of `size` pixels (white background; for the PDF report).
QImage renderProductionChart(ProductionChart kind, const ProductionModel& model, const QSize& size);

} // namespace ocu
