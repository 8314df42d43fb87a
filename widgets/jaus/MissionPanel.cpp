#include "widgets/jaus/MissionPanel.h"

#include "models/CommandGate.h"
#include "models/FleetSelection.h"
#include "models/jaus/JausVehicleBridge.h"
#include "models/jaus/MissionGeoJson.h"
#include "models/jaus/MissionImport.h"
#include "models/jaus/MissionPlan.h"
#include "widgets/CommandPermissionHint.h"
#include "widgets/SiteMapView.h"
#include "widgets/jaus/MissionCommands.h"
#include "widgets/jaus/MissionPlanEditor.h"
#include "widgets/jaus/MissionPlanLayer.h"
#include "widgets/jaus/MissionPlanTableModel.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QShortcut>
#include <QSpinBox>
#include <QTableView>
#include <QTimer>
#include <QUndoStack>
#include <QVBoxLayout>

#include <cmath>

namespace ocu {

namespace {

QString duration(double s) {
    const qint64 t = qint64(std::llround(s));
    if (t < 60)
        return MissionPanel::tr("%1 s").arg(t);
    if (t < 3600)
        return MissionPanel::tr("%1 min %2 s").arg(t / 60).arg(t % 60);
    return MissionPanel::tr("%1 h %2 min").arg(t / 3600).arg((t % 3600) / 60);
}

QString metres(double m) {
    return m < 1000 ? MissionPanel::tr("%1 m").arg(qint64(std::llround(m)))
                    : MissionPanel::tr("%1 km").arg(m / 1000, 0, 'f', 2);
}

// "1 waypoint", "3 waypoints" (no plural forms needed in the translations).
QString waypointCount(int n) {
    return n == 1 ? MissionPanel::tr("1 waypoint") : MissionPanel::tr("%1 waypoints").arg(n);
}

bool isOneOf(MissionState s, std::initializer_list<MissionState> states) {
    return std::find(states.begin(), states.end(), s) != states.end();
}

} // namespace

MissionPanel::MissionPanel(JausVehicleBridge* bridge, FleetSelection* selection, QWidget* parent)
    : QWidget(parent), m_bridge(bridge), m_selection(selection) {
    build();
    if (m_bridge)
        connect(m_bridge, &JausVehicleBridge::subsystemUpdated, this, &MissionPanel::onVehicle);
    if (m_selection) {
        connect(m_selection, &FleetSelection::currentMachineChanged, this, &MissionPanel::onSelection);
        onSelection(m_selection->currentId());
    }
    refreshState();
    refreshButtons();
}

MissionPanel::~MissionPanel() {
    delete m_editor; // before the layer it edits
    delete m_layer;
}

QPushButton* MissionPanel::addButton(Action a, const QString& text, const QString& tip) {
    auto* b = new QPushButton(text, this);
    b->setToolTip(tip);
    m_buttons.insert(int(a), b);
    return b;
}

QPushButton* MissionPanel::button(Action a) const {
    return m_buttons.value(int(a));
}

void MissionPanel::build() {
    m_routeTimer = new QTimer(this);
    m_routeTimer->setSingleShot(true);
    m_routeTimer->setInterval(100);
    connect(m_routeTimer, &QTimer::timeout, this, [this] {
        MissionPlan* p = plan();
        const QColor colour = MissionPlanLayer::missionColour(m_vehicle);
        emit planRouteChanged(p ? p->waypoints() : QVector<MissionWaypoint>{}, colour);
        const QVector<QPair<double, double>> path = m_reported.value(m_vehicle).drivenPath;
        if (path != m_pathSent || m_vehicle != m_pathSentFor) {
            m_pathSent = path;
            m_pathSentFor = m_vehicle;
            emit drivenPathChanged(path, colour);
        }
    });
    m_title = new QLabel(this);
    m_title->setWordWrap(true);
    QFont bold = m_title->font();
    bold.setBold(true);
    m_title->setFont(bold);
    m_state = new QLabel(this);
    m_state->setWordWrap(true);
    m_state->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_summary = new QLabel(this);
    m_message = new QLabel(this);
    m_message->setWordWrap(true);
    m_unavailable = new QLabel(tr("Sending missions is not available in this build: the plan can be edited, "
                                  "saved, opened and drawn."),
                               this);
    m_unavailable->setWordWrap(true);

    auto* edit = addButton(Action::Edit, tr("&Edit on map"),
                           tr("Click on the map to add waypoints, drag them, click a leg to insert one"));
    edit->setCheckable(true);
    addButton(Action::Open, tr("&Open…"), tr("Open a mission saved as GeoJSON"));
    addButton(Action::Import, tr("&Import…"), tr("Import a route from GPX or KML"));
    addButton(Action::Save, tr("&Save…"), tr("Save the plan as GeoJSON"));
    addButton(Action::Clear, tr("Clear"), tr("Remove every waypoint (undo brings them back)"));
    addButton(Action::Delete, tr("Delete waypoint"), tr("Delete the selected waypoint (Delete)"));
    addButton(Action::Undo, tr("Undo"), tr("Undo the last edit (Ctrl+Z)"));
    addButton(Action::Redo, tr("Redo"), tr("Redo (Ctrl+Shift+Z)"));
    addButton(Action::Upload, tr("Up&load"),
              tr("Send the plan to the vehicle; uploaded once read back equal"));
    addButton(Action::Start, tr("Start"), tr("Run the uploaded mission from the waypoint chosen beside"));
    addButton(Action::Pause, tr("&Pause"), tr("Pause the running mission"));
    addButton(Action::Resume, tr("Resume"), tr("Resume the paused mission"));
    addButton(Action::Abort, tr("A&bort"), tr("Abort the mission"));
    m_from = new QSpinBox(this);
    m_from->setPrefix(tr("from "));
    m_from->setMinimum(1);
    m_from->setToolTip(tr("The waypoint the mission starts from"));

    m_model = new MissionPlanTableModel(this);
    m_table = new QTableView(this);
    m_table->setModel(m_model);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                             QAbstractItemView::AnyKeyPressed);

