#include "app/CompactionSetup.h"

#include "app/HeadlessCommands.h"
#include "models/FleetBridge.h"
#include "models/bridges/OsyrisPassCountLayer.h"
#include "models/coverage/CompactionSession.h"
#include "widgets/SiteMapView.h"
#include "widgets/coverage/CompactionMapOverlay.h"
#include "widgets/coverage/CompactionPanel.h"

#include <QPointer>

#ifdef OCU_HAVE_OCU_VIEW3D
#include "widgets/view3d/RouteOverlay3D.h"
#include "widgets/view3d/Site3DView.h"
#endif

namespace ocu {

CompactionSession* startCompaction(const SiteConfig& config, const GeoFrame& frame,
                                   const OsyrisPassCountLayer* layer, QObject* parent,
                                   QStringList* problems) {
    auto* s = new CompactionSession(config.compaction, frame, parent);
    s->setSiteName(QString::fromStdString(config.name));
#ifdef OCU_SITE_HAVE_OSYRIS
    if (config.osyris) {
        s->setWorksiteOrigin({config.osyris->originLat, config.osyris->originLon, config.osyris->originAlt});
        QStringList names;
        for (const auto& [idx, name] : config.osyris->machineNames)
            names << QString::fromStdString(name);
        s->setMachines(names);
    }
#endif
    if (layer)
        s->setSnapshotSource([layer] { return layer->snapshot(); });
    // The built-in simulated site paves the shipped design's road.
    QString design = QString::fromStdString(config.compaction.design);
    if (design.isEmpty() && config.simulation.enabled && config.simulation.osyrisRollers > 0)
        design = QStringLiteral(":/designs/paving-job.xml");
    if (!design.isEmpty()) {
        const QString e = s->loadDesign(design);
        if (!e.isEmpty() && problems)
            *problems << QObject::tr("Compaction design not loaded: %1").arg(e);
    }
    return s;
}

void registerCompactionHeadless(HeadlessCommands& table, CompactionSession* session) {
    if (!session)
        return;
    QPointer<CompactionSession> s(session);
    table.addLocal(
        QStringLiteral("coverage_report"),
        [s](const QJsonObject& cmd) {
            return s ? s->reportCommand(cmd)
                     : QJsonObject{
                           {QStringLiteral("ok"), false},
                           {QStringLiteral("message"), QStringLiteral("the compaction job has ended")}};
        },
        HeadlessCommands::always); // writes the job's proof of compaction: the permission table decides who
}

void watchCompactionCounts(CompactionSession* session, QObject* fleetBridge) {
    if (auto* b = qobject_cast<FleetBridge*>(fleetBridge); b && session)
        QObject::connect(b, &FleetBridge::passCountChanged, session, &CompactionSession::countsChanged);
}

QWidget* buildCompactionPanel(CompactionSession* session, SiteMapView* map) {
    return new CompactionPanel(session, new CompactionMapOverlay(map, session));
}

void attachCompaction3D(CompactionSession* session, QWidget* site3DView) {
#ifdef OCU_HAVE_OCU_VIEW3D
    auto* view = qobject_cast<Site3DView*>(site3DView);
    if (!session || !view)
        return;
    // One line overlay per polyline, rebuilt when the design or the areas change.
    auto* holder = new QObject(view);
    auto rebuild = [session, view, holder] {
        for (QObject* c : holder->children())
            delete c;
        const auto& g = session->mapGeometry();
        auto add = [&](QPolygonF line, bool closed, double r, double gr, double b, float w) {
            if (line.size() < 2)
                return;
            if (closed)
                line << line.first();
            auto* o = new RouteOverlay3D(view);
            o->setParent(holder);
            o->setStyle(r, gr, b, w);
            o->setPath(QVector<QPointF>(line.begin(), line.end()));
        };
        for (const QPolygonF& c : g.centreLines)
            add(c, false, 0.88, 0.44, 0.0, 4);
        for (const QPolygonF& b : g.boundaries)
            add(b, true, 0.25, 0.25, 0.25, 2);
        for (const auto& a : g.areas)
            add(a.second, true, 0.69, 0.0, 0.43, 3); // the 2D map's area colour
    };
    QObject::connect(session, &CompactionSession::changed, holder, rebuild);
    rebuild();
#else
    (void)session;
    (void)site3DView;
#endif
}

} // namespace ocu
