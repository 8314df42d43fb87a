#pragma once
// The one selection shared by the fleet list, the 2D map and the 3D view.
// It wraps a QItemSelectionModel on the FleetModel (source rows); views over a proxy map through it with
// the helpers below. Everything is keyed by machine id, so it survives sorting and filtering.
#include <QItemSelectionModel>
#include <QObject>
#include <QStringList>

namespace ocu {

class FleetModel;

class FleetSelection : public QObject {
    Q_OBJECT
public:
    explicit FleetSelection(FleetModel* model, QObject* parent = nullptr);

    FleetModel* model() const { return m_model; }
    QItemSelectionModel* selectionModel() const { return m_selection; }

    QString currentId() const { return m_current; }
    QStringList selectedIds() const;
    bool isSelected(const QString& id) const;

    // Select exactly these machines; the first becomes current (or `current` when given and selected).
    void select(const QStringList& ids, const QString& current = {});
    void setCurrent(const QString& id); // also selects it alone
    void toggle(const QString& id);     // ctrl-click
    void clear();

    // Helpers for views over proxies: the id of any index (source or proxy; IdRole passes through
    // proxies), and a machine's index in `model` (the FleetModel or any chain of proxies on it).
    static QString idAt(const QModelIndex& index);
    QModelIndex indexFor(const QString& id, const QAbstractItemModel* model) const;

signals:
    void currentMachineChanged(const QString& id); // empty when none
    void selectionChanged(const QStringList& ids);

private:
    void onModelSelectionChanged();
    void onCurrentChanged(const QModelIndex& current);

    FleetModel* m_model;
    QItemSelectionModel* m_selection;
    QString m_current;
    QStringList m_lastEmitted;
};

} // namespace ocu
