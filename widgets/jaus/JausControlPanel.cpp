#include "widgets/jaus/JausControlPanel.h"

#include "models/CommandGate.h"

#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/jaus/JausSubsystemModel.h"
#include "widgets/ColumnFit.h"
#include "widgets/CommandPermissionHint.h"
#include "widgets/FleetListWidget.h"
#include "widgets/jaus/HandoffBanner.h"
#include "widgets/jaus/PlatformServicesWidget.h"
#include "widgets/jaus/VehicleDetailsWidget.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonObject>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QStackedWidget>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>

namespace ocu {

JausControlPanel::JausControlPanel(JausVehicleBridge* bridge, CommandGate* gate, FleetSelection* selection,
                                   QWidget* parent)
    : QWidget(parent), m_bridge(bridge), m_gate(gate), m_selection(selection),
      m_model(new JausSubsystemModel(bridge, this)), m_table(new QTableView(this)),
      m_details(new VehicleDetailsWidget(bridge, this)), m_roleLabel(new QLabel(this)),
      m_releaseAll(new QPushButton(tr("Release all"), this)), m_detailsStack(new QStackedWidget(this)),
      m_hint(new QLabel(this)), m_generic(new QLabel), m_detailsRefresh(new QTimer(this)) {
    setObjectName(QStringLiteral("jaus-control-panel"));
    auto* top = new QHBoxLayout;
    const JausConsoleIdentity me = bridge->identity();
    m_roleLabel->setText(me.mayControl ? tr("This console: %1 [%2] · authority %3")
                                             .arg(me.callSign)
                                             .arg(me.subsystemId)
                                             .arg(me.authority)
                                       : tr("This console: %1 [%2] · MONITOR role: commands are disabled")
                                             .arg(me.callSign)
                                             .arg(me.subsystemId));
    m_roleLabel->setWordWrap(true); // a narrow dock wraps it rather than cutting off "Release all"
    top->addWidget(m_roleLabel, 1);
    m_releaseAll->setObjectName(QStringLiteral("button-release-all"));
    connect(m_releaseAll, &QPushButton::clicked, this, [this] { send(ReleaseAll{}); });
    top->addWidget(m_releaseAll);
    m_handoff = new HandoffBanner(bridge, gate, selection, this);
    // Keyboard path: Release all, the banner's buttons while it shows, then the vehicle table.
    QWidget* prev = m_releaseAll;
    for (QWidget* w : m_handoff->tabChain()) {
        QWidget::setTabOrder(prev, w);
        prev = w;
    }
    QWidget::setTabOrder(prev, m_table);

    m_table->setModel(m_model);
    m_table->setObjectName(QStringLiteral("jaus-subsystems"));
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->verticalHeader()->setVisible(false);
    m_table->verticalHeader()->setDefaultSectionSize(30);
    fitColumnsWithinWidth();
    // Keyboard-only path (docs/keyboard.md): arrows move between vehicles, Tab leaves the table
    // for the row's Monitor / Control / Release buttons (with tab navigation on, Tab cycled the cells).
    m_table->setTabKeyNavigation(false);

    // The details pane: what to do when nothing is selected, the JAUS details of a JAUS
    // vehicle, the fleet picture's details of a machine of any other protocol.
    m_hint->setObjectName(QStringLiteral("details-hint"));
    m_hint->setText(tr("No machine selected.\nSelect one in the fleet list, in the table above or on the map "
                       "(click, or Tab to the list and use the arrow keys) to see its details here."));
    m_hint->setAlignment(Qt::AlignCenter);
    m_hint->setWordWrap(true);
    m_hint->setMargin(12);
    m_generic->setObjectName(QStringLiteral("details-generic"));
    m_generic->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_generic->setWordWrap(true);
    m_generic->setMargin(8);
    m_generic->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
    auto* genericScroll = new QScrollArea(this);
    genericScroll->setWidget(m_generic);
    genericScroll->setWidgetResizable(true);
    m_detailsStack->addWidget(m_hint);
    m_detailsStack->addWidget(m_details);
    m_detailsStack->addWidget(genericScroll);
    m_detailsStack->setCurrentWidget(m_hint);
    m_detailsRefresh->setInterval(1000);
    connect(m_detailsRefresh, &QTimer::timeout, this, [this] {
        if (isVisible())
            showMachineDetails(m_detailsId);
    });
    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(m_table);
    split->addWidget(m_detailsStack);
    split->setStretchFactor(0, 2);
    split->setStretchFactor(1, 3);
    auto* l = new QVBoxLayout(this);
    l->setContentsMargins(2, 2, 2, 2);
    l->addLayout(top);
    l->addWidget(m_handoff);
    l->addWidget(split);
    m_platform = new PlatformServicesWidget(bridge, gate, this);
    l->addWidget(m_platform);

    connect(m_model, &QAbstractItemModel::rowsInserted, this,
            [this](const QModelIndex&, int first, int last) { installRowButtons(first, last); });
    connect(m_model, &QAbstractItemModel::dataChanged, this, &JausControlPanel::refreshButtons);
    if (gate)
        connect(gate, &CommandGate::permissionsChanged, this, &JausControlPanel::refreshButtons);
    installRowButtons(0, m_model->rowCount() - 1);

    connect(m_table->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex& current) {
                const std::uint16_t sub = m_model->subsystemAt(current.row());
                m_details->showSubsystem(sub);
                m_platform->setVehicle(sub);
                if (sub)
                    m_detailsStack->setCurrentWidget(m_details);
                if (m_selection && sub)
                    m_selection->setCurrent(JausVehicleBridge::machineId(sub));
            });
    if (m_selection)
        connect(m_selection, &FleetSelection::currentMachineChanged, this, [this](const QString& id) {
            if (auto sub = JausVehicleBridge::subsystemOf(id))
                selectSubsystem(*sub);
            showMachineDetails(id);
        });
}

