#include "widgets/dispatch/DispatchPanel.h"

#include "models/AutoDispatcher.h"
#include "models/CommandGate.h"
#include "models/FleetSelection.h"
#include "widgets/ColumnFit.h"
#include "widgets/CommandPermissionHint.h"
#include "widgets/OnScreenWatcher.h"
#include "widgets/SiteMapView.h"
#include "widgets/dispatch/CachedTextDelegate.h"
#include "widgets/dispatch/RouteOverlay2D.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeySequence>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QShortcut>
#include <QSplitter>
#include <QStyle>
#include <QTableView>
#include <QTime>
#include <QVBoxLayout>

namespace ocu {

namespace {
const QStringList kTasks{QStringLiteral("Load"), QStringLiteral("Offload"), QStringLiteral("Fuel"),
                         QStringLiteral("Park"), QStringLiteral("Wait")};
// A status line shows only while it has something to say (the panel is short in the default layout).
void setLine(QLabel* label, const QString& text) {
    label->setText(text);
    label->setVisible(!text.isEmpty());
}
bool hasTask(const DispatchTruck& t) {
    return t.assignmentStatus == QLatin1String("Pending") || t.assignmentStatus == QLatin1String("Active");
}
QString areaText(const DispatchArea& a) {
    const QString name = a.name.isEmpty() ? DispatchPanel::tr("way %1").arg(a.wayId) : a.name;
    return a.defaultTask.isEmpty() ? name : QStringLiteral("%1 — %2").arg(name, a.defaultTask);
}
} // namespace

QString DispatchPanel::shortcutHelp() {
    return tr("Dispatch panel keys:\n"
              "Up/Down: choose a truck in the table (Alt+K: go to the table)\n"
              "F6: next truck that needs an assignment\n"
              "Alt+T: task, Alt+D: destination (type to search), Alt+M: pick the destination on the 2D map "
              "(click an area; Esc cancels)\n"
              "Ctrl+Enter or Alt+A: assign (re-assigning a truck that has a task asks first)\n"
              "Alt+R: reset the truck's assignment (asks first)\n"
              "Alt+Q: go to the queues per shovel and dump\n"
              "Alt+U: auto dispatch on/off (switching on asks first)");
}

DispatchPanel::DispatchPanel(DispatchSource* source, CommandGate* gate, FleetSelection* selection,
                             QWidget* parent)
    : QWidget(parent), m_source(source), m_gate(gate), m_selection(selection) {
    setObjectName(QStringLiteral("dispatch-panel"));
    setToolTip(shortcutHelp());
    m_model = new DispatchModel(this);
    m_model->setSource(source);
    if (selection)
        m_model->setFleet(selection->model());
    m_queues = new DispatchQueueModel(m_model, this);

    auto* top = new QVBoxLayout(this);
    // Compact: on a 1366x768 field laptop the panel shares the bottom row; every pixel row is a truck row.
    top->setContentsMargins(2, 2, 2, 2);
    top->setSpacing(2);

    auto* split = m_split = new QSplitter(Qt::Horizontal, this);
    QWidget* left = buildTruckList(split);
    QWidget* queues = buildQueueList(split);
    split->addWidget(left);
    split->addWidget(queues);
    split->setStretchFactor(0, 4);
    split->setStretchFactor(1, 1);
    split->setChildrenCollapsible(true); // the queues can be dragged away on a narrow screen
    top->addWidget(split, 1);
    for (QTableView* t : {m_table, m_queueTable})
        m_sideBySideWidth +=
            t->horizontalHeader()->length() + t->style()->pixelMetric(QStyle::PM_ScrollBarExtent) + 8;
    keepColumnsWithinWidth(m_table);
    // The truck's name whole, the others elided as far as need be.
    setColumnShrinkTier(m_table, DispatchModel::ColTruck, 1, m_table->columnWidth(DispatchModel::ColTruck));
    keepColumnsWithinWidth(m_queueTable);
    keepColumnsFitted(m_queueTable); // a few rows: their texts ("Shovel (load)") set the widths wanted

    buildControls(top);
    connectControls(source, selection);
    rebuildDestinations();
    onTrucksUpdated({});
}

void DispatchPanel::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    const Qt::Orientation o = width() >= m_sideBySideWidth ? Qt::Horizontal : Qt::Vertical;
    if (m_split->orientation() != o) {
        m_split->setOrientation(o);
        // Below the trucks the queues get a third of the height (the areas of a pit: a few rows).
        m_split->setStretchFactor(0, o == Qt::Horizontal ? 4 : 2);
        m_split->setStretchFactor(1, 1);
        const int total = o == Qt::Horizontal ? m_split->width() : m_split->height();
        m_split->setSizes(o == Qt::Horizontal ? QList<int>{total * 4 / 5, total / 5}
                                              : QList<int>{total * 2 / 3, total / 3});
    }
}

