#include "widgets/FleetListWidget.h"

#include "models/CommandGate.h"
#include "models/DisplayText.h"
#include "models/FleetFilterProxy.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "widgets/ColumnFit.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHash>
#include <QHeaderView>
#include <QIcon>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QPainter>
#include <QPixmap>
#include <QResizeEvent>
#include <QStyledItemDelegate>
#include <QTableView>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

namespace ocu {

namespace {
// Paints the status colour as a bar in the name column, the link column as a coloured data-age badge and
// the stop column red when the machine reports a stop.
class FleetDelegate : public QStyledItemDelegate {
public:
    using QStyledItemDelegate::QStyledItemDelegate;

protected:
    // The base class turns a colour decoration into a new pixmap at every paint; the icon engine caches a
    // scaled copy of each under a new key in QPixmapCache, which (Qt 6.4) never evicts pixmaps this small:
    // at 1,000 machines the window grew ~50 MB an hour. One icon per colour and size keeps the keys the same.
    void initStyleOption(QStyleOptionViewItem* opt, const QModelIndex& index) const override {
        QStyledItemDelegate::initStyleOption(opt, index);
        const QVariant deco = index.data(Qt::DecorationRole);
        if (deco.typeId() != QMetaType::QColor)
            return;
        const QColor c = deco.value<QColor>();
        const QString key = QStringLiteral("%1/%2x%3")
                                .arg(c.rgba())
                                .arg(opt->decorationSize.width())
                                .arg(opt->decorationSize.height());
        auto it = m_icons.find(key);
        if (it == m_icons.end()) {
            QPixmap pm(opt->decorationSize);
            pm.fill(c);
            it = m_icons.insert(key, QIcon(pm)); // a handful: one per status colour
        }
        opt->icon = it.value();
    }

public:
    void paint(QPainter* p, const QStyleOptionViewItem& option, const QModelIndex& index) const override {
        const int col = index.column();
        if (col == FleetModel::ColLink) {
            QStyleOptionViewItem opt = option;
            initStyleOption(&opt, index);
            opt.text.clear();
            opt.widget->style()->drawControl(QStyle::CE_ItemViewItem, &opt, p, opt.widget);
            const bool stale = index.data(FleetModel::StaleRole).toBool();
            const qint64 age = index.data(FleetModel::AgeMsRole).toLongLong();
            QColor badge = stale || age < 0 ? statusColor(StatusCategory::Stale)
                           : age > 2000     ? statusColor(StatusCategory::Warning)
                                            : statusColor(StatusCategory::Ok);
            const QString text = index.data().toString();
            const QRect r = option.rect.adjusted(3, 3, -3, -3);
            p->save();
            p->setRenderHint(QPainter::Antialiasing);
            p->setPen(Qt::NoPen);
            p->setBrush(badge);
            p->drawRoundedRect(r, r.height() / 2.0, r.height() / 2.0);
            p->setPen(Qt::black);
            p->drawText(r, Qt::AlignCenter, text);
            p->restore();
            return;
        }
        if (col == FleetModel::ColStop &&
            index.data(FleetModel::RawRole).toInt() == int(StopState::Stopped)) {
            p->fillRect(option.rect, statusColor(StatusCategory::FaultOrStopped));
            QStyleOptionViewItem opt = option;
            initStyleOption(&opt, index);
            opt.palette.setColor(QPalette::Text, Qt::white);
            opt.palette.setColor(QPalette::HighlightedText, Qt::white);
            opt.backgroundBrush = Qt::NoBrush;
            opt.font.setBold(true);
            opt.widget->style()->drawItemText(p, option.rect.adjusted(4, 0, -4, 0),
                                              Qt::AlignVCenter | Qt::AlignLeft, opt.palette, true, opt.text,
                                              QPalette::Text);
            return;
        }
        QStyledItemDelegate::paint(p, option, index);
        if (col == FleetModel::ColName) {
            const QColor c = index.data(FleetModel::StatusColorRole).value<QColor>();
            p->fillRect(QRect(option.rect.left(), option.rect.top(), 5, option.rect.height()), c);
        }
    }

private:
    mutable QHash<QString, QIcon> m_icons; // colour and size -> icon
};
} // namespace

FleetListWidget::FleetListWidget(FleetModel* fleet, FleetSelection* selection, QWidget* parent)
    : QWidget(parent), m_fleet(fleet), m_selection(selection), m_proxy(new FleetFilterProxy(this)),
      m_view(new QTableView(this)), m_filter(new QLineEdit(this)), m_protocol(new QComboBox(this)),
      m_status(new QComboBox(this)), m_densityButton(new QToolButton(this)) {
    // 1,000 machines at 10 Hz: the table re-sorts and repaints at most 4 times a second.
    m_proxy->setChangeIntervalMs(250);
    m_proxy->setSourceModel(fleet);
    m_filter->setPlaceholderText(tr("Filter machines…"));
    m_filter->setClearButtonEnabled(true);
    // The filter row stays narrow enough for a field laptop: the combos shrink to a few
    // characters, the filter keeps room for its placeholder.
    m_filter->setMinimumWidth(fontMetrics().horizontalAdvance(m_filter->placeholderText()) + 36);
    for (QComboBox* c : {m_protocol, m_status}) {
        c->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        c->setMinimumContentsLength(9);
    }
    m_protocol->addItem(tr("All protocols"), -1);
    m_protocol->addItem(QStringLiteral("JAUS"), int(Protocol::Jaus));
    m_protocol->addItem(QStringLiteral("ISO 23725"), int(Protocol::Iso23725));
    m_protocol->addItem(QStringLiteral("OSYRIS"), int(Protocol::Osyris));
    m_status->addItem(tr("All states"), -1);
    m_status->addItem(tr("OK"), int(StatusCategory::Ok));
    m_status->addItem(tr("Warning"), int(StatusCategory::Warning));
    m_status->addItem(tr("Fault / stopped"), int(StatusCategory::FaultOrStopped));
    m_status->addItem(tr("Stale / no comms"), int(StatusCategory::Stale));
    m_status->addItem(tr("Autonomous"), int(StatusCategory::Autonomous));
    m_densityButton->setText(tr("Large rows"));
    m_densityButton->setCheckable(true);
    m_densityButton->setToolTip(tr("Switch between dense rows (workstation) and large rows (field laptop)"));

    // In a narrow dock (the 1366-px laptop's default layout gives the list a quarter of the
    // width) the filter field goes on its own row above the combos instead of forcing the dock ~480 px wide
    // and squeezing the map and the JAUS / teleop column; resizeEvent() switches.
    auto* combos = new QHBoxLayout;
    combos->addWidget(m_protocol);
    combos->addWidget(m_status);
    combos->addWidget(m_densityButton);
    m_filterBar = new QBoxLayout(QBoxLayout::LeftToRight);
    m_filterBar->addWidget(m_filter, 1);
    m_filterBar->addLayout(combos);
    auto* lay = new QVBoxLayout(this);
    lay->setContentsMargins(0, 0, 0, 0);
    lay->addLayout(m_filterBar);
    lay->addWidget(m_view, 1);
    setMinimumWidth(std::max(m_filter->minimumWidth(), combos->minimumSize().width()));

    m_view->setModel(m_proxy);
    useElidingHeader(m_view);
    m_view->setItemDelegate(new FleetDelegate(m_view));
    m_view->setSortingEnabled(true);
    m_view->sortByColumn(FleetModel::ColName, Qt::AscendingOrder);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->setContextMenuPolicy(Qt::CustomContextMenu);
    m_view->setAlternatingRowColors(true);
    m_view->verticalHeader()->hide();
    m_view->horizontalHeader()->setStretchLastSection(true);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_view->setTabKeyNavigation(false); // arrows move in the table, Tab leaves it (docs/keyboard.md)
    setDensity(Density::Dense);
    fitColumnsWithinWidth();

    connect(m_filter, &QLineEdit::textChanged, this, &FleetListWidget::applyFilters);
    connect(m_protocol, &QComboBox::currentIndexChanged, this, &FleetListWidget::applyFilters);
    connect(m_status, &QComboBox::currentIndexChanged, this, &FleetListWidget::applyFilters);
    connect(m_densityButton, &QToolButton::toggled, this,
            [this](bool large) { setDensity(large ? Density::Large : Density::Dense); });
    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &FleetListWidget::syncToShared);
    connect(m_view->selectionModel(), &QItemSelectionModel::currentChanged, this,
            &FleetListWidget::syncToShared);
    connect(selection, &FleetSelection::selectionChanged, this, &FleetListWidget::syncFromShared);
    connect(selection, &FleetSelection::currentMachineChanged, this, &FleetListWidget::syncFromShared);
    connect(m_view, &QTableView::customContextMenuRequested, this, [this](const QPoint& pos) {
        const QModelIndex idx = m_view->indexAt(pos);
        if (idx.isValid())
            showContextMenu(idx.data(FleetModel::IdRole).toString(), m_view->viewport()->mapToGlobal(pos));
    });
    connect(m_view, &QTableView::doubleClicked, this, [this](const QModelIndex& idx) {
        emit centerOnMapRequested(idx.data(FleetModel::IdRole).toString());
    });
}