void JausControlPanel::fitColumnsWithinWidth() {
    // The table fits its dock: the controller takes the width left (elided, its whole text in the tooltip),
    // the health and management go out of sight in a narrow dock (the header's menu brings them back), the
    // vehicle's name elides last and the row's buttons never.
    using S = JausSubsystemModel;
    useElidingHeader(m_table);
    QHeaderView* h = m_table->horizontalHeader();
    h->setSectionResizeMode(QHeaderView::Interactive);
    h->setSectionResizeMode(S::Controller, QHeaderView::Stretch);
    setColumnDroppable(m_table, S::Management, 0);
    setColumnDroppable(m_table, S::Health, 1);
    setColumnShrinkTier(m_table, S::Vehicle, 1);
    startColumnsAtHeaderWidth(m_table);
    keepColumnsWithinWidth(m_table);
    keepColumnsFitted(m_table);
    addColumnMenu(m_table);
    showElidedTextInTooltips(m_table);
}

void JausControlPanel::showMachineDetails(const QString& id) {
    m_detailsId = id;
    const MachineState* m =
        id.isEmpty() || !m_selection || !m_selection->model() ? nullptr : m_selection->model()->machine(id);
    if (JausVehicleBridge::subsystemOf(id) && m_model->rowOf(*JausVehicleBridge::subsystemOf(id)) >= 0) {
        m_detailsRefresh->stop();
        m_detailsStack->setCurrentWidget(m_details);
    } else if (m != nullptr) {
        m_generic->setText(FleetListWidget::describeMachine(*m));
        m_detailsStack->setCurrentIndex(2);
        if (!m_detailsRefresh->isActive())
            m_detailsRefresh->start();
    } else {
        m_detailsRefresh->stop();
        m_detailsStack->setCurrentWidget(m_hint);
    }
}

QString JausControlPanel::detailsText() const {
    QWidget* page = m_detailsStack->currentWidget();
    if (page == m_hint)
        return m_hint->text();
    if (page == m_details)
        return QStringLiteral("jaus:%1").arg(m_details->subsystem());
    return m_generic->text();
}

void JausControlPanel::selectSubsystem(std::uint16_t subsystem) {
    const int row = m_model->rowOf(subsystem);
    if (row < 0 || m_table->currentIndex().row() == row)
        return;
    m_table->setCurrentIndex(m_model->index(row, 0));
}

static QPushButton* findButton(QWidget* cell, const char* name) {
    return cell ? cell->findChild<QPushButton*>(QLatin1String(name)) : nullptr;
}

QPushButton* JausControlPanel::controlButton(std::uint16_t subsystem) const {
    return findButton(
        m_table->indexWidget(m_model->index(m_model->rowOf(subsystem), JausSubsystemModel::Actions)),
        "control");
}
QPushButton* JausControlPanel::releaseButton(std::uint16_t subsystem) const {
    return findButton(
        m_table->indexWidget(m_model->index(m_model->rowOf(subsystem), JausSubsystemModel::Actions)),
        "release");
}
QPushButton* JausControlPanel::monitorButton(std::uint16_t subsystem) const {
    return findButton(
        m_table->indexWidget(m_model->index(m_model->rowOf(subsystem), JausSubsystemModel::Actions)),
        "monitor");
}