    // Rows of at most three buttons: the panel shares the side column with the JAUS panels.
    auto row = [this](std::initializer_list<QWidget*> widgets) {
        auto* h = new QHBoxLayout;
        for (QWidget* w : widgets)
            h->addWidget(w);
        h->addStretch();
        return h;
    };
    auto* files = new QVBoxLayout;
    files->addLayout(row({button(Action::Edit), button(Action::Clear)}));
    files->addLayout(row({button(Action::Open), button(Action::Import), button(Action::Save)}));
    auto* edits = row({button(Action::Delete), button(Action::Undo), button(Action::Redo)});
    auto* commands = new QVBoxLayout;
    commands->addLayout(row({button(Action::Upload), button(Action::Start), m_from}));
    commands->addLayout(row({button(Action::Pause), button(Action::Resume), button(Action::Abort)}));
    auto* v = new QVBoxLayout(this);
    v->addWidget(m_title);
    v->addWidget(m_state);
    v->addLayout(files);
    v->addWidget(m_table, 1);
    v->addLayout(edits);
    v->addWidget(m_summary);
    v->addLayout(commands);
    v->addWidget(m_unavailable);
    v->addWidget(m_message);

    connectButtons();
}

void MissionPanel::connectButtons() {
    connect(button(Action::Edit), &QPushButton::toggled, this, [this](bool on) {
        if (m_editor)
            m_editor->setEditing(on);
    });
    for (Action a : {Action::Open, Action::Import, Action::Save})
        connect(button(a), &QPushButton::clicked, this, [this, a] { chooseFile(a); });
    connect(button(Action::Clear), &QPushButton::clicked, this, [this] {
        if (MissionPlan* p = plan())
            p->replace({}, tr("Clear plan"));
    });
    connect(button(Action::Delete), &QPushButton::clicked, this, &MissionPanel::deleteSelected);
    connect(button(Action::Undo), &QPushButton::clicked, this, [this] {
        if (MissionPlan* p = plan())
            p->undo();
    });
    connect(button(Action::Redo), &QPushButton::clicked, this, [this] {
        if (MissionPlan* p = plan())
            p->redo();
    });
    // The panel's own keys (the map's are the editor's): undo, redo and delete while the focus is here.
    auto shortcut = [this](const QKeySequence& keys, auto slot) {
        auto* s = new QShortcut(keys, this, slot);
        s->setContext(Qt::WidgetWithChildrenShortcut);
    };
    shortcut(QKeySequence(Qt::CTRL | Qt::Key_Z), [this] { button(Action::Undo)->click(); });
    shortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), [this] { button(Action::Redo)->click(); });
    shortcut(QKeySequence(Qt::CTRL | Qt::Key_Y), [this] { button(Action::Redo)->click(); });
    shortcut(QKeySequence(Qt::Key_Delete), [this] { deleteSelected(); });

    auto send = [this](Action a, auto call) {
        connect(button(a), &QPushButton::clicked, this, [this, call] {
            if (!m_commands || !m_vehicle)
                return;
            call();
            showMessage(tr("Sent to the command gate: the event log shows what went on the wire, the state "
                           "above what the vehicle reports"),
                        false);
        });
    };
    send(Action::Upload, [this] { m_commands->upload(machineId(), plan()->waypoints()); });
    send(Action::Start, [this] { m_commands->start(machineId(), m_from->value() - 1); });
    send(Action::Pause, [this] { m_commands->pause(machineId()); });
    send(Action::Resume, [this] { m_commands->resume(machineId()); });
    send(Action::Abort, [this] { m_commands->abort(machineId()); });

    connect(m_table->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex& cur) {
                if (m_editor && cur.isValid() && m_editor->selected() != cur.row())
                    m_editor->select(cur.row());
                refreshButtons();
            });
}

