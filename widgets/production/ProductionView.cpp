#include "widgets/production/ProductionView.h"

#include "models/ProductionModel.h"
#include "widgets/ColumnFit.h"
#include "widgets/production/ProductionCharts.h"
#include "widgets/production/ShiftReport.h"

#include <QDateTime>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace ocu {

namespace {

QString mmss(double seconds) {
    return QStringLiteral("%1:%2")
        .arg(qint64(seconds) / 60)
        .arg(qint64(seconds) % 60, 2, 10, QLatin1Char('0'));
}

} // namespace

ProductionView::ProductionView(ProductionModel* model, QWidget* parent) : QWidget(parent), m_model(model) {
    setObjectName(QStringLiteral("production-view"));
    auto* top = new QHBoxLayout;
    m_summary = new QLabel(this);
    m_summary->setObjectName(QStringLiteral("production-summary"));
    m_summary->setTextFormat(Qt::RichText);
    // Wraps in a narrow dock (German at 1366x768) instead of widening the panel past it.
    m_summary->setWordWrap(true);
    m_summary->setMinimumWidth(160);
    top->addWidget(m_summary, 1);
    top->addWidget(new QLabel(tr("Plan (t/shift):"), this));
    m_plan = new QDoubleSpinBox(this);
    m_plan->setObjectName(QStringLiteral("production-plan"));
    m_plan->setRange(0, 10'000'000);
    m_plan->setDecimals(0);
    m_plan->setSingleStep(1000);
    m_plan->setToolTip(tr("Tonnes planned for the shift (0: no plan)"));
    m_plan->setValue(
        QSettings().value(QStringLiteral("production/planTonnes"), model->planTonnes()).toDouble());
    model->setPlanTonnes(m_plan->value());
    connect(m_plan, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        QSettings().setValue(QStringLiteral("production/planTonnes"), v);
        m_model->setPlanTonnes(v);
    });
    top->addWidget(m_plan);
    auto* report = new QPushButton(tr("Shift &report…"), this);
    report->setObjectName(QStringLiteral("production-report"));
    report->setToolTip(tr("Write the shift report as PDF and CSV"));
    connect(report, &QPushButton::clicked, this, &ProductionView::askAndWriteReport);
    top->addWidget(report);
    auto* newShift = new QPushButton(tr("New shift"), this);
    newShift->setToolTip(tr("Start counting a new shift now (the current figures are discarded)"));
    connect(newShift, &QPushButton::clicked, this, [this] {
        if (QMessageBox::question(
                this, tr("New shift"),
                tr("Start a new shift now? The current shift's figures are discarded; write "
                   "the shift report first.")) == QMessageBox::Yes)
            m_model->clear();
    });
    top->addWidget(newShift);

    auto* charts = new QSplitter(Qt::Horizontal, this);
    charts->addWidget(createProductionChartView(ProductionChart::TonnesVsPlan, model, charts));
    charts->addWidget(createProductionChartView(ProductionChart::CycleBreakdown, model, charts));

    m_tabs = new QTabWidget(this);
    const QStringList names{tr("Trucks"), tr("Shovels"), tr("Dumps")};
    for (int i = 0; i < 3; ++i) {
        auto* t = new QTableWidget(0, 10, this);
        t->setObjectName(QStringLiteral("production-table-%1").arg(i));
        t->setHorizontalHeaderLabels({names[i] == tr("Trucks") ? tr("Truck") : tr("Area"), tr("Loads"),
                                      tr("Tonnes"), tr("Cycles"), tr("Queue"), tr("Spot"), tr("Load"),
                                      tr("Haul"), tr("Dump"), tr("Return")});
        t->setEditTriggers(QAbstractItemView::NoEditTriggers);
        t->setSelectionBehavior(QAbstractItemView::SelectRows);
        t->verticalHeader()->setVisible(false);
        t->setToolTip(tr("Cycle parts: average minutes:seconds per cycle"));
        // The table fits its tab: the name takes the width left (elided, whole in its tooltip), the
        // figures keep theirs, their titles elided first.
        useElidingHeader(t);
        t->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
        t->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
        startColumnsAtHeaderWidth(t);
        keepColumnsWithinWidth(t);
        keepColumnsFitted(t);
        showElidedTextInTooltips(t);
        m_tables[i] = t;
        m_tabs->addTab(t, names[i]);
    }
    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(charts);
    split->addWidget(m_tabs);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);

    auto* lay = new QVBoxLayout(this);
    lay->setContentsMargins(4, 4, 4, 4);
    lay->addLayout(top);
    lay->addWidget(split, 1);
    connect(model, &ProductionModel::changed, this, [this] {
        if (m_refreshQueued)
            return;
        m_refreshQueued = true;
        QTimer::singleShot(500, this, &ProductionView::refresh);
    });
    refresh();
}