void JausControlPanel::installRowButtons(int first, int last) {
    for (int row = first; row <= last && row >= 0; ++row) {
        const std::uint16_t sub = m_model->subsystemAt(row);
        auto* cell = new QWidget(m_table);
        auto* h = new QHBoxLayout(cell);
        h->setContentsMargins(2, 0, 2, 0);
        h->setSpacing(3);
        auto make = [&](const QString& text, const char* name, const QString& tip) {
            auto* b = new QPushButton(text, cell);
            b->setObjectName(QLatin1String(name));
            b->setToolTip(tip);
            h->addWidget(b);
            return b;
        };
        auto* monitor = make(tr("Monitor"), "monitor", tr("Select this vehicle to watch it (no control)"));
        auto* control = make(tr("Control"), "control", tr("Request control with this console's authority"));
        auto* release = make(tr("Release"), "release", tr("Release control of this vehicle"));
        connect(monitor, &QPushButton::clicked, this, [this, sub] {
            selectSubsystem(sub);
            if (m_selection)
                m_selection->setCurrent(JausVehicleBridge::machineId(sub));
        });
        connect(control, &QPushButton::clicked, this, [this, sub] {
            selectSubsystem(sub);
            send(RequestControl{JausVehicleBridge::machineId(sub)});
        });
        connect(release, &QPushButton::clicked, this,
                [this, sub] { send(ReleaseControl{JausVehicleBridge::machineId(sub)}); });
        m_table->setIndexWidget(m_model->index(row, JausSubsystemModel::Actions), cell);
        // The buttons whole, always: their column never gives up width.
        const int buttons = cell->sizeHint().width() + 4;
        if (buttons > m_actionsWidth) {
            m_actionsWidth = buttons;
            m_table->setColumnWidth(JausSubsystemModel::Actions, buttons);
            setColumnShrinkTier(m_table, JausSubsystemModel::Actions, 9, buttons);
            fitColumnsToContent(m_table);
        }
    }
    // Rows inserted above shift the index widgets: reinstall them for every row.
    if (first < m_model->rowCount() - 1 && last < m_model->rowCount() - 1 && first >= 0) {
        for (int row = last + 1; row < m_model->rowCount(); ++row)
            if (!m_table->indexWidget(m_model->index(row, JausSubsystemModel::Actions)))
                installRowButtons(row, row);
    }
    // Tab order: from the table straight to the rows' buttons, row by row (they are created after the rest
    // of the panel, so by default they came last, after the details and the teleop panel).
    QWidget* prev = m_table;
    for (int row = 0; row < m_model->rowCount(); ++row)
        if (QWidget* cell = m_table->indexWidget(m_model->index(row, JausSubsystemModel::Actions)))
            for (const char* name : {"monitor", "control", "release"})
                if (QPushButton* b = findButton(cell, name)) {
                    QWidget::setTabOrder(prev, b);
                    prev = b;
                }
    refreshButtons();
}

void JausControlPanel::refreshButtons() {
    const bool may = m_bridge->mayCommand();
    // The operator's role too (the gate's table): greyed with the role needed in the tooltip.
    m_releaseAll->setEnabled(permittedShowingWhy(m_releaseAll, m_gate, QStringLiteral("release_all")) && may);
    for (int row = 0; row < m_model->rowCount(); ++row) {
        const JausVehicle* s = m_model->vehicleAt(row);
        QWidget* cell = m_table->indexWidget(m_model->index(row, JausSubsystemModel::Actions));
        if (!s || !cell)
            continue;
        // Control can be requested once the vehicle's mobility component (its access-control service) is
        // known.
        const bool up = s->link != JausLink::Down && s->mobilityComponent.subsystem != 0;
        if (auto* b = findButton(cell, "control"))
            b->setEnabled(permittedShowingWhy(b, m_gate, QStringLiteral("request_control")) && may && up &&
                          !s->controlledByUs);
        if (auto* b = findButton(cell, "release"))
            b->setEnabled(permittedShowingWhy(b, m_gate, QStringLiteral("release_control")) && may &&
                          s->controlledByUs);
    }
}

void JausControlPanel::send(const OperatorCommand& command) {
    // Through the command gate: audited, and its result (targets sent or not) lands in the event log.
    if (m_gate)
        m_gate->command(command, QStringLiteral("gui"));
}

} // namespace ocu