// The trucks: a header row (needs-assignment count, next, auto dispatch) over the truck table.
QWidget* DispatchPanel::buildTruckList(QSplitter* split) {
    auto* left = new QWidget(split);
    auto* leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    leftLayout->setSpacing(2);
    auto* head = new QHBoxLayout;
    auto* trucksLabel = new QLabel(tr("Truc&ks"), this);
    trucksLabel->setStyleSheet(QStringLiteral("font-weight:bold"));
    head->addWidget(trucksLabel);
    m_needs = new QLabel(this);
    m_needs->setObjectName(QStringLiteral("label-needs-assignment"));
    head->addWidget(m_needs);
    head->addStretch(1);
    auto* next = new QPushButton(tr("Next needing work (F6)"), this);
    next->setFlat(true);
    next->setObjectName(QStringLiteral("button-next-needing"));
    next->setToolTip(tr("Select the next truck that asks for work or was handed back to the FMS."));
    connect(next, &QPushButton::clicked, this, &DispatchPanel::selectNextNeedingAssignment);
    head->addWidget(next);
    // The automatic dispatcher's switch (shown when there is one, see setAutoDispatcher).
    m_auto = new QPushButton(tr("A&uto dispatch"), this);
    m_auto->setObjectName(QStringLiteral("button-auto-dispatch"));
    m_auto->setCheckable(true);
    m_auto->setToolTip(
        tr("Assign every idle FMS truck automatically: empty to the shovel with the shortest "
           "queue, loaded to the dump with the shortest queue (Alt+U; switching on asks first)."));
    m_auto->hide();
    head->addWidget(m_auto);
    leftLayout->addLayout(head);
    m_autoLabel = new QLabel(this);
    m_autoLabel->setObjectName(QStringLiteral("label-auto-dispatch"));
    m_autoLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_autoLabel->hide();
    leftLayout->addWidget(m_autoLabel);
    m_table = new QTableView(left);
    useElidingHeader(m_table);
    leftLayout->addWidget(m_table, 1);
    m_table->setObjectName(QStringLiteral("dispatch-table"));
    m_table->setModel(m_model);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setAlternatingRowColors(true);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed); // uniform rows, no size hints
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 4);
    m_table->verticalHeader()->setMinimumSectionSize(m_table->fontMetrics().height() + 4);
    m_table->setItemDelegate(new CachedTextDelegate(m_table)); // 1,000 trucks: see bench_dispatch_panel
    m_table->horizontalHeader()->setStretchLastSection(false);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    m_table->setWordWrap(false);
    m_table->setTabKeyNavigation(false); // Tab leaves the table for the controls
    trucksLabel->setBuddy(m_table);
    {
        const QFontMetrics fm = m_table->fontMetrics();
        const int w[] = {fm.horizontalAdvance(QStringLiteral("HT-0000")),
                         fm.horizontalAdvance(QStringLiteral("Custodian")),
                         fm.horizontalAdvance(QStringLiteral("Autonomous")),
                         fm.horizontalAdvance(QStringLiteral("NEEDS ASSIGNMENT")),
                         fm.horizontalAdvance(QStringLiteral("Offload")),
                         fm.horizontalAdvance(QStringLiteral("Crusher 1 (way)")),
                         fm.horizontalAdvance(QStringLiteral("~00:00")),
                         fm.horizontalAdvance(QStringLiteral("Production")),
                         fm.horizontalAdvance(QStringLiteral("Payload")),
                         fm.horizontalAdvance(QStringLiteral("In state"))};
        for (int c = 0; c < DispatchModel::ColumnCount; ++c)
            m_table->setColumnWidth(c, w[c] + 16);
    }

    return left;
}

