#include "widgets/production/ProductionCharts.h"

#include "models/ProductionModel.h"

#include <QBarCategoryAxis>
#include <QBarSet>
#include <QChart>
#include <QChartView>
#include <QDateTime>
#include <QDateTimeAxis>
#include <QGraphicsScene>
#include <QHorizontalStackedBarSeries>
#include <QLineSeries>
#include <QPainter>
#include <QTimer>
#include <QValueAxis>

#include <algorithm>

namespace ocu {

namespace {

// Colours of the cycle parts (queue red: time lost waiting).
QColor partColor(CycleBreakdown::Part p) {
    static const QColor c[CycleBreakdown::PartCount] = {QColor(0xd6, 0x45, 0x45), QColor(0xe0, 0xa0, 0x30),
                                                        QColor(0x3b, 0x7d, 0xd8), QColor(0x2e, 0x9e, 0x5b),
                                                        QColor(0x8e, 0x5c, 0xc2), QColor(0x7a, 0xa8, 0xb8),
                                                        QColor(0x9a, 0x9a, 0x9a)};
    return c[p];
}

QString partTitle(CycleBreakdown::Part p) {
    switch (p) {
    case CycleBreakdown::Queue:
        return QObject::tr("Queue");
    case CycleBreakdown::Spot:
        return QObject::tr("Spot");
    case CycleBreakdown::Load:
        return QObject::tr("Load");
    case CycleBreakdown::Haul:
        return QObject::tr("Haul");
    case CycleBreakdown::Dump:
        return QObject::tr("Dump");
    case CycleBreakdown::Return:
        return QObject::tr("Return");
    default:
        return QObject::tr("Other");
    }
}

// Fills `chart` (cleared first) from the model.
void build(ProductionChart kind, QChart* chart, const ProductionModel& m) {
    chart->removeAllSeries();
    for (QAbstractAxis* a : chart->axes())
        chart->removeAxis(a), delete a;
    chart->legend()->setAlignment(Qt::AlignBottom);
    chart->setMargins(QMargins(4, 4, 4, 4));
    if (kind == ProductionChart::TonnesVsPlan) {
        chart->setTitle(QObject::tr("Tonnes over the shift: %1 t in %2 loads")
                            .arg(m.shift().tonnes, 0, 'f', 0)
                            .arg(m.shift().loads));
        const qint64 now = std::clamp(m.nowMs(), m.shiftStart(), m.shiftEnd());
        qint64 last = m.tonnesOverShift().isEmpty() ? m.shiftStart() : qint64(m.tonnesOverShift().last().x());
        const qint64 xEnd = std::max({now, last, m.shiftStart() + 60'000});
        auto* actual = new QLineSeries;
        actual->setName(QObject::tr("Dumped (t)"));
        actual->append(double(m.shiftStart()), 0);
        double y = 0;
        for (const QPointF& p : m.tonnesOverShift()) {
            actual->append(p.x(), y); // a step at each dump
            actual->append(p);
            y = p.y();
        }
        actual->append(double(xEnd), y);
        actual->setPen(QPen(QColor(0x2e, 0x6f, 0xd0), 2.5));
        chart->addSeries(actual);
        double yMax = std::max(10.0, y);
        QLineSeries* plan = nullptr;
        if (m.planTonnes() > 0) {
            plan = new QLineSeries;
            plan->setName(QObject::tr("Plan (t, %1 t/shift)").arg(m.planTonnes(), 0, 'f', 0));
            plan->append(double(m.shiftStart()), 0);
            plan->append(double(xEnd), m.plannedTonnesAt(xEnd));
            QPen pen(QColor(0xc0, 0x50, 0x30), 1.5, Qt::DashLine);
            plan->setPen(pen);
            chart->addSeries(plan);
            yMax = std::max(yMax, m.plannedTonnesAt(xEnd));
        }
        auto* x = new QDateTimeAxis;
        x->setFormat(QStringLiteral("HH:mm"));
        x->setRange(QDateTime::fromMSecsSinceEpoch(m.shiftStart()), QDateTime::fromMSecsSinceEpoch(xEnd));
        x->setTickCount(6);
        auto* yAxis = new QValueAxis;
        yAxis->setRange(0, yMax * 1.05);
        yAxis->applyNiceNumbers();
        yAxis->setLabelFormat(QStringLiteral("%.0f"));
        yAxis->setTitleText(QObject::tr("t"));
        chart->addAxis(x, Qt::AlignBottom);
        chart->addAxis(yAxis, Qt::AlignLeft);
        actual->attachAxis(x);
        actual->attachAxis(yAxis);
        if (plan) {
            plan->attachAxis(x);
            plan->attachAxis(yAxis);
        }
        return;
    }
    // Cycle breakdown: average minutes per cycle and part, one bar per truck plus the shift.
    chart->setTitle(QObject::tr("Cycle time breakdown (average minutes per cycle)"));
    auto* series = new QHorizontalStackedBarSeries;
    QStringList names;
    QVector<ProductionTally> rows;
    for (const auto& t : m.trucks())
        if (t.cycle.cycles > 0)
            rows << t;
    rows << m.shift();
    for (const auto& r : rows)
        names << QStringLiteral("%1 (%2)").arg(r.name).arg(r.cycle.cycles);
    double maxTotal = 1;
    for (int p = 0; p < CycleBreakdown::PartCount; ++p) {
        auto* set = new QBarSet(partTitle(CycleBreakdown::Part(p)));
        set->setColor(partColor(CycleBreakdown::Part(p)));
        set->setBorderColor(partColor(CycleBreakdown::Part(p)).darker(120));
        for (const auto& r : rows)
            *set << r.cycle.average(CycleBreakdown::Part(p)) / 60.0;
        series->append(set);
    }
    for (const auto& r : rows)
        maxTotal = std::max(maxTotal, r.cycle.averageTotal() / 60.0);
    series->setBarWidth(0.7);
    chart->addSeries(series);
    auto* cats = new QBarCategoryAxis;
    cats->append(names);
    auto* minutes = new QValueAxis;
    minutes->setRange(0, maxTotal * 1.05);
    minutes->applyNiceNumbers();
    minutes->setLabelFormat(QStringLiteral("%.0f"));
    minutes->setTitleText(QObject::tr("min"));
    chart->addAxis(cats, Qt::AlignLeft);
    chart->addAxis(minutes, Qt::AlignBottom);
    series->attachAxis(cats);
    series->attachAxis(minutes);
}

} // namespace

QWidget* createProductionChartView(ProductionChart kind, const ProductionModel* model, QWidget* parent) {
    auto* chart = new QChart;
    chart->setAnimationOptions(QChart::NoAnimation);
    auto* view = new QChartView(chart, parent);
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumSize(260, 180);
    build(kind, chart, *model);
    // Rebuilt at most twice a second: reports can come in bursts.
    auto* again = new QTimer(view);
    again->setSingleShot(true);
    again->setInterval(500);
    QObject::connect(again, &QTimer::timeout, view, [chart, kind, model] { build(kind, chart, *model); });
    QObject::connect(model, &ProductionModel::changed, again, [again] {
        if (!again->isActive())
            again->start();
    });
    return view;
}

QImage renderProductionChart(ProductionChart kind, const ProductionModel& model, const QSize& size) {
    QGraphicsScene scene;
    auto* chart = new QChart;
    chart->setAnimationOptions(QChart::NoAnimation);
    chart->setBackgroundRoundness(0);
    scene.addItem(chart);
    build(kind, chart, model);
    chart->resize(size);
    scene.setSceneRect(QRectF(QPointF(0, 0), size));
    QImage img(size, QImage::Format_ARGB32_Premultiplied);
    img.fill(Qt::white);
    QPainter p(&img);
    p.setRenderHint(QPainter::Antialiasing);
    scene.render(&p, QRectF(QPointF(0, 0), size), QRectF(QPointF(0, 0), size));
    return img;
}

} // namespace ocu
