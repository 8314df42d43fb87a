#pragma once
// The alarm list / event log: filter, search, acknowledge, CSV export; alarm management:
// priority and count columns, shelving with an expiry, the alarm rate per 10 min with the
// flood indication, a details pane with the grouped items of the selected alarm.
#include <QPointer>
#include <QWidget>

class QTableView;
class QLineEdit;
class QComboBox;
class QCheckBox;
class QLabel;
class QPushButton;
class QPlainTextEdit;
class QSplitter;
class QBoxLayout;

namespace ocu {

class AlarmFilterProxy;
class AlarmModel;

class EventLogWidget : public QWidget {
    Q_OBJECT
public:
    explicit EventLogWidget(AlarmModel* alarms, QWidget* parent = nullptr);
    // The message column's least share of the table's width (the other columns elide below their widths).
    static constexpr int kMessagePercent = 35;

    QTableView* tableView() const { return m_view; }
    AlarmFilterProxy* proxy() const { return m_proxy; }
    QLineEdit* searchEdit() const { return m_search; }
    QPushButton* ackButton() const { return m_ack; }
    QPushButton* ackAllButton() const { return m_ackAll; }
    QLabel* unackLabel() const { return m_unackLabel; }
    QLabel* rateLabel() const { return m_rateLabel; }
    QPushButton* shelveButton() const { return m_shelve; }
    QPlainTextEdit* detailsPane() const { return m_details; }
    // The details pane is open while an alarm is selected (folded away otherwise).
    bool detailsShown() const;

    // Shelves the alarms of the selected rows for the duration chosen in the panel (default 15 min).
    void shelveSelected();
    void unshelveSelected();

    // Acknowledges the selected rows of the (filtered) view.
    void acknowledgeSelected();
    // Exports the rows currently shown (after filtering) as CSV.
    bool exportShown(const QString& path) const;

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    // Construction.
    void buildLayout();
    void setupTable();
    void connectSignals(AlarmModel* alarms);
    QPointer<AlarmModel> m_alarms;
    AlarmFilterProxy* m_proxy;
    QTableView* m_view;
    QLineEdit* m_search;
    QComboBox* m_severity;
    QCheckBox* m_unackOnly;
    QPushButton* m_ack;
    QPushButton* m_ackAll;
    QPushButton* m_export;
    QLabel* m_unackLabel;
    QCheckBox* m_showShelved;
    QComboBox* m_shelveFor;
    QPushButton* m_shelve;
    QPushButton* m_unshelve;
    QLabel* m_rateLabel;
    QPlainTextEdit* m_details;
    QSplitter* m_split = nullptr;
    QBoxLayout* m_bar2 = nullptr; // shelving buttons beside (wide) or above (narrow) the alarm counts
    void showDetails();
    QStringList selectedKeys() const;
};

} // namespace ocu
