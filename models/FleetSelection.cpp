#include "models/FleetSelection.h"

#include "models/FleetModel.h"

#include <QAbstractProxyModel>

namespace ocu {

FleetSelection::FleetSelection(FleetModel* model, QObject* parent)
    : QObject(parent), m_model(model), m_selection(new QItemSelectionModel(nullptr, this)) {
    // Connected before the selection model attaches to the model, so this runs first: when the current
    // machine disappears there is no current machine (a followed machine must not silently become another).
    connect(model, &QAbstractItemModel::rowsAboutToBeRemoved, this,
            [this](const QModelIndex&, int first, int last) {
                const QModelIndex cur = m_selection->currentIndex();
                if (cur.isValid() && cur.row() >= first && cur.row() <= last)
                    m_selection->setCurrentIndex(QModelIndex(), QItemSelectionModel::NoUpdate);
            });
    m_selection->setModel(model);
    connect(m_selection, &QItemSelectionModel::selectionChanged, this,
            &FleetSelection::onModelSelectionChanged);
    connect(m_selection, &QItemSelectionModel::currentChanged, this,
            [this](const QModelIndex& cur, const QModelIndex&) { onCurrentChanged(cur); });
    // Rows removed under the selection: QItemSelectionModel updates itself; keep the current id honest.
    connect(model, &FleetModel::machineRemoved, this, [this](const QString& id) {
        if (id == m_current) {
            m_current.clear();
            emit currentMachineChanged(QString());
        }
        onModelSelectionChanged();
    });
}

QStringList FleetSelection::selectedIds() const {
    QStringList out;
    for (const QModelIndex& idx : m_selection->selectedRows(0))
        out.push_back(idx.data(FleetModel::IdRole).toString());
    return out;
}

bool FleetSelection::isSelected(const QString& id) const {
    const int row = m_model->rowOf(id);
    return row >= 0 && m_selection->isRowSelected(row, {});
}

void FleetSelection::select(const QStringList& ids, const QString& current) {
    QItemSelection sel;
    for (const QString& id : ids) {
        const int row = m_model->rowOf(id);
        if (row >= 0)
            sel.select(m_model->index(row, 0), m_model->index(row, FleetModel::ColumnCount - 1));
    }
    const QString cur =
        !current.isEmpty() && ids.contains(current) ? current : (ids.isEmpty() ? QString() : ids.first());
    const int curRow = m_model->rowOf(cur);
    m_selection->select(sel, QItemSelectionModel::ClearAndSelect);
    m_selection->setCurrentIndex(curRow >= 0 ? m_model->index(curRow, 0) : QModelIndex(),
                                 QItemSelectionModel::NoUpdate);
    if (curRow < 0 && !m_current.isEmpty()) {
        m_current.clear();
        emit currentMachineChanged(QString());
    }
}

void FleetSelection::setCurrent(const QString& id) {
    select(id.isEmpty() ? QStringList{} : QStringList{id}, id);
}

void FleetSelection::toggle(const QString& id) {
    QStringList ids = selectedIds();
    if (ids.contains(id))
        ids.removeAll(id);
    else
        ids.push_back(id);
    select(ids, ids.contains(id) ? id : QString());
}

void FleetSelection::clear() {
    select({});
}

QString FleetSelection::idAt(const QModelIndex& index) {
    return index.data(FleetModel::IdRole).toString();
}

QModelIndex FleetSelection::indexFor(const QString& id, const QAbstractItemModel* model) const {
    const int row = m_model->rowOf(id);
    if (row < 0)
        return {};
    QModelIndex idx = m_model->index(row, 0);
    if (model == m_model)
        return idx;
    // Walk the proxy chain from `model` down to the fleet model, then map back up.
    QVector<const QAbstractProxyModel*> chain;
    for (auto* p = qobject_cast<const QAbstractProxyModel*>(model); p;
         p = qobject_cast<const QAbstractProxyModel*>(p->sourceModel())) {
        chain.push_front(p);
        if (p->sourceModel() == m_model)
            break;
    }
    if (chain.isEmpty() || chain.front()->sourceModel() != m_model)
        return {};
    for (const QAbstractProxyModel* p : chain)
        idx = p->mapFromSource(idx);
    return idx;
}

void FleetSelection::onModelSelectionChanged() {
    const QStringList ids = selectedIds();
    if (ids != m_lastEmitted) {
        m_lastEmitted = ids;
        emit selectionChanged(ids);
    }
}

void FleetSelection::onCurrentChanged(const QModelIndex& current) {
    const QString id = current.isValid() ? current.data(FleetModel::IdRole).toString() : QString();
    if (id != m_current) {
        m_current = id;
        emit currentMachineChanged(id);
    }
}

} // namespace ocu