QTableWidget* ProductionView::table(int section) const {
    return m_tables[std::clamp(section, 0, 2)];
}

void ProductionView::fill(QTableWidget* t, const QVector<ProductionTally>& rows) {
    t->setRowCount(rows.size());
    for (int r = 0; r < rows.size(); ++r) {
        const auto& x = rows[r];
        QStringList cells{x.name, QString::number(x.loads), QString::number(x.tonnes, 'f', 0),
                          QString::number(x.cycle.cycles)};
        for (auto part : {CycleBreakdown::Queue, CycleBreakdown::Spot, CycleBreakdown::Load,
                          CycleBreakdown::Haul, CycleBreakdown::Dump, CycleBreakdown::Return})
            cells << (x.cycle.cycles ? mmss(x.cycle.average(part)) : QStringLiteral("–"));
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = t->item(r, c);
            if (!item) {
                item = new QTableWidgetItem;
                if (c > 0)
                    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
                t->setItem(r, c, item);
            }
            item->setText(cells[c]);
        }
    }
}

void ProductionView::refresh() {
    m_refreshQueued = false;
    const auto& s = m_model->shift();
    const qint64 now = std::clamp(m_model->nowMs(), m_model->shiftStart(), m_model->shiftEnd());
    const double due = m_model->plannedTonnesAt(now);
    QString plan = m_model->planTonnes() > 0 ? tr("%1 % of the %2 t due by now")
                                                   .arg(due > 0 ? 100 * s.tonnes / due : 0, 0, 'f', 0)
                                                   .arg(due, 0, 'f', 0)
                                             : tr("no plan set");
    m_summary->setText(tr("<b>%1 t</b> in <b>%2 loads</b> · %3 cycles, average %4 · %5")
                           .arg(s.tonnes, 0, 'f', 0)
                           .arg(s.loads)
                           .arg(s.cycle.cycles)
                           .arg(s.cycle.cycles ? mmss(s.cycle.averageTotal()) : QStringLiteral("–"))
                           .arg(plan));
    fill(m_tables[0], m_model->trucks());
    fill(m_tables[1], m_model->shovels());
    fill(m_tables[2], m_model->dumps());
}

QString ProductionView::writeReport(const QString& pdfFile, const QString& csvFile) {
    const QImage map = m_snapshot ? m_snapshot(QSize(1100, 500)) : QImage();
    if (QString e = writeShiftPdf(*m_model, map, m_siteName, pdfFile); !e.isEmpty())
        return e;
    if (QString e = writeShiftCsv(*m_model, csvFile); !e.isEmpty())
        return e;
    emit reportWritten(pdfFile, csvFile);
    return {};
}

void ProductionView::askAndWriteReport() {
    const QString base = QStringLiteral("shift-report-%1.pdf")
                             .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmm")));
    const QString pdf = QFileDialog::getSaveFileName(this, tr("Shift report"), base, tr("PDF (*.pdf)"));
    if (pdf.isEmpty())
        return;
    QString csv = pdf;
    if (csv.endsWith(QLatin1String(".pdf"), Qt::CaseInsensitive))
        csv.chop(4);
    csv += QStringLiteral(".csv");
    const QString e = writeReport(pdf, csv);
    if (e.isEmpty())
        QMessageBox::information(this, tr("Shift report"), tr("Written:\n%1\n%2").arg(pdf, csv));
    else
        QMessageBox::warning(this, tr("Shift report"), tr("The shift report was not written: %1").arg(e));
}

} // namespace ocu
