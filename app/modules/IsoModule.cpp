// The ISO 23725 module of the console (the FMS side): the IsoBridge over the FMS stack, whose AHS map is the
// site map, the "ISO 23725" link indicator, and the console's own position sent to the AHS as one of the
// FMS's machines when the site configuration names it (own_position.fms_machine_id).
#include "app/ProtocolModule.h"
#include "app/modules/IsoProduction.h"

#include "models/FleetContext.h"
#include "models/OwnPosition.h"
#include "models/ProductionModel.h"
#include "models/bridges/IsoBridge.h"

namespace ocu {

namespace {

class IsoModule final : public ProtocolModule {
public:
    QString displayName() const override { return QStringLiteral("ISO 23725"); }
    Protocol protocol() const override { return Protocol::Iso23725; }

    QString start(const ModuleStart& s) override {
        if (!s.config.iso23725)
            return {};
        m_bridge = new IsoBridge(*s.config.iso23725, s.frame, s.owner);
        attachProductionModel(m_bridge)->setSiteName(QString::fromStdString(s.config.name)); // issue 15 §4
        s.fleet->addBridge(m_bridge);
        return m_bridge->start();
    }
    void stop() override {
        if (m_bridge)
            m_bridge->stop();
    }
    FleetBridge* bridge() const override { return m_bridge; }

    void populate(const ModulePanels& ui) override {
        addProductionDock(ui.window, ui.fleet, m_bridge, QString::fromStdString(ui.config.name));
    }

    void attachOwnPosition(OwnPosition* own, const SiteConfig& config) override {
        if (!m_bridge || config.ownPosition.fmsMachineId.empty())
            return;
        const QString machine = QString::fromStdString(config.ownPosition.fmsMachineId);
        QObject::connect(
            own, &OwnPosition::fixChanged, m_bridge, [bridge = m_bridge, machine](const OwnFix& f) {
                if (f.valid)
                    bridge->setOwnPosition(machine, f.lat, f.lon, f.alt, f.headingDeg, f.speed * 3.6);
            });
    }

private:
    IsoBridge* m_bridge = nullptr;
};

} // namespace

std::unique_ptr<ProtocolModule> makeIsoModule() {
    return std::make_unique<IsoModule>();
}

} // namespace ocu
