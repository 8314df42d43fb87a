#pragma once
// The production view: the shift's figures against the plan, live charts (tonnes over the shift
// vs the plan, cycle-time breakdown per truck), tables per truck, shovel and dump, and the shift report (PDF
// and CSV) on a button.
#include <QImage>
#include <QWidget>

#include <functional>

class QDoubleSpinBox;
class QLabel;
class QTableWidget;
class QTabWidget;

namespace ocu {

class ProductionModel;
struct ProductionTally;

class ProductionView : public QWidget {
    Q_OBJECT
public:
    explicit ProductionView(ProductionModel* model, QWidget* parent = nullptr);

    // The map snapshot for the report (the site map as it is now); none: the report says so.
    void setMapSnapshotSource(std::function<QImage(const QSize&)> source) { m_snapshot = std::move(source); }
    void setSiteName(const QString& name) { m_siteName = name; }
    // Writes the PDF and the CSV (same base name) without asking; returns an error text or empty.
    QString writeReport(const QString& pdfFile, const QString& csvFile);

    QTableWidget* table(int section) const; // 0 trucks, 1 shovels, 2 dumps
    QLabel* summaryLabel() const { return m_summary; }

public slots:
    void refresh();

signals:
    void reportWritten(const QString& pdfFile, const QString& csvFile);

private:
    void askAndWriteReport();
    void fill(QTableWidget* t, const QVector<ProductionTally>& rows);

    ProductionModel* m_model;
    QLabel* m_summary;
    QDoubleSpinBox* m_plan;
    QTabWidget* m_tabs;
    QTableWidget* m_tables[3];
    std::function<QImage(const QSize&)> m_snapshot;
    QString m_siteName;
    bool m_refreshQueued = false;
};

} // namespace ocu