void FleetListWidget::fitColumnsWithinWidth() {
    // A narrow dock (a laptop's side column) loses the coordinates first, then the columns a machine's row
    // can do without; the name, link, stop, health and last message stay (the header's menu brings any back).
    using M = FleetModel;
    int priority = 0;
    for (const QList<int>& group :
         {QList<int>{M::ColLatitude, M::ColLongitude}, QList<int>{M::ColEast, M::ColNorth},
          QList<int>{M::ColHeading}, QList<int>{M::ColController}, QList<int>{M::ColProtocol},
          QList<int>{M::ColType}, QList<int>{M::ColSpeed}, QList<int>{M::ColMode}}) {
        for (int c : group)
            setColumnDroppable(m_view, c, priority);
        ++priority;
    }
    // Then the health text and the name elide, the name never below a few letters; the link and stop keep
    // their width longest.
    setColumnShrinkTier(m_view, M::ColName, 0,
                        m_view->fontMetrics().horizontalAdvance(QStringLiteral("MMMMMM")));
    for (int c : {M::ColLink, M::ColStop})
        setColumnShrinkTier(m_view, c, 1);
    startColumnsAtHeaderWidth(m_view);
    keepColumnsWithinWidth(m_view);
    keepColumnsFitted(m_view);
    addColumnMenu(m_view);
    showElidedTextInTooltips(m_view);
}