void MissionPanel::setCommands(MissionCommands* commands) {
    m_commands = commands;
    if (m_editor)
        m_editor->setGoHereTarget(m_commands && m_vehicle ? vehicleName(m_vehicle) : QString());
    refreshButtons();
}

void MissionPanel::setUnavailableText(const QString& text) {
    m_unavailable->setText(text);
}

void MissionPanel::attachMap(SiteMapView* map, const GeoFrame& frame) {
    if (!map || m_layer)
        return;
    m_layer = new MissionPlanLayer(map, frame);
    m_editor = new MissionPlanEditor(map, m_layer, this);
    m_editor->setSelection(m_selection);
    connect(m_editor, &MissionPlanEditor::editingChanged, this,
            [this](bool on) { button(Action::Edit)->setChecked(on); });
    connect(m_editor, &MissionPlanEditor::selectedChanged, this, [this](int row) {
        if (row >= 0 && row != selectedRow())
            m_table->selectRow(row);
        refreshButtons();
    });
    connect(m_editor, &MissionPlanEditor::goHereRequested, this, &MissionPanel::goHere);
    const quint16 v = m_vehicle;
    m_vehicle = 0;
    setVehicle(v); // the layer draws the current plan
    refreshMissions();
}

MissionPlan* MissionPanel::plan() const {
    return m_plans.value(m_vehicle);
}

MissionPlan* MissionPanel::planFor(quint16 subsystem) {
    if (MissionPlan* p = m_plans.value(subsystem))
        return p;
    auto* p = new MissionPlan(this);
    if (m_bridge)
        if (const auto v = m_bridge->subsystem(subsystem))
            p->setDefaults(MissionPlan::defaultsFor(v->platform));
    m_plans.insert(subsystem, p);
    return p;
}

QString MissionPanel::machineId() const {
    return JausVehicleBridge::machineId(m_vehicle);
}

QString MissionPanel::vehicleName(quint16 subsystem) const {
    const auto v = m_bridge ? m_bridge->subsystem(subsystem) : std::nullopt;
    return v && !v->callSign.isEmpty() ? v->callSign : tr("UGV %1").arg(subsystem);
}

int MissionPanel::selectedRow() const {
    const QModelIndex cur = m_table->selectionModel()->currentIndex();
    return cur.isValid() ? cur.row() : -1;
}

void MissionPanel::onSelection(const QString& id) {
    // Another protocol's machine or nothing: the plan of the last UGV stays in front.
    if (const auto sub = JausVehicleBridge::subsystemOf(id))
        setVehicle(*sub);
}

