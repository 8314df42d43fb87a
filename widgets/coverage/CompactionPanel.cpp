#include "widgets/coverage/CompactionPanel.h"

#include "models/coverage/CompactionView.h"
#include "widgets/coverage/CompactionMapOverlay.h"

#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QJsonArray>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>

namespace ocu {

CompactionPanel::CompactionPanel(CompactionView* session, CompactionMapOverlay* overlay, QWidget* parent)
    : QWidget(parent), m_session(session), m_overlay(overlay) {
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(4, 4, 4, 4);
    m_design = new QLabel;
    m_design->setWordWrap(true);
    v->addWidget(m_design);
    auto* liftRow = new QHBoxLayout;
    liftRow->addWidget(new QLabel(tr("Lift:")));
    m_lift = new QComboBox;
    m_lift->addItem(tr("Top view"), -1);
    liftRow->addWidget(m_lift, 1);
    v->addLayout(liftRow);
    QWidget* stationsPage = buildTables();
    m_tabs = new QTabWidget;
    m_tabs->setDocumentMode(true);
    m_tabs->addTab(m_table, tr("Areas"));
    m_tabs->addTab(stationsPage, tr("Stations"));
    v->addWidget(m_tabs, 1);
    auto* buttons = new QHBoxLayout;
    m_draw = new QPushButton(tr("Draw area"));
    m_draw->setToolTip(tr(
        "Draw a compaction area on the 2D map: click to add points; Enter, a double click or a click on the "
        "first point closes; Backspace undoes; Esc cancels"));
    m_remove = new QPushButton(tr("Remove"));
    m_report = new QPushButton(tr("Coverage report…"));
    m_report->setToolTip(
        tr("PDF, Veta-style CSV and GeoTIFF of the pass counts, in the site's projected CRS"));
    buttons->addWidget(m_draw);
    buttons->addWidget(m_remove);
    buttons->addStretch(1);
    buttons->addWidget(m_report);
    v->addLayout(buttons);
    m_status = new QLabel;
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    v->addWidget(m_status);

    connectSignals(session);
    refresh();
}

// The per-area table and the page of the per-station table (returned); both as narrow as their numbers.
QWidget* CompactionPanel::buildTables() {
    m_table = new QTableWidget(0, 6);
    m_table->setHorizontalHeaderLabels(
        {tr("Area"), tr("Covered %"), tr("Target %"), tr("Under %"), tr("Over %"), tr("Incompl.")});
    m_table->horizontalHeaderItem(2)->setToolTip(tr("Covered cells within the target passes, % of the area"));
    m_table->horizontalHeaderItem(5)->setToolTip(
        tr("Cells a given-up ribbon gap may have passed over: their counts are lower bounds"));
    // Per station range along the design's alignment (the report's per-station table).
    auto* stationsPage = new QWidget;
    auto* sv = new QVBoxLayout(stationsPage);
    sv->setContentsMargins(0, 2, 0, 0);
    m_stationsCaption = new QLabel;
    m_stationsCaption->setWordWrap(true);
    m_stationsCaption->setMaximumHeight(m_stationsCaption->fontMetrics().lineSpacing() * 2 + 2);
    sv->addWidget(m_stationsCaption);
    m_stations = new QTableWidget(0, 6);
    m_stations->setHorizontalHeaderLabels(
        {tr("From"), tr("Covered %"), tr("Target %"), tr("Under %"), tr("Over %"), tr("Incompl.")});
    m_stations->horizontalHeaderItem(2)->setToolTip(
        tr("Covered cells within the target passes, % of the range's band"));
    m_stations->horizontalHeaderItem(5)->setToolTip(
        tr("Cells a given-up ribbon gap may have passed over: their counts are lower bounds"));
    // The numbers as narrow as they are, the name takes the rest (the panel is about 300 px wide at 1366 x
    // 768).
    for (QTableWidget* t : {m_table, m_stations}) {
        t->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
        t->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
        t->horizontalHeader()->setMinimumSectionSize(40);
        t->setWordWrap(false);
        t->setTextElideMode(Qt::ElideRight);
        t->verticalHeader()->hide();
        t->setEditTriggers(QAbstractItemView::NoEditTriggers);
        t->setSelectionBehavior(QAbstractItemView::SelectRows);
        t->setSelectionMode(QAbstractItemView::SingleSelection);
    }
    m_stations->setToolTip(tr("Pick a range to outline it on the map; double click to show it"));
    // The station must be readable: when the panel is narrow, the incomplete count gives way instead.
    m_stations->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_stations->horizontalHeader()->setSectionResizeMode(5, QHeaderView::Stretch);
    sv->addWidget(m_stations, 1);
    return stationsPage;
}

void CompactionPanel::connectSignals(CompactionView* session) {
    m_throttle.setSingleShot(true);
    m_throttle.setInterval(2000);
    connect(&m_throttle, &QTimer::timeout, this, &CompactionPanel::refresh);
    connect(session, &CompactionView::changed, this, &CompactionPanel::refresh);
    // The statistics follow the counts (and so the filters: a filter change recounts into a new snapshot).
    connect(session, &CompactionView::countsChanged, this, &CompactionPanel::countsChanged);
    connect(m_lift, &QComboBox::currentIndexChanged, this, &CompactionPanel::refresh);
    connect(m_draw, &QPushButton::clicked, this, [this] {
        if (m_overlay->isDrawing())
            m_overlay->cancelDrawing();
        else
            m_overlay->startDrawing();
    });
    connect(m_overlay, &CompactionMapOverlay::drawingChanged, this,
            [this](bool on) { m_draw->setText(on ? tr("Cancel drawing") : tr("Draw area")); });
    connect(m_overlay, &CompactionMapOverlay::polygonFinished, this, &CompactionPanel::askAreaName);
    connect(m_remove, &QPushButton::clicked, this, [this] {
        const int row = m_table->currentRow();
        if (row < 0)
            return;
        const QString name = m_table->item(row, 0)->data(Qt::UserRole).toString();
        if (m_session->removeArea(name)) {
            const QString e = m_session->saveAreas();
            m_status->setText(e.isEmpty() ? tr("Area \"%1\" removed.").arg(name) : e);
        }
    });
    connect(m_table, &QTableWidget::itemSelectionChanged, this, [this] {
        const int row = m_table->currentRow();
        m_overlay->setHighlightedArea(row >= 0 ? m_table->item(row, 0)->data(Qt::UserRole).toString()
                                               : QString());
    });
    // A double click on an area frames it on the map.
    connect(m_table, &QTableWidget::cellDoubleClicked, this, [this](int row, int) {
        if (auto* it = m_table->item(row, 0))
            m_overlay->zoomToArea(it->data(Qt::UserRole).toString());
    });
    m_table->setToolTip(tr("Double click an area to show it on the map"));
    connect(m_stations, &QTableWidget::itemSelectionChanged, this, &CompactionPanel::stationPicked);
    connect(m_tabs, &QTabWidget::currentChanged, this, &CompactionPanel::stationPicked);
    connect(m_stations, &QTableWidget::cellDoubleClicked, this, [this](int, int) {
        stationPicked();
        m_overlay->zoomToBand();
    });
    connect(m_report, &QPushButton::clicked, this, &CompactionPanel::reportAction);
}

// Columns 1-5 of both tables: covered, at target, under, over (%), incomplete cells; a dash without counts.
static void setFigureCells(QTableWidget* table, int row, const CompactionView::CoverageFigures& f) {
    const QStringList texts =
        f.hasStats
            ? QStringList{QString::number(f.coveragePercent, 'f', 1),
                          QString::number(f.atTargetPercent, 'f', 1), QString::number(f.underPercent, 'f', 1),
                          QString::number(f.overPercent, 'f', 1), QString::number(f.incompleteCells)}
            : QStringList(5, QStringLiteral("–"));
    for (int c = 0; c < 5; ++c) {
        auto* it = new QTableWidgetItem(texts[c]);
        it->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        table->setItem(row, c + 1, it);
    }
}

void CompactionPanel::countsChanged() {
    if (!m_throttle.isActive())
        m_throttle.start();
}

void CompactionPanel::refresh() {
    const CompactionView::DesignInfo design = m_session->designInfo();
    if (design.loaded)
        m_design->setText(tr("Design: %1 — %2 alignment(s), %3 boundary(ies)%4")
                              .arg(QFileInfo(design.path).fileName())
                              .arg(design.alignments)
                              .arg(design.boundaries)
                              .arg(design.warnings.isEmpty() ? QString()
                                                             : tr(" · %1 warning(s): %2")
                                                                   .arg(design.warnings.size())
                                                                   .arg(design.warnings.first())));
    else
        m_design->setText(tr("No design loaded (site configuration \"compaction\": {\"design\": …})."));
    const CompactionView::CoverageTable t = m_session->coverageTable(m_lift->currentData().toInt());
    // Lifts of the data.
    const int liftCount = int(t.lifts.size());
    if (m_lift->count() != liftCount + 1) {
        const QSignalBlocker block(m_lift);
        const int keep = m_lift->currentData().toInt();
        m_lift->clear();
        m_lift->addItem(tr("Top view"), -1);
        for (int i = 0; i < liftCount; ++i)
            m_lift->addItem(tr("Lift %1 (z %2 … %3 m)")
                                .arg(i + 1)
                                .arg(t.lifts[i].bottom, 0, 'f', 2)
                                .arg(t.lifts[i].top, 0, 'f', 2),
                            i);
        const int idx = m_lift->findData(keep);
        m_lift->setCurrentIndex(idx < 0 ? 0 : idx);
    }
    const QString selected = m_table->currentRow() >= 0
                                 ? m_table->item(m_table->currentRow(), 0)->data(Qt::UserRole).toString()
                                 : QString();
    m_table->setRowCount(int(t.areas.size()));
    for (int r = 0; r < t.areas.size(); ++r) {
        const CompactionView::AreaRow& a = t.areas[r];
        auto set = [&](int c, const QString& text) {
            auto* it = new QTableWidgetItem(text);
            if (c > 0)
                it->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_table->setItem(r, c, it);
            return it;
        };
        auto* name = set(0, a.fromDesign ? tr("%1 (design)").arg(a.name) : a.name);
        name->setData(Qt::UserRole, a.name);
        setFigureCells(m_table, r, a);
        if (a.name == selected)
            m_table->selectRow(r);
    }
    // Station ranges.
    if (t.alignment.isEmpty() && t.stations.isEmpty())
        m_stationsCaption->setText(
            design.loaded
                ? tr("No station ranges: the alignment cannot be placed (no EPSG code or worksite frame).")
                : tr("No station ranges without a design alignment."));
    else
        m_stationsCaption->setText(tr("Every %1 m along %2 (%3 m left, %4 m right)")
                                       .arg(t.stationStep)
                                       .arg(t.alignment.isEmpty() ? tr("the alignment") : t.alignment)
                                       .arg(t.bandLeft)
                                       .arg(t.bandRight));
    const int stationRow = m_stations->currentRow();
    m_stations->setRowCount(int(t.stations.size()));
    m_stationBands.clear();
    for (int r = 0; r < t.stations.size(); ++r) {
        const CompactionView::StationRow& st = t.stations[r];
        auto set = [&](int c, const QString& text) {
            auto* it = new QTableWidgetItem(text);
            if (c > 0)
                it->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_stations->setItem(r, c, it);
        };
        // The range's start (narrow at 1366 x 768); the whole range in the tooltip and on the map.
        set(0, CompactionView::stationText(st.from, 0));
        m_stations->item(r, 0)->setToolTip(tr("%1 – %2").arg(CompactionView::stationText(st.from, 0),
                                                             CompactionView::stationText(st.to, 0)));
        setFigureCells(m_stations, r, st);
        m_stationBands.push_back(st.band);
    }
    if (stationRow >= 0 && stationRow < m_stations->rowCount()) {
        const QSignalBlocker block(m_stations);
        m_stations->selectRow(stationRow);
    }
    stationPicked();
    m_remove->setEnabled(!t.areas.isEmpty());
    m_report->setEnabled(m_session->hasWorksite());
}

void CompactionPanel::stationPicked() {
    // Outlined on the map only while the Stations tab is in front and a range is picked.
    const int row = m_stations->currentRow();
    const bool show = m_tabs->currentIndex() == 1 && row >= 0 && row < m_stationBands.size() &&
                      !m_stations->selectedItems().isEmpty();
    m_overlay->setHighlightedBand(show ? m_stationBands[row] : QPolygonF(),
                                  show ? m_stations->item(row, 0)->toolTip() : QString());
}

void CompactionPanel::askAreaName(const QPolygonF& siteEN) {
    QStringList taken;
    for (const auto& a : m_session->mapGeometry().areas)
        taken << a.first;
    // The first free "Area N": after a removal, "Area <count + 1>" may exist, and the new outline would
    // silently replace it.
    int k = m_session->areaCount() + 1;
    while (taken.contains(tr("Area %1").arg(k)))
        ++k;
    QString name = tr("Area %1").arg(k);
    for (;;) {
        bool ok = false;
        name = QInputDialog::getText(this, tr("New compaction area"), tr("Name of the area:"),
                                     QLineEdit::Normal, name, &ok)
                   .trimmed();
        if (!ok) {
            m_status->setText(tr("The drawn area was discarded."));
            return;
        }
        if (!taken.contains(name))
            break;
        // Names are unique: an existing area is only replaced when the operator says so.
        if (QMessageBox::question(
                this, tr("Replace area"),
                tr("An area named \"%1\" exists. Replace it with the new outline?").arg(name),
                QMessageBox::Yes | QMessageBox::No, QMessageBox::No) == QMessageBox::Yes)
            break;
    }
    QString e = m_session->addArea(name, siteEN);
    if (e.isEmpty())
        e = m_session->saveAreas();
    m_status->setText(e.isEmpty() ? tr("Area \"%1\" saved to %2.").arg(name, m_session->areasFile()) : e);
}

QString CompactionPanel::writeReport(const QString& pdfPath) {
    const QFileInfo fi(pdfPath);
    const QString base = fi.path() + QLatin1Char('/') + fi.completeBaseName();
    QJsonObject cmd{{QStringLiteral("pdf"), base + QStringLiteral(".pdf")},
                    {QStringLiteral("csv"), base + QStringLiteral(".csv")},
                    {QStringLiteral("geotiff"), base + QStringLiteral(".tif")}};
    const int lift = m_lift->currentData().toInt();
    if (lift >= 0)
        cmd[QStringLiteral("lift")] = lift + 1;
    const int row = m_table->currentRow();
    if (row >= 0)
        cmd[QStringLiteral("area")] = m_table->item(row, 0)->data(Qt::UserRole).toString();
    const QJsonObject r = m_session->reportCommand(cmd);
    const QJsonObject w = r.value(QStringLiteral("written")).toObject();
    QStringList done, failed;
    for (const QString& k : {QStringLiteral("pdf"), QStringLiteral("csv"), QStringLiteral("geotiff")})
        (w.value(k).toBool() ? done : failed) << k.toUpper();
    QString text = done.isEmpty() ? tr("Coverage report not written.")
                                  : tr("Written: %1 (%2.*).").arg(done.join(QStringLiteral(", ")), base);
    for (const auto& e : r.value(QStringLiteral("errors")).toArray())
        text += QLatin1Char(' ') + tr("Failed: %1").arg(e.toString());
    m_status->setText(text);
    return text;
}

void CompactionPanel::reportAction() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Coverage report"), tr("coverage-report.pdf"),
                                                      tr("PDF (*.pdf)"));
    if (!path.isEmpty())
        writeReport(path);
}

} // namespace ocu