void FleetListWidget::setCommandGate(CommandGate* stop) {
    m_gate = stop;
}

void FleetListWidget::setDensity(Density d) {
    m_density = d;
    QFont f = font();
    const int pt = QFontInfo(font()).pointSize();
    f.setPointSize(d == Density::Large ? int(pt * 1.35 + 0.5) : pt);
    m_view->setFont(f);
    m_view->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_view->verticalHeader()->setDefaultSectionSize(d == Density::Large ? 40 : 20);
    const QSignalBlocker block(m_densityButton);
    m_densityButton->setChecked(d == Density::Large);
}

void FleetListWidget::applyFilters() {
    m_proxy->setText(m_filter->text());
    const int p = m_protocol->currentData().toInt();
    m_proxy->setProtocols(p < 0 ? QSet<Protocol>{} : QSet<Protocol>{Protocol(p)});
    const int s = m_status->currentData().toInt();
    m_proxy->setStatuses(s < 0 ? QSet<StatusCategory>{} : QSet<StatusCategory>{StatusCategory(s)});
}

void FleetListWidget::syncToShared() {
    if (m_syncing || !m_selection)
        return;
    m_syncing = true;
    QStringList ids;
    for (const QModelIndex& idx : m_view->selectionModel()->selectedRows(0))
        ids.push_back(idx.data(FleetModel::IdRole).toString());
    const QModelIndex cur = m_view->selectionModel()->currentIndex();
    m_selection->select(ids, cur.isValid() ? cur.data(FleetModel::IdRole).toString() : QString());
    m_syncing = false;
}

void FleetListWidget::syncFromShared() {
    if (m_syncing || !m_selection || !m_fleet)
        return;
    m_syncing = true;
    QItemSelection sel;
    for (const QString& id : m_selection->selectedIds()) {
        const int row = m_fleet->rowOf(id);
        if (row < 0)
            continue;
        const QModelIndex p = m_proxy->mapFromSource(m_fleet->index(row, 0));
        if (p.isValid())
            sel.select(p, p.siblingAtColumn(FleetModel::ColumnCount - 1));
    }
    auto* sm = m_view->selectionModel();
    sm->select(sel, QItemSelectionModel::ClearAndSelect);
    const int curRow = m_fleet->rowOf(m_selection->currentId());
    const QModelIndex cur = curRow >= 0 ? m_proxy->mapFromSource(m_fleet->index(curRow, 0)) : QModelIndex();
    sm->setCurrentIndex(cur, QItemSelectionModel::NoUpdate);
    if (cur.isValid())
        m_view->scrollTo(cur);
    m_syncing = false;
}