// The queues per shovel and dump, beside the trucks.
QWidget* DispatchPanel::buildQueueList(QSplitter* split) {
    auto* queues = new QWidget(split);
    auto* queueLayout = new QVBoxLayout(queues);
    queueLayout->setContentsMargins(0, 0, 0, 0);
    queueLayout->setSpacing(2);
    // Short: the panel must fit half the bottom row of a 1366x768 screen (the tooltip says the rest).
    auto* queueLabel = new QLabel(tr("&Queues"), queues);
    queueLabel->setToolTip(tr("Queues per shovel and dump: trucks at the area and trucks coming to it"));
    queueLabel->setStyleSheet(QStringLiteral("font-weight:bold"));
    queueLayout->addWidget(queueLabel);
    m_queueTable = new QTableView(queues);
    useElidingHeader(m_queueTable);
    m_queueTable->setObjectName(QStringLiteral("dispatch-queues"));
    m_queueTable->setModel(m_queues);
    m_queueTable->verticalHeader()->hide();
    m_queueTable->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_queueTable->verticalHeader()->setDefaultSectionSize(m_queueTable->fontMetrics().height() + 4);
    m_queueTable->verticalHeader()->setMinimumSectionSize(m_queueTable->fontMetrics().height() + 4);
    m_queueTable->setItemDelegate(new CachedTextDelegate(m_queueTable));
    m_queueTable->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_queueTable->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_queueTable->setWordWrap(false);
    m_queueTable->horizontalHeader()->setStretchLastSection(true);
    {
        const QFontMetrics fm = m_queueTable->fontMetrics();
        m_queueTable->setColumnWidth(DispatchQueueModel::ColArea,
                                     fm.horizontalAdvance(QStringLiteral("Pit 1 shovel 1")) + 14);
        m_queueTable->setColumnWidth(DispatchQueueModel::ColKind,
                                     fm.horizontalAdvance(QStringLiteral("Shovel")) + 14);
        m_queueTable->setColumnWidth(DispatchQueueModel::ColEnRoute,
                                     fm.horizontalAdvance(QStringLiteral("Coming")) + 14);
        m_queueTable->setColumnWidth(DispatchQueueModel::ColAtArea,
                                     fm.horizontalAdvance(QStringLiteral("At area")) + 14);
    }
    queueLabel->setBuddy(m_queueTable);
    queueLayout->addWidget(m_queueTable, 1);
    return queues;
}

