#include "widgets/jaus/VehicleDetailsWidget.h"

#include "models/jaus/JausSubsystemModel.h"
#include "models/jaus/JausVehicleBridge.h"

#include <QDateTime>
#include <QHeaderView>
#include <QListWidget>
#include <QSplitter>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <cmath>

namespace ocu {

VehicleDetailsWidget::VehicleDetailsWidget(JausVehicleBridge* bridge, QWidget* parent)
    : QWidget(parent), m_bridge(bridge), m_tree(new QTreeWidget(this)), m_messages(new QListWidget(this)) {
    auto* l = new QVBoxLayout(this);
    l->setContentsMargins(0, 0, 0, 0);
    auto* split = new QSplitter(Qt::Vertical, this);
    m_tree->setColumnCount(2);
    m_tree->setHeaderLabels({tr("Item"), tr("Value")});
    m_tree->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_tree->setObjectName(QStringLiteral("jaus-details-tree"));
    m_messages->setObjectName(QStringLiteral("jaus-last-messages"));
    split->addWidget(m_tree);
    split->addWidget(m_messages);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 1);
    l->addWidget(split);
    connect(bridge, &JausVehicleBridge::subsystemUpdated, this, [this](const JausVehicle& s) {
        if (s.subsystem == m_subsystem)
            rebuild(s);
    });
    connect(bridge, &JausVehicleBridge::jausEvent, this, [this](const JausVehicleEvent& e) {
        if (e.subsystem != m_subsystem || m_subsystem == 0)
            return;
        m_messages->insertItem(0, QStringLiteral("%1  %2  %3")
                                      .arg(QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss")),
                                           e.kindText, e.text));
        while (m_messages->count() > 200)
            delete m_messages->takeItem(m_messages->count() - 1);
    });
}

void VehicleDetailsWidget::showSubsystem(std::uint16_t subsystem) {
    if (subsystem != m_subsystem)
        m_messages->clear();
    m_subsystem = subsystem;
    m_tree->clear();
    if (auto s = m_bridge->subsystem(subsystem))
        rebuild(*s);
}

static QString num(const std::optional<double>& v, int prec, const QString& unit) {
    return v ? QStringLiteral("%1 %2").arg(*v, 0, 'f', prec).arg(unit) : QStringLiteral("—");
}