QString FleetListWidget::describeMachine(const MachineState& m) {
    QStringList lines;
    lines << tr("Id: %1").arg(m.id) << tr("Name: %1").arg(m.name) << tr("Type: %1").arg(m.type)
          << tr("Protocol: %1").arg(toText(m.protocol)) << tr("Link: %1").arg(DisplayText::link(m.link));
    if (m.hasPosition)
        lines
            << tr("Position: E %1 m, N %2 m, U %3 m")
                   .arg(m.e, 0, 'f', 2)
                   .arg(m.n, 0, 'f', 2)
                   .arg(m.u, 0, 'f', 2)
            << tr("WGS84: %1, %2").arg(m.lat, 0, 'f', 7).arg(m.lon, 0, 'f', 7)
            << tr("Heading: %1°  Speed: %2 km/h").arg(m.headingDeg, 0, 'f', 1).arg(m.speed * 3.6, 0, 'f', 1);
    lines << tr("Size: %1 × %2 × %3 m").arg(m.length).arg(m.width).arg(m.height)
          << tr("Mode: %1 (%2)").arg(m.modeText, DisplayText::mode(m.mode))
          << tr("Stop (reported): %1 %2").arg(DisplayText::stop(m.stop), m.stopText)
          << tr("Controller: %1 (%2)").arg(m.controller, DisplayText::control(m.control))
          << tr("Health: %1 %2").arg(DisplayText::health(m.health), m.healthText);
    if (!m.workText.isEmpty())
        lines << tr("Work: %1").arg(m.workText);
    return lines.join(QLatin1Char('\n'));
}

void FleetListWidget::showContextMenu(const QString& id, QPoint globalPos) {
    if (id.isEmpty() || !m_fleet)
        return;
    QMenu menu(this);
    menu.addAction(tr("Centre on map"), this, [this, id] { emit centerOnMapRequested(id); });
    QAction* stop = menu.addAction(tr("Stop"), this, [this, id] {
        if (m_gate)
            m_gate->stopMachine(id, QStringLiteral("gui"));
    });
    stop->setEnabled(m_gate != nullptr);
    const QStringList selected = m_selection ? m_selection->selectedIds() : QStringList{};
    if (selected.size() > 1) {
        QAction* stopSel =
            menu.addAction(tr("Stop %1 selected").arg(selected.size()), this, [this, selected] {
                for (const QString& s : selected)
                    if (m_gate)
                        m_gate->stopMachine(s, QStringLiteral("gui"));
            });
        stopSel->setEnabled(m_gate != nullptr);
    }
    menu.addSeparator();
    menu.addAction(tr("Details…"), this, [this, id] {
        emit detailsRequested(id);
        if (const MachineState* m = m_fleet ? m_fleet->machine(id) : nullptr) {
            auto* box = new QMessageBox(QMessageBox::NoIcon, tr("Machine %1").arg(id), describeMachine(*m),
                                        QMessageBox::Close, this);
            box->setAttribute(Qt::WA_DeleteOnClose);
            box->setModal(false);
            box->show();
        }
    });
    menu.exec(globalPos);
}

bool FleetListWidget::filterRowWrapped() const {
    return m_filterBar->direction() == QBoxLayout::TopToBottom;
}

void FleetListWidget::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    // One row needs the filter's minimum beside the combos' and the button's widths.
    const int oneRow = m_filter->minimumWidth() + m_protocol->sizeHint().width() +
                       m_status->sizeHint().width() + m_densityButton->sizeHint().width() +
                       3 * m_filterBar->spacing();
    const auto dir = width() < oneRow ? QBoxLayout::TopToBottom : QBoxLayout::LeftToRight;
    if (m_filterBar->direction() != dir)
        m_filterBar->setDirection(dir);
}

} // namespace ocu