// Task, destination, pick on map, assign and reset, then the refusal and result lines.
void DispatchPanel::buildControls(QVBoxLayout* top) {
    auto* controls = new QHBoxLayout;
    auto* taskLabel = new QLabel(tr("&Task"), this);
    m_task = new QComboBox(this);
    m_task->setObjectName(QStringLiteral("combo-task"));
    m_task->addItems(kTasks);
    taskLabel->setBuddy(m_task);
    auto* destLabel = new QLabel(tr("&Destination"), this);
    m_destination = new QComboBox(this);
    m_destination->setObjectName(QStringLiteral("combo-destination"));
    m_destination->setMinimumContentsLength(16);
    // It stretches; its own minimum (the longest area name) would push Reset off half the bottom row of a
    // 1366x768 screen.
    m_destination->setMinimumWidth(
        m_destination->fontMetrics().horizontalAdvance(QStringLiteral("Pit 1 shovel 1")) + 40);
    m_destination->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    destLabel->setBuddy(m_destination);
    m_pick = new QPushButton(tr("Pick on &map"), this);
    m_pick->setObjectName(QStringLiteral("button-pick-on-map"));
    m_pick->setCheckable(true);
    m_pick->setToolTip(
        tr("Then click a load, dump, crusher, park or fuel area on the 2D map (Esc cancels)."));
    m_assign = new QPushButton(tr("&Assign"), this);
    m_assign->setObjectName(QStringLiteral("button-assign"));
    m_reset = new QPushButton(tr("&Reset"), this);
    m_reset->setObjectName(QStringLiteral("button-reset-assignment"));
    m_reset->setToolTip(tr("Reset the truck's assignment (HaulTruckAssignmentResetV1); asks first."));
    controls->addWidget(taskLabel);
    controls->addWidget(m_task);
    controls->addWidget(destLabel);
    controls->addWidget(m_destination, 1);
    controls->addWidget(m_pick);
    controls->addWidget(m_assign);
    controls->addWidget(m_reset);
    top->addLayout(controls);
    m_refusal = new QLabel(this);
    m_refusal->setObjectName(QStringLiteral("label-assign-refusal"));
    m_refusal->setWordWrap(true);
    m_refusal->setStyleSheet(QStringLiteral("color:#b00000"));
    top->addWidget(m_refusal);
    m_result = new QLabel(this);
    m_result->setObjectName(QStringLiteral("label-dispatch-result"));
    m_result->setWordWrap(true);
    m_result->setTextInteractionFlags(Qt::TextSelectableByMouse);
    top->addWidget(m_result);
    m_refusal->hide();
    m_result->hide();
}

void DispatchPanel::connectControls(DispatchSource* source, FleetSelection* selection) {
    // Keyboard (within the panel).
    auto shortcut = [this](const QKeySequence& k, auto slot) {
        auto* s = new QShortcut(k, this);
        s->setContext(Qt::WidgetWithChildrenShortcut);
        connect(s, &QShortcut::activated, this, slot);
    };
    shortcut(QKeySequence(Qt::CTRL | Qt::Key_Return), &DispatchPanel::assignCurrent);
    shortcut(QKeySequence(Qt::CTRL | Qt::Key_Enter), &DispatchPanel::assignCurrent);
    shortcut(QKeySequence(Qt::Key_F6), &DispatchPanel::selectNextNeedingAssignment);
    shortcut(QKeySequence(Qt::Key_Escape), [this] {
        if (m_pick->isChecked())
            m_pick->setChecked(false);
    });

    if (m_gate)
        connect(m_gate, &CommandGate::permissionsChanged, this, &DispatchPanel::updateControls);
    // The preview is a question the dispatcher asks at this panel: another workspace's map does not show it.
    m_onScreen = new OnScreenWatcher(this);
    connect(m_onScreen, &OnScreenWatcher::changed, this, &DispatchPanel::updateRoute);
    connect(m_assign, &QPushButton::clicked, this, &DispatchPanel::assignCurrent);
    connect(m_reset, &QPushButton::clicked, this, &DispatchPanel::resetCurrent);
    connect(m_pick, &QPushButton::toggled, this, &DispatchPanel::pickOnMap);
    connect(m_destination, &QComboBox::currentIndexChanged, this, [this] {
        // The area's own task is the natural one (Load at a shovel, Offload at a dump...).
        const QString task = m_destination->currentData(Qt::UserRole + 1).toString();
        if (kTasks.contains(task))
            m_task->setCurrentText(task);
        updateControls();
        updateRoute();
    });
    connect(m_task, &QComboBox::currentIndexChanged, this, &DispatchPanel::updateControls);
    connect(m_table->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex& cur) {
                const QString id =
                    cur.isValid() ? m_model->data(cur, DispatchModel::IdRole).toString() : QString();
                setCurrentTruck(id);
                if (m_selection && !m_syncing && !id.isEmpty()) {
                    m_syncing = true;
                    m_selection->setCurrent(id);
                    m_syncing = false;
                }
            });
    if (selection)
        connect(selection, &FleetSelection::currentMachineChanged, this, [this](const QString& id) {
            if (m_syncing || m_model->rowOf(id) < 0)
                return;
            m_syncing = true;
            m_table->setCurrentIndex(m_model->index(m_model->rowOf(id), 0));
            m_syncing = false;
        });
    connect(m_model, &DispatchModel::trucksUpdated, this, &DispatchPanel::onTrucksUpdated);
    if (source)
        connect(source, &DispatchSource::areasChanged, this, &DispatchPanel::rebuildDestinations);
}

