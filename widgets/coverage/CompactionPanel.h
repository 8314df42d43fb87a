#pragma once
// The compaction areas under the pass-count summary (issue 17): the design in use, one row per area with
// its coverage (covered %, at/under/over target %, incomplete cells) of the current pass counts, refreshed at
// most every 2 s while counts change; "Draw area" (the map's polygon tool), "Remove", and "Coverage report…"
// (PDF + Veta-style CSV + GeoTIFF next to each other, the result said in the panel).
#include <QTimer>
#include <QWidget>

class QLabel;
class QPushButton;
class QTableWidget;
class QComboBox;

namespace ocu {

class CompactionView;
class CompactionMapOverlay;

class CompactionPanel : public QWidget {
    Q_OBJECT
public:
    CompactionPanel(CompactionView* session, CompactionMapOverlay* overlay, QWidget* parent = nullptr);

    QTableWidget* table() const { return m_table; }
    QLabel* statusLabel() const { return m_status; }
    // Writes the report to <base>.pdf/.csv/.tif (the GUI action asks for base with a file dialog).
    QString writeReport(const QString& pdfPath);

public slots:
    void countsChanged(); // throttled refresh
    void refresh();

private:
    void askAreaName(const QPolygonF& siteEN);
    void reportAction();

    CompactionView* m_session;
    CompactionMapOverlay* m_overlay;
    QLabel* m_design;
    QTableWidget* m_table;
    QComboBox* m_lift;
    QPushButton* m_draw;
    QPushButton* m_remove;
    QPushButton* m_report;
    QLabel* m_status;
    QTimer m_throttle;
};

} // namespace ocu