void MissionPanel::setVehicle(quint16 subsystem) {
    if (subsystem == m_vehicle)
        return;
    disconnect(m_planConnection);
    m_vehicle = subsystem;
    MissionPlan* p = subsystem ? planFor(subsystem) : nullptr;
    m_model->setPlan(p);
    if (p)
        m_planConnection = connect(p, &MissionPlan::changed, this, &MissionPanel::onPlanChanged);
    const QColor colour = MissionPlanLayer::missionColour(subsystem);
    if (m_layer)
        m_layer->setPlan(p, colour);
    if (m_editor) {
        m_editor->setGoHereTarget(m_commands && subsystem ? vehicleName(subsystem) : QString());
        if (!p)
            m_editor->setEditing(false);
    }
    m_title->setText(subsystem ? tr("Mission of %1 (%2)").arg(vehicleName(subsystem), machineId())
                               : tr("Select a UGV on the map or in the fleet list to plan its mission."));
    onPlanChanged();
}

void MissionPanel::onVehicle(const JausVehicle& v) {
    if (MissionPlan* p = m_plans.value(v.subsystem); p && v.platform) {
        const MissionPlan::Defaults d = MissionPlan::defaultsFor(v.platform);
        if (!(d == p->defaults()))
            p->setDefaults(d); // new waypoints get them; the plan's own stay as set
    }
    const bool draw = v.mission.state != MissionState::None || !v.mission.drivenPath.isEmpty();
    const auto it = m_reported.constFind(v.subsystem);
    if (draw ? (it == m_reported.constEnd() || !(*it == v.mission)) : it != m_reported.constEnd()) {
        if (draw)
            m_reported.insert(v.subsystem, v.mission);
        else
            m_reported.remove(v.subsystem);
        refreshMissions();
    }
    if (v.subsystem == m_vehicle) {
        refreshState();
        refreshButtons();
        if (v.mission.drivenPath != m_pathSent && !m_routeTimer->isActive())
            m_routeTimer->start(); // the 3D path follows the vehicle at most every 100 ms
    }
}

void MissionPanel::refreshMissions() {
    if (!m_layer)
        return;
    QVector<MissionPlanLayer::VehicleMission> drawn;
    for (auto it = m_reported.constBegin(); it != m_reported.constEnd(); ++it)
        drawn.push_back({it.key(), MissionPlanLayer::missionColour(it.key()), it.value()});
    std::sort(drawn.begin(), drawn.end(),
              [](const auto& a, const auto& b) { return a.subsystem < b.subsystem; });
    m_layer->setMissions(drawn);
}

void MissionPanel::onPlanChanged() {
    MissionPlan* p = plan();
    m_summary->setText(summaryText());
    m_from->setMaximum(std::max(1, p ? p->size() : 1));
    if (m_layer)
        m_layer->setPlanLabel(
            p && !p->isEmpty()
                ? tr("%1: %2, %3").arg(vehicleName(m_vehicle), metres(p->lengthM()), duration(p->etaS()))
                : QString());
    if (m_editor && p && m_editor->selected() >= 0 && m_editor->selected() != selectedRow())
        m_table->selectRow(m_editor->selected());
    refreshState();
    refreshButtons();
    m_routeTimer->start(); // the 3D route follows a drag at most every 100 ms
}

QString MissionPanel::summaryText() const {
    const MissionPlan* p = plan();
    if (!p || p->isEmpty())
        return m_vehicle ? tr("No waypoints yet: Edit on map, then click on the map to add them.")
                         : QString();
    QString s = tr("%1, %2, ETA %3").arg(waypointCount(p->size()), metres(p->lengthM()), duration(p->etaS()));
    const auto v = m_bridge ? m_bridge->subsystem(m_vehicle) : std::nullopt;
    if (v && v->globalPose && v->globalPose->lat && v->globalPose->lon) {
        const QPair<double, double> from{*v->globalPose->lat, *v->globalPose->lon};
        s += tr("; from the vehicle %1, %2").arg(metres(p->lengthM(from)), duration(p->etaS(from)));
    }
    return s;
}