DispatchPanel::~DispatchPanel() {
    if (m_map)
        m_map->setAreaPicking(false);
    delete m_overlay;
}

void DispatchPanel::setAutoDispatcher(AutoDispatcher* autoDispatcher) {
    if (m_autoDispatcher)
        disconnect(m_autoDispatcher, nullptr, this, nullptr);
    disconnect(m_auto, &QPushButton::clicked, this, nullptr);
    m_autoDispatcher = autoDispatcher;
    m_auto->setVisible(autoDispatcher != nullptr);
    if (!autoDispatcher) {
        m_autoLabel->hide();
        return;
    }
    connect(autoDispatcher, &AutoDispatcher::stateChanged, this, &DispatchPanel::updateAuto);
    connect(autoDispatcher, &AutoDispatcher::acted, this, &DispatchPanel::updateAuto);
    connect(m_auto, &QPushButton::clicked, this, [this](bool on) {
        if (!m_autoDispatcher)
            return;
        if (on &&
            !confirm(tr("Switch auto dispatch on?"),
                     tr("Every idle truck the FMS dispatches will be assigned automatically (empty: "
                        "shortest shovel queue; loaded: shortest dump queue) until you switch it off.")))
            on = false;
        m_autoDispatcher->setOn(on, QStringLiteral("gui"));
        updateAuto();
    });
    updateAuto();
}

void DispatchPanel::updateAuto() {
    if (!m_autoDispatcher)
        return;
    const bool on = m_autoDispatcher->isOn();
    {
        const QSignalBlocker block(m_auto);
        m_auto->setChecked(on);
    }
    m_auto->setText(on ? tr("A&uto dispatch ON") : tr("A&uto dispatch"));
    m_auto->setStyleSheet(on ? QStringLiteral("background:#1b5e20; color:white; font-weight:bold;")
                             : QString());
    const QString last = m_autoDispatcher->lastAction();
    m_autoLabel->setText(on ? tr("Auto dispatch ON — last: %1").arg(last.isEmpty() ? tr("nothing yet") : last)
                            : (last.isEmpty() ? QString() : tr("Auto dispatch OFF — last: %1").arg(last)));
    m_autoLabel->setVisible(!m_autoLabel->text().isEmpty());
}

void DispatchPanel::setMap(SiteMapView* map) {
    delete m_overlay;
    m_overlay = nullptr;
    if (m_map)
        disconnect(m_map, nullptr, this, nullptr);
    m_map = map;
    if (!map)
        return;
    m_overlay = new RouteOverlay2D(map);
    updateControls();
    connect(map, &SiteMapView::areaClicked, this, &DispatchPanel::pickArea);
    connect(map, &QObject::destroyed, this, [this] {
        if (m_overlay)
            m_overlay->forgetView(); // QWidget emits destroyed before its QPointers are cleared
        delete m_overlay;
        m_overlay = nullptr;
    });
    updateRoute();
}

bool DispatchPanel::confirm(const QString& title, const QString& text) {
    if (m_confirm)
        return m_confirm(title, text);
    return QMessageBox::question(this, title, text, QMessageBox::Yes | QMessageBox::No, QMessageBox::No) ==
           QMessageBox::Yes;
}

