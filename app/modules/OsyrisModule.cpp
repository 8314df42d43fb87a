// The OSYRIS module of the console: the OsyrisBridge over the OCU's OSYRIS station, whose pass counts are the
// pass-count layer of the 2D map, the 3D view and the pass-count panel, and the "OSYRIS" link indicator.
#include "app/ProtocolModule.h"

#include "models/FleetContext.h"
#include "models/bridges/OsyrisBridge.h"

namespace ocu {

namespace {

class OsyrisModule final : public ProtocolModule {
public:
    QString displayName() const override { return QStringLiteral("OSYRIS"); }
    Protocol protocol() const override { return Protocol::Osyris; }

    QString start(const ModuleStart& s) override {
        if (!s.config.osyris)
            return {};
        m_bridge = new OsyrisBridge(*s.config.osyris, s.frame, s.owner);
        m_bridge->setMessageTap(s.tap);
        s.fleet->addBridge(m_bridge);
        return m_bridge->start();
    }
    void stop() override {
        if (m_bridge)
            m_bridge->stop();
    }
    FleetBridge* bridge() const override { return m_bridge; }

private:
    OsyrisBridge* m_bridge = nullptr;
};

} // namespace

std::unique_ptr<ProtocolModule> makeOsyrisModule() {
    return std::make_unique<OsyrisModule>();
}

} // namespace ocu