QString MissionPanel::describe(const JausMission& m, int planned) {
    const int n = int(m.waypoints.size());
    const int k = m.activeIndex + 1;
    QString s;
    switch (m.state) {
    case MissionState::None:
        s = planned > 0 ? tr("Planned: %1, not uploaded").arg(waypointCount(planned)) : tr("No mission");
        break;
    case MissionState::Uploading:
        s = tr("Uploading %1…").arg(waypointCount(n));
        break;
    case MissionState::Uploaded:
        s = tr("Uploaded and verified: %1").arg(waypointCount(n));
        break;
    case MissionState::Running:
        s = tr("Running: waypoint %1 of %2").arg(k).arg(n);
        if (m.distanceToGoM)
            s += tr(", %1 to go").arg(metres(*m.distanceToGoM));
        if (m.etaS)
            s += tr(", ETA %1").arg(duration(*m.etaS));
        break;
    case MissionState::Paused:
        s = k > 0 ? tr("Paused at waypoint %1 of %2").arg(k).arg(n) : tr("Paused");
        break;
    case MissionState::Completed:
        s = tr("Completed: %1").arg(waypointCount(n));
        break;
    case MissionState::Aborted:
        s = k > 0 ? tr("Aborted at waypoint %1 of %2").arg(k).arg(n) : tr("Aborted");
        break;
    case MissionState::StoppedByEmergency:
        s = (k > 0 ? tr("Stopped by emergency at waypoint %1 of %2").arg(k).arg(n)
                   : tr("Stopped by emergency")) +
            tr("; clearing the emergency does not restart it");
        break;
    case MissionState::Lost:
        s = m.lastSeenIndex >= 0
                ? tr("Unknown, last seen at waypoint %1 of %2").arg(m.lastSeenIndex + 1).arg(n)
                : tr("Unknown: not seen running");
        break;
    case MissionState::Rejected:
        s = tr("Rejected: %1").arg(m.reason.isEmpty() ? tr("no reason given") : m.reason);
        break;
    }
    if (!m.reason.isEmpty() && m.state != MissionState::Rejected)
        s += tr(" (%1)").arg(m.reason);
    if (!m.ours)
        s += tr("; not ours: another console holds the vehicle's list driver");
    return s;
}

QString MissionPanel::stateText() const {
    return m_state->text();
}

QString MissionPanel::messageText() const {
    return m_message->text();
}

void MissionPanel::refreshState() {
    if (!m_vehicle) {
        m_state->clear();
        return;
    }
    const auto v = m_bridge ? m_bridge->subsystem(m_vehicle) : std::nullopt;
    const JausMission mission = v ? v->mission : JausMission{};
    QString s = describe(mission, plan() ? plan()->size() : 0);
    if (mission.state != MissionState::None && plan() && mission.waypoints != plan()->waypoints())
        s += tr("; the plan differs from the uploaded mission");
    if (!mission.drivenPath.isEmpty())
        s += tr("; driven path from the %1").arg(mission.pathSource);
    m_state->setText(s);
}

void MissionPanel::setCommandGate(CommandGate* gate) {
    if (m_gate)
        disconnect(m_gate, nullptr, this, nullptr);
    m_gate = gate;
    if (gate)
        connect(gate, &CommandGate::permissionsChanged, this, &MissionPanel::refreshButtons);
    refreshButtons();
}

void MissionPanel::refreshButtons() {
    MissionPlan* p = plan();
    const auto v = m_vehicle && m_bridge ? m_bridge->subsystem(m_vehicle) : std::nullopt;
    const JausMission m = v ? v->mission : JausMission{};
    const bool up = v && v->link != JausLink::Down;
    const bool may = m_commands && up && m_bridge && m_bridge->mayCommand() && m.ours;
    const MissionState s = m.state;
    const bool same = p && !p->isEmpty() && m.waypoints == p->waypoints();
    const bool planned = p && !p->isEmpty();
    button(Action::Edit)->setEnabled(p && m_editor);
    for (Action a : {Action::Open, Action::Import, Action::Clear})
        button(a)->setEnabled(p != nullptr);
    button(Action::Save)->setEnabled(planned);
    button(Action::Delete)->setEnabled(p && selectedRow() >= 0);
    button(Action::Undo)->setEnabled(p && p->undoStack()->canUndo());
    button(Action::Redo)->setEnabled(p && p->undoStack()->canRedo());
    // The role's permission per command (the tooltip says which role would do).
    const auto permitted = [this](Action a, const char* command) {
        return permittedShowingWhy(button(a), m_gate, QLatin1String(command));
    };
    const bool mayUpload = permitted(Action::Upload, "mission_upload");
    const bool mayStart = permitted(Action::Start, "mission_start");
    const bool mayPause = permitted(Action::Pause, "mission_pause");
    const bool mayResume = permitted(Action::Resume, "mission_resume");
    const bool mayAbort = permitted(Action::Abort, "mission_abort");
    button(Action::Upload)
        ->setEnabled(mayUpload && may && planned &&
                     !isOneOf(s, {MissionState::Uploading, MissionState::Running}));
    button(Action::Start)
        ->setEnabled(mayStart && may && same &&
                     isOneOf(s, {MissionState::Uploaded, MissionState::Completed, MissionState::Aborted,
                                 MissionState::StoppedByEmergency}));
    m_from->setEnabled(button(Action::Start)->isEnabled());
    button(Action::Pause)->setEnabled(mayPause && may && s == MissionState::Running);
    button(Action::Resume)->setEnabled(mayResume && may && s == MissionState::Paused);
    button(Action::Abort)
        ->setEnabled(mayAbort && may &&
                     isOneOf(s, {MissionState::Running, MissionState::Paused, MissionState::Uploading}));
    m_unavailable->setVisible(!m_commands && m_vehicle);
}

