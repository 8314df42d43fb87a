#include "app/HeadlessReplay.h"

#include "app/HeadlessMonitor.h"
#include "app/ProtocolModule.h"
#include "models/recording/ReplayController.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QIODevice>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>

namespace ocu {

HeadlessReplay::HeadlessReplay(recording::ReplayController* c, QIODevice* out, QObject* parent)
    : QObject(parent), m_controller(c), m_out(out),
      m_monitor(std::make_unique<HeadlessMonitor>(c->fleet(), c->alarms(), nullptr)) {
    m_monitor->setOutput(out);
    m_monitor->setRateLimitMs(0);
    // The modules' own records (a UGV's mission), in the machine lines and "list" as live.
    for (const auto& m : makeProtocolModules())
        m->registerHeadlessReplay({m_monitor->commands(), c, this});
    m_monitor->printAll();
    connect(c, &recording::ReplayController::positionChanged, this, [this](qint64 t) {
        if (t == m_lastStamp)
            return;
        m_lastStamp = t;
        m_out->write(
            QJsonDocument(
                QJsonObject{{QStringLiteral("type"), QStringLiteral("replay")},
                            {QStringLiteral("time"),
                             QDateTime::fromMSecsSinceEpoch(t, Qt::UTC).toString(Qt::ISODateWithMs)}})
                .toJson(QJsonDocument::Compact) +
            '\n');
    });
}

HeadlessReplay::~HeadlessReplay() = default;

void HeadlessReplay::runToEnd(qint64 stepMs, const std::function<bool()>& stop) {
    for (qint64 t = m_controller->position(); t < m_controller->endMs();) {
        t = std::min(m_controller->endMs(), t + std::max<qint64>(1, stepMs));
        m_controller->moveTo(t);
        QCoreApplication::processEvents();
        if (stop && stop())
            break;
    }
    QCoreApplication::processEvents();
}

} // namespace ocu