void VehicleDetailsWidget::rebuild(const JausVehicle& s) {
    // Keep the user's expansion state across the frequent updates.
    QSet<QString> collapsed;
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i)
        if (!m_tree->topLevelItem(i)->isExpanded())
            collapsed.insert(m_tree->topLevelItem(i)->text(0));
    m_tree->clear();
    auto section = [&](const QString& name) {
        auto* it = new QTreeWidgetItem(m_tree, {name});
        it->setExpanded(!collapsed.contains(name));
        return it;
    };
    auto row = [](QTreeWidgetItem* parent, const QString& k, const QString& v) {
        return new QTreeWidgetItem(parent, {k, v});
    };
    auto* ident = section(tr("Identification"));
    row(ident, tr("Call sign"), s.callSign);
    row(ident, tr("Subsystem ID"), QString::number(s.subsystem));
    row(ident, tr("Endpoint"), s.endpoint);
    row(ident, tr("Link"), JausSubsystemModel::linkText(s.link));

    auto* state = section(tr("State"));
    row(state, tr("Access"), JausSubsystemModel::accessText(s.access));
    row(state, tr("Management"), s.management ? s.managementText : tr("unknown"));
    row(state, tr("Emergency"), s.emergency ? tr("YES") : tr("no"));
    row(state, tr("Drive session"), s.driving ? tr("open") : tr("closed"));
    row(state, tr("Access timeout"), s.accessTimeoutS ? tr("%1 s").arg(s.accessTimeoutS) : tr("unknown"));

    auto* platform = section(tr("Platform"));
    if (s.platform) {
        const auto& p = *s.platform;
        row(platform, tr("Name"), p.name);
        row(platform, tr("Steering"), p.steeringType == 1 ? tr("Ackermann") : tr("skid steer"));
        if (p.front && p.back)
            row(platform, tr("Length"), QStringLiteral("%1 m").arg(*p.front + *p.back, 0, 'f', 2));
        if (p.left && p.right)
            row(platform, tr("Width"), QStringLiteral("%1 m").arg(*p.left + *p.right, 0, 'f', 2));
        row(platform, tr("Max forward speed"), num(p.maxForwardSpeed, 2, QStringLiteral("m/s")));
        row(platform, tr("Max reverse speed"), num(p.maxReverseSpeed, 2, QStringLiteral("m/s")));
        row(platform, tr("Max rotational speed"), num(p.maxRotationalSpeed, 2, QStringLiteral("rad/s")));
    } else {
        row(platform, tr("Specifications"), tr("not reported yet"));
    }

    addPlatformServices(section(tr("Platform services")), s.platformServices);

    auto* pose = section(tr("Pose"));
    if (s.globalPose) {
        row(pose, tr("Latitude"), num(s.globalPose->lat, 7, QStringLiteral("°")));
        row(pose, tr("Longitude"), num(s.globalPose->lon, 7, QStringLiteral("°")));
        row(pose, tr("Altitude"), num(s.globalPose->alt, 1, QStringLiteral("m")));
        if (s.globalPose->yaw)
            row(pose, tr("Heading"),
                QStringLiteral("%1 °").arg(std::fmod(*s.globalPose->yaw * 180 / M_PI + 360, 360), 0, 'f', 1));
    }
    if (s.localPose) {
        row(pose, tr("Local X"), num(s.localPose->x, 2, QStringLiteral("m")));
        row(pose, tr("Local Y"), num(s.localPose->y, 2, QStringLiteral("m")));
    }
    if (s.velocity) {
        row(pose, tr("Speed"), num(s.velocity->vx, 2, QStringLiteral("m/s")));
        row(pose, tr("Yaw rate"), num(s.velocity->yawRate, 2, QStringLiteral("rad/s")));
    }

    auto* health = section(tr("Health"));
    if (s.health) {
        static const char* names[] = {"NONE", "INFO", "WARNING", "ERROR", "FAILURE"};
        row(health, tr("Summary"), QString::fromLatin1(names[std::min<int>(s.health->severity, 4)]));
        for (auto [node, sev] : s.health->nodes)
            row(health, tr("Node %1").arg(node), QString::fromLatin1(names[std::min<int>(sev, 4)]));
    } else {
        row(health, tr("Summary"), tr("unknown"));
    }

    auto* services = section(tr("Services"));
    auto* sub = row(services, tr("Subsystem %1").arg(s.subsystem), s.callSign);
    sub->setExpanded(true);
    for (const JausNodeServices& n : s.services) {
        auto* node = row(sub, tr("Node %1").arg(n.node), QString());
        node->setExpanded(true);
        for (const JausComponentServices& c : n.components) {
            auto* comp = row(node, QStringLiteral("[%1.%2.%3]").arg(s.subsystem).arg(n.node).arg(c.component),
                             QString());
            comp->setExpanded(true);
            for (const JausService& r : c.services)
                row(comp, r.uri, QStringLiteral("v%1.%2").arg(r.major).arg(r.minor));
        }
    }
}

// Mode, state, lights, odometer and the comms-lost service, as the vehicle reports them.
void VehicleDetailsWidget::addPlatformServices(QTreeWidgetItem* parent, const JausPlatformServices& p) {
    auto row = [parent](const QString& k, const QString& v) { new QTreeWidgetItem(parent, {k, v}); };
    auto value = [](const JausOfferedService& s, const std::optional<int>& v, QString (*name)(int)) {
        return !s.offered ? tr("not offered") : v ? name(*v) : tr("not reported yet");
    };
    row(tr("Platform mode"), value(p.modeService, p.mode, &JausPlatformText::modeName));
    row(tr("Platform state"), value(p.stateService, p.state, &JausPlatformText::stateName));
    QStringList on;
    for (JausLight l : kJausLights)
        if (p.lightOn(l))
            on << JausPlatformText::lightName(l);
    row(tr("Lights"), !p.illuminationService.offered ? tr("not offered")
                      : !p.lights                    ? tr("not reported yet")
                      : on.isEmpty()                 ? tr("all off")
                                                     : on.join(QStringLiteral(", ")));
    auto metres = [](const std::optional<quint32>& m) {
        return m ? tr("%1 m").arg(*m) : tr("not reported yet");
    };
    row(tr("Odometer"), p.odometryService.offered ? metres(p.odometerM) : tr("not offered"));
    row(tr("Trip"), p.odometryService.offered ? metres(p.tripM) : tr("not offered"));
    row(tr("Comms-lost policy service"),
        p.commsLostService.offered
            ? QStringLiteral("%1 v%2").arg(p.commsLostService.uri, p.commsLostService.versionText())
            : tr("not offered"));
}

} // namespace ocu