void DispatchPanel::rebuildDestinations() {
    const QString keep = m_destination->currentData().toString();
    const QSignalBlocker block(m_destination);
    m_destination->clear();
    if (m_source) {
        QVector<DispatchArea> areas = m_source->areas();
        // Load, dump and crusher areas first, then park and fuel; by name.
        auto rank = [](const DispatchArea& a) {
            return a.defaultTask == QLatin1String("Load")      ? 0
                   : a.defaultTask == QLatin1String("Offload") ? 1
                                                               : 2;
        };
        std::stable_sort(areas.begin(), areas.end(), [&](const DispatchArea& a, const DispatchArea& b) {
            return rank(a) != rank(b) ? rank(a) < rank(b) : a.name < b.name;
        });
        for (const auto& a : areas) {
            m_destination->addItem(areaText(a), a.featureId());
            m_destination->setItemData(m_destination->count() - 1, a.defaultTask, Qt::UserRole + 1);
        }
    }
    if (m_destination->count() == 0)
        m_destination->setPlaceholderText(tr("no areas yet (waiting for the road network)"));
    const int at = m_destination->findData(keep);
    m_destination->setCurrentIndex(at >= 0 ? at : (m_destination->count() > 0 ? 0 : -1));
    if (at < 0 && m_destination->count() > 0) {
        const QString task = m_destination->currentData(Qt::UserRole + 1).toString();
        if (kTasks.contains(task))
            m_task->setCurrentText(task);
    }
    updateControls();
}

void DispatchPanel::setCurrentTruck(const QString& id) {
    if (id == m_current)
        return;
    m_current = id;
    const int row = m_model->rowOf(id);
    if (row >= 0 && m_table->currentIndex().row() != row) {
        m_syncing = true;
        m_table->setCurrentIndex(m_model->index(row, 0));
        m_syncing = false;
    }
    updateControls();
    updateRoute();
}

void DispatchPanel::onTrucksUpdated(const QStringList& ids) {
    const int n = m_model->needsAssignmentCount();
    if (n != m_needsShown) { // a style sheet change re-polishes the label: only when the count changed
        m_needsShown = n;
        m_needs->setText(n == 0 ? tr("no truck needs an assignment")
                                : tr("%n truck(s) need an assignment", "", n));
        m_needs->setStyleSheet(n == 0 ? QString()
                                      : QStringLiteral("background:#ffd54f; color:black; font-weight:bold;"
                                                       " padding:1px 6px; border-radius:3px;"));
    }
    if (m_current.isEmpty() && m_model->rowCount() > 0 && !m_table->currentIndex().isValid()) {
        // Nothing chosen yet: start on the first truck, so the keyboard has a row to move from.
        m_table->setCurrentIndex(m_model->index(0, 0));
    }
    if (m_model->rowOf(m_current) < 0 && !m_current.isEmpty()) {
        m_current.clear();
        updateRoute();
    }
    if (ids.isEmpty() || ids.contains(m_current)) {
        updateControls();
        updateRoute();
    }
    if (!m_followTruck.isEmpty() && (ids.isEmpty() || ids.contains(m_followTruck)))
        followAnswer();
}

void DispatchPanel::updateControls() {
    // Switching automatic dispatch is in the role table too (its state stays shown while greyed).
    m_auto->setEnabled(permittedShowingWhy(m_auto, m_gate, QStringLiteral("auto_dispatch")));
    const int row = m_model->rowOf(m_current);
    if (row < 0) {
        m_assign->setEnabled(false);
        m_reset->setEnabled(false);
        permittedShowingWhy(m_assign, m_gate, QStringLiteral("assign"));
        permittedShowingWhy(m_reset, m_gate, QStringLiteral("reset_assignment"));
        m_pick->setEnabled(false);
        setLine(m_refusal,
                m_model->rowCount() == 0 ? tr("No haul truck reports dispatch data yet.") : QString());
        return;
    }
    const DispatchTruck& t = m_model->truckAt(row);
    const QString why = m_source ? m_source->assignRefusal(m_current) : tr("no dispatch source");
    setLine(m_refusal, why);
    m_assign->setText(hasTask(t) ? tr("Re-&assign") : tr("&Assign"));
    m_assign->setToolTip(why.isEmpty() ? tr("Send %1 to %2 as %3 (Ctrl+Enter)")
                                             .arg(t.name, m_destination->currentText(), m_task->currentText())
                                       : why);
    // The operator's role too (the gate's table): greyed with the role needed in the tooltip.
    m_assign->setEnabled(permittedShowingWhy(m_assign, m_gate, QStringLiteral("assign")) && why.isEmpty() &&
                         m_destination->currentIndex() >= 0 && m_gate);
    m_reset->setEnabled(permittedShowingWhy(m_reset, m_gate, QStringLiteral("reset_assignment")) &&
                        why.isEmpty() && hasTask(t) && m_gate);
    m_pick->setEnabled(m_map != nullptr);
}

