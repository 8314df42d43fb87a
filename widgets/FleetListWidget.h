#pragma once
// The fleet list: a sortable, filterable table of every machine with status colours
// (green OK, amber warning, red fault/stopped, grey no comms/stale, blue autonomous), a data-age badge,
// a dense/large density switch and a per-machine context menu. Its selection is the shared FleetSelection.
#include <QPointer>
#include <QWidget>

class QTableView;
class QLineEdit;
class QComboBox;
class QToolButton;
class QBoxLayout;

namespace ocu {

class FleetFilterProxy;
class FleetModel;
class FleetSelection;
class CommandGate;
struct MachineState;

class FleetListWidget : public QWidget {
    Q_OBJECT
public:
    enum class Density { Dense, Large };

    FleetListWidget(FleetModel* fleet, FleetSelection* selection, QWidget* parent = nullptr);

    void setCommandGate(CommandGate* stop);
    void setDensity(Density d);
    Density density() const { return m_density; }

    QTableView* tableView() const { return m_view; }
    FleetFilterProxy* proxy() const { return m_proxy; }
    QLineEdit* filterEdit() const { return m_filter; }

    // Opens the per-machine context menu (also used by the map's context menu).
    void showContextMenu(const QString& id, QPoint globalPos);
    static QString describeMachine(const MachineState& m);
    // True while the filter field sits on its own row above the combos (a narrow dock).
    bool filterRowWrapped() const;

signals:
    void centerOnMapRequested(const QString& id);
    void detailsRequested(const QString& id);

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void fitColumnsWithinWidth();
    void syncFromShared();
    void syncToShared();
    void applyFilters();

    QPointer<FleetModel> m_fleet;
    QPointer<FleetSelection> m_selection;
    QPointer<CommandGate> m_gate;
    FleetFilterProxy* m_proxy;
    QTableView* m_view;
    QLineEdit* m_filter;
    QComboBox* m_protocol;
    QComboBox* m_status;
    QToolButton* m_densityButton;
    QBoxLayout* m_filterBar = nullptr; // the filter field beside (wide) or above (narrow) the combos
    Density m_density = Density::Dense;
    bool m_syncing = false;
};

} // namespace ocu
