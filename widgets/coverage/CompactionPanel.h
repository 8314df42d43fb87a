#pragma once
// The compaction areas under the pass-count summary: the design in use, one row per area with
// its coverage (covered %, at/under/over target %, incomplete cells) of the current pass counts, and one row
// per station range along the design's alignment (a tab; a picked range is outlined on the map, a double
// click frames it), refreshed at most every 2 s while counts change; "Draw area" (the map's polygon tool),
// "Remove", and "Coverage report…" (PDF + Veta-style CSV + GeoTIFF next to each other, the result said in the
// panel).
#include <QPolygonF>
#include <QTimer>
#include <QVector>
#include <QWidget>

class QLabel;
class QPushButton;
class QTableWidget;
class QTabWidget;
class QComboBox;

namespace ocu {

class CompactionView;
class CompactionMapOverlay;

class CompactionPanel : public QWidget {
    Q_OBJECT
public:
    CompactionPanel(CompactionView* session, CompactionMapOverlay* overlay, QWidget* parent = nullptr);

    QTableWidget* table() const { return m_table; }
    QTableWidget* stationTable() const { return m_stations; }
    QTabWidget* tabs() const { return m_tabs; }
    QLabel* statusLabel() const { return m_status; }
    // Writes the report to <base>.pdf/.csv/.tif (the GUI action asks for base with a file dialog).
    QString writeReport(const QString& pdfPath);

public slots:
    void countsChanged(); // throttled refresh
    void refresh();

private:
    // Construction.
    QWidget* buildTables();
    void connectSignals(CompactionView* session);
    void askAreaName(const QPolygonF& siteEN);
    void reportAction();
    void stationPicked();

    CompactionView* m_session;
    CompactionMapOverlay* m_overlay;
    QLabel* m_design;
    QTableWidget* m_table;
    QTabWidget* m_tabs;
    QTableWidget* m_stations;
    QLabel* m_stationsCaption;
    QVector<QPolygonF> m_stationBands; // per row of m_stations, site ENU
    QComboBox* m_lift;
    QPushButton* m_draw;
    QPushButton* m_remove;
    QPushButton* m_report;
    QLabel* m_status;
    QTimer m_throttle;
};

} // namespace ocu
