#pragma once
// The alarm list / event log (issue 6 §7): filter, search, acknowledge, CSV export.
#include <QPointer>
#include <QWidget>

class QTableView;
class QLineEdit;
class QComboBox;
class QCheckBox;
class QLabel;
class QPushButton;

namespace ocu {

class AlarmFilterProxy;
class AlarmModel;

class EventLogWidget : public QWidget {
    Q_OBJECT
public:
    explicit EventLogWidget(AlarmModel* alarms, QWidget* parent = nullptr);

    QTableView* tableView() const { return m_view; }
    AlarmFilterProxy* proxy() const { return m_proxy; }
    QLineEdit* searchEdit() const { return m_search; }
    QPushButton* ackButton() const { return m_ack; }
    QPushButton* ackAllButton() const { return m_ackAll; }
    QLabel* unackLabel() const { return m_unackLabel; }

    // Acknowledges the selected rows of the (filtered) view.
    void acknowledgeSelected();
    // Exports the rows currently shown (after filtering) as CSV.
    bool exportShown(const QString& path) const;

private:
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
};

} // namespace ocu