void DispatchPanel::updateRoute() {
    const int row = m_model->rowOf(m_current);
    DispatchRoute r;
    QString label;
    bool preview = false;
    if (row >= 0) {
        const DispatchTruck& t = m_model->truckAt(row);
        r = m_model->routeOf(row);
        if (!r.ways.isEmpty()) {
            label =
                QStringLiteral("%1 → %2 · ETA %3")
                    .arg(t.name, m_model->data(m_model->index(row, DispatchModel::ColDestination)).toString(),
                         m_model->data(m_model->index(row, DispatchModel::ColEta)).toString());
        } else if (const auto area = currentArea();
                   area && m_source && m_onScreen && m_onScreen->onScreen()) {
            // No task: the route the truck would drive to the chosen destination, before it is sent.
            r = m_source->routeTo(t.id, *area);
            preview = true;
            if (!r.ways.isEmpty())
                label = tr("preview: %1 → %2 · %3 m").arg(t.name, area->name).arg(r.lengthM, 0, 'f', 0);
        }
    }
    if (m_overlay)
        m_overlay->setRoute(r.link, r.ways, label, preview);
    emit routeChanged(r.link, r.ways);
}

std::optional<DispatchArea> DispatchPanel::currentArea() const {
    if (!m_source || m_destination->currentIndex() < 0)
        return std::nullopt;
    const QString featureId = m_destination->currentData().toString();
    for (const auto& a : m_source->areas())
        if (a.featureId() == featureId)
            return a;
    return std::nullopt;
}

void DispatchPanel::selectNextNeedingAssignment() {
    const int n = m_model->rowCount();
    if (n == 0)
        return;
    const int start = std::max(0, m_model->rowOf(m_current));
    for (int i = 1; i <= n; ++i) {
        const int row = (start + i) % n;
        if (m_model->truckAt(row).needsAssignment) {
            m_table->setCurrentIndex(m_model->index(row, 0));
            m_table->setFocus();
            return;
        }
    }
}

void DispatchPanel::pickOnMap(bool on) {
    if (m_pick->isChecked() != on)
        m_pick->setChecked(on); // re-enters through toggled
    if (!m_map)
        return;
    m_pickFor = on ? m_current : QString();
    m_map->setAreaPicking(on);
    setLine(m_result,
            on ? tr("Click an area on the 2D map for %1 (Esc cancels).")
                     .arg(m_model->rowOf(m_current) >= 0 ? m_model->truckAt(m_model->rowOf(m_current)).name
                                                         : QString())
               : QString());
}

void DispatchPanel::pickArea(const QString& featureId) {
    const int at = m_destination->findData(featureId);
    if (at < 0) {
        setLine(m_result, tr("That map area is not a destination of the road network (no area way %1).")
                              .arg(featureId.section(QLatin1Char('/'), -1)));
        return;
    }
    m_destination->setCurrentIndex(at);
    if (m_pick->isChecked())
        m_pick->setChecked(false);
    if (!m_pickFor.isEmpty())
        setCurrentTruck(m_pickFor);
    setLine(m_result, tr("Destination picked on the map: %1").arg(m_destination->currentText()));
    m_assign->setFocus();
}