void MissionPanel::showMessage(const QString& text, bool error) {
    m_message->setText(text);
    m_message->setStyleSheet(error ? QStringLiteral("color: #c62828;") : QString());
}

void MissionPanel::deleteSelected() {
    MissionPlan* p = plan();
    const int row = selectedRow();
    if (!p || row < 0 || row >= p->size())
        return;
    p->remove(row);
    if (p->size() > 0) {
        m_table->selectRow(std::min(row, p->size() - 1));
        if (m_editor)
            m_editor->select(std::min(row, p->size() - 1));
    }
}

void MissionPanel::goHere(double lat, double lon) {
    if (!m_commands || !m_vehicle)
        return;
    m_commands->goTo(machineId(), plan()->makeWaypoint(lat, lon));
    showMessage(tr("Go here sent to the command gate for %1: the event log shows what went on the wire")
                    .arg(vehicleName(m_vehicle)),
                false);
}

QString MissionPanel::openFile(const QString& path) {
    QString error;
    const auto waypoints = readMissionGeoJsonFile(path, &error);
    if (!waypoints) {
        showMessage(error, true);
        return error;
    }
    plan()->replace(*waypoints, tr("Open %1").arg(QFileInfo(path).fileName()));
    showMessage(tr("Opened %1: %2").arg(QFileInfo(path).fileName(), waypointCount(int(waypoints->size()))),
                false);
    return {};
}

QString MissionPanel::importFile(const QString& path) {
    MissionFileRead r = importMissionRoute(path);
    if (!r.ok()) {
        showMessage(r.error, true);
        return r.error;
    }
    for (MissionWaypoint& w : r.waypoints) // the vehicle's defaults: the file has none
        w = plan()->makeWaypoint(w.lat, w.lon);
    plan()->replace(r.waypoints, tr("Import %1").arg(QFileInfo(path).fileName()));
    showMessage(tr("Imported %1: %2 with the vehicle's default speed and tolerance")
                    .arg(QFileInfo(path).fileName(), waypointCount(int(r.waypoints.size()))),
                false);
    return {};
}

QString MissionPanel::saveFile(const QString& path) {
    QString error;
    if (!writeMissionGeoJsonFile(path, plan() ? plan()->waypoints() : QVector<MissionWaypoint>{}, &error)) {
        showMessage(error, true);
        return error;
    }
    showMessage(tr("Saved %1").arg(QFileInfo(path).fileName()), false);
    return {};
}

void MissionPanel::chooseFile(Action a) {
    if (!plan())
        return;
    const QString geojson = tr("Mission (*.geojson *.json)");
    QString path;
    if (a == Action::Save) {
        path = QFileDialog::getSaveFileName(this, tr("Save mission"), QString(), geojson);
        if (!path.isEmpty() && QFileInfo(path).suffix().isEmpty())
            path += QStringLiteral(".geojson");
    } else {
        path = QFileDialog::getOpenFileName(
            this, a == Action::Open ? tr("Open mission") : tr("Import route"), QString(),
            a == Action::Open ? geojson : tr("Routes (*.gpx *.kml);;All files (*)"));
    }
    if (path.isEmpty())
        return;
    if (a == Action::Save)
        saveFile(path);
    else if (a == Action::Open)
        openFile(path);
    else
        importFile(path);
}

} // namespace ocu