void DispatchPanel::assignCurrent() {
    const int row = m_model->rowOf(m_current);
    if (row < 0 || !m_gate || !m_source || m_destination->currentIndex() < 0)
        return;
    const DispatchTruck t = m_model->truckAt(row);
    const auto picked = currentArea();
    if (!picked)
        return;
    const DispatchArea area = *picked;
    const QString task = m_task->currentText();
    const QString what = tr("%1 to %2 for %3").arg(task, areaText(area), t.name);
    if (hasTask(t) &&
        !confirm(tr("Re-assign %1?").arg(t.name),
                 tr("%1 has a %2 assignment (%3 to %4). Replace it with %5?")
                     .arg(t.name, t.assignmentStatus, t.task,
                          t.destinationName.isEmpty() ? QString::number(t.destinationId.value_or(0))
                                                      : t.destinationName,
                          what)))
        return;
    QString assignmentId;
    const Assign assign = m_source->assignCommand(t.id, task, area, &assignmentId);
    m_followTruck = t.id;
    m_followAssignment = assignmentId;
    m_followText.clear();
    QPointer<DispatchPanel> self(this);
    m_gate->command(assign, QStringLiteral("gui"), [self, what](const CommandResult& r) {
        if (self)
            self->showResult(tr("Assign %1").arg(what), r);
    });
}

void DispatchPanel::resetCurrent() {
    const int row = m_model->rowOf(m_current);
    if (row < 0 || !m_gate)
        return;
    const DispatchTruck t = m_model->truckAt(row);
    if (!confirm(tr("Reset %1's assignment?").arg(t.name),
                 tr("%1 will drop its %2 assignment (%3) and wait for a new one.")
                     .arg(t.name, t.assignmentStatus.isEmpty() ? tr("current") : t.assignmentStatus,
                          t.task.isEmpty() ? tr("no task reported") : t.task)))
        return;
    m_followTruck.clear();
    QPointer<DispatchPanel> self(this);
    const QString what = t.name;
    m_gate->command(ResetAssignment{t.id}, QStringLiteral("gui"), [self, what](const CommandResult& r) {
        if (self)
            self->showResult(tr("Reset %1").arg(what), r);
    });
}

void DispatchPanel::showResult(const QString& what, const CommandResult& r) {
    QStringList parts;
    for (const TargetOutcome& t : r.targets) {
        const int row = m_model->rowOf(targetId(t));
        const QString name = row >= 0 ? m_model->truckAt(row).name : targetId(t);
        parts << (t.sent ? tr("%1: sent").arg(name) : tr("%1: NOT sent — %2").arg(name, reasonText(t)));
    }
    if (parts.isEmpty())
        parts << (r.ok ? r.message : tr("NOT sent — %1").arg(r.message));
    m_followText = QStringLiteral("%1 %2: %3")
                       .arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss")), what,
                            parts.join(QStringLiteral("; ")));
    if (!r.ok)
        m_followTruck.clear(); // nothing on the wire: no answer to wait for
    m_result->setStyleSheet(r.ok ? QString() : QStringLiteral("color:#b00000; font-weight:bold"));
    setLine(m_result, m_followText);
    followAnswer();
}

void DispatchPanel::followAnswer() {
    if (m_followTruck.isEmpty() || m_followText.isEmpty() || !m_source)
        return;
    const auto t = m_source->truck(m_followTruck);
    if (!t || t->requestedAssignmentId != m_followAssignment || t->lastResponse.isEmpty())
        return;
    QString answer = t->lastResponse == QLatin1String("Accepted")
                         ? tr("the truck answered Accepted")
                         : tr("the truck answered %1: %2").arg(t->lastResponse, t->lastResponseDetail);
    if (t->assignmentId == m_followAssignment && !t->assignmentStatus.isEmpty())
        answer += tr(", assignment %1").arg(t->assignmentStatus);
    m_result->setStyleSheet(t->lastResponse == QLatin1String("Accepted")
                                ? QStringLiteral("color:#1b5e20; font-weight:bold")
                                : QStringLiteral("color:#b00000; font-weight:bold"));
    setLine(m_result, m_followText + QStringLiteral(" — ") + answer);
}

} // namespace ocu
