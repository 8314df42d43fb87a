#include "models/QtStrings.h"
#include "models/bridges/IsoBridge.h"

#include "protocols/common/OutcomeCollector.h"

#include <mutex>

namespace ocu {

using namespace iso23725;

// ---- GUI thread: commands ----

QString IsoBridge::linkOf(const QString& machineId) const {
    std::lock_guard lock(m_machineLinksMutex);
    return m_machineLinks.value(machineId);
}

QString IsoBridge::linkRefusal(const QString& link, const QString& what) const {
    std::optional<LinkStatus> st;
    {
        std::lock_guard lock(m_linkNowMutex);
        auto it = m_linkNow.find(QStringLiteral("iso23725:") + link);
        if (it != m_linkNow.end())
            st = *it;
    }
    if (st && st->state == ocu::LinkState::Up)
        return {};
    const QString why = st && !st->detail.isEmpty() ? QStringLiteral(" (%1)").arg(st->detail) : QString();
    return st && st->state == ocu::LinkState::Down
               ? tr("%1 refused: ISO 23725 link %2 is down%3; nothing sent").arg(what, link, why)
               : tr("%1 refused: ISO 23725 link %2 is not connected%3; nothing sent").arg(what, link, why);
}

void IsoBridge::applyOrRefuse(const QString& link, bool apply, OutcomeCallback done) {
    const std::string target = IsoStack::linkTarget(link.toStdString());
    if (const QString why = linkRefusal(link, apply ? tr("all-stop Apply") : tr("all-stop Remove"));
        !why.isEmpty()) {
        done({TargetOutcome::refused(target, OutcomeReason::LinkDown, why.toStdString())});
        return;
    }
    if (!m_running) {
        done({TargetOutcome::refused(target, OutcomeReason::NotRunning,
                                     tr("the ISO 23725 stack is not running; nothing sent").toStdString())});
        return;
    }
    if (apply)
        m_stack->allStopApply(link.toStdString(), std::move(done));
    else
        m_stack->allStopRemove(link.toStdString(), std::move(done));
}

void IsoBridge::stopAll(OutcomeCallback done) {
    // All-stop Apply on every AHS link: a link that is down is a target not sent, with the reason.
    if (m_config.links.empty()) {
        done({refusal(QStringLiteral("iso23725"), OutcomeReason::UnknownTarget,
                      tr("no ISO 23725 link configured"))});
        return;
    }
    auto collector = OutcomeCollector::create(int(m_config.links.size()), std::move(done));
    for (const auto& l : m_config.links)
        applyOrRefuse(toQString(l.name), true, collector->part());
}

void IsoBridge::stopMachine(const QString& id, OutcomeCallback done) {
    const QString link = linkOf(id);
    if (link.isEmpty()) {
        done({refusal(id, OutcomeReason::UnknownTarget, tr("unknown ISO 23725 machine"))});
        return;
    }
    // ISO 23725 stops autonomous machines per AHS (all-stop); there is no single-machine stop message, so the
    // target is the AHS link.
    applyOrRefuse(link, true, std::move(done));
}

void IsoBridge::clearStop(const QString& id, OutcomeCallback done) {
    const QString link = linkOf(id);
    if (link.isEmpty()) {
        done({refusal(id, OutcomeReason::UnknownTarget, tr("unknown ISO 23725 machine"))});
        return;
    }
    applyOrRefuse(link, false, std::move(done));
}

bool IsoBridge::confirmsCommand(const QString& action) const {
    return action == QLatin1String("clear_stop") || action == QLatin1String("all_stop_remove");
}

bool IsoBridge::reportsConfirmed(const QString& action, const QString& target) const {
    if (!confirmsCommand(action))
        return false;
    for (const auto& l : m_config.links)
        if (toQString(IsoStack::linkTarget(l.name)) == target)
            return allStopState(toQString(l.name)) == AllStopState::Off;
    return false;
}

bool IsoBridge::reportsStopped(const QString& target) const {
    for (const auto& l : m_config.links)
        if (toQString(IsoStack::linkTarget(l.name)) == target)
            return allStopState(toQString(l.name)) == AllStopState::On;
    return false;
}

QString IsoBridge::commandLink(const QString& link, const QString& id) const {
    QString out = link;
    if (out.isEmpty() && !id.isEmpty())
        out = linkOf(id);
    if (out.isEmpty() && m_config.links.size() == 1)
        out = toQString(m_config.links.front().name);
    return out;
}

bool IsoBridge::refuseLink(const QString& what, const QString& link, const QString& shown,
                           OutcomeCallback& done) const {
    if (!linkNames().contains(link)) {
        done({refusal(link.isEmpty() ? QStringLiteral("iso23725") : link, OutcomeReason::UnknownTarget,
                      tr("%1: unknown ISO 23725 link \"%2\"").arg(what, link))});
        return true;
    }
    // Never queued while the link is down (§2.1 rule 1): refused here, nothing posted.
    if (const QString why = linkRefusal(link, what); !why.isEmpty()) {
        done({refusal(shown, OutcomeReason::LinkDown, why)});
        return true;
    }
    if (!m_running) {
        done({refusal(shown, OutcomeReason::NotRunning,
                      tr("the ISO 23725 stack is not running; nothing sent"))});
        return true;
    }
    return false;
}

void IsoBridge::truckCommand(
    const QString& what, const QString& id, OutcomeCallback done,
    const std::function<void(const std::string&, const std::string&, OutcomeCallback)>& send) {
    const QString link = commandLink({}, id);
    if (!linkNames().contains(link)) {
        done({refusal(link.isEmpty() ? QStringLiteral("iso23725") : link, OutcomeReason::UnknownTarget,
                      tr("%1: unknown ISO 23725 link \"%2\"").arg(what, link))});
        return;
    }
    const QString prefix = protocolPrefix(Protocol::Iso23725);
    if (!id.startsWith(prefix)) {
        done({refusal(id, OutcomeReason::UnknownTarget,
                      tr("%1: \"id\" must name an ISO 23725 machine").arg(what))});
        return;
    }
    if (refuseLink(what, link, id, done))
        return;
    // The stack reports the outcome: sent only when the socket took the frame.
    send(link.toStdString(), id.mid(prefix.size()).toStdString(), std::move(done));
}

void IsoBridge::command(const OperatorCommand& command, OutcomeCallback done) {
    const QString what = commandName(command);
    // All-stop and the map fetch name the link as their target.
    auto onLink = [&](const QString& linkArg, const QString& id, bool refuseFirst,
                      const std::function<void(const QString&)>& send) {
        const QString link = commandLink(linkArg, id);
        if (!linkNames().contains(link)) {
            done({refusal(link.isEmpty() ? QStringLiteral("iso23725") : link, OutcomeReason::UnknownTarget,
                          tr("%1: unknown ISO 23725 link \"%2\"").arg(what, link))});
            return;
        }
        if (refuseFirst && refuseLink(what, link, toQString(IsoStack::linkTarget(link.toStdString())), done))
            return;
        send(link);
    };
    std::visit(
        Overloaded{
            [&](const AllStopApply& c) {
                onLink(c.link, c.id, false,
                       [&](const QString& l) { applyOrRefuse(l, true, std::move(done)); });
            },
            [&](const AllStopRemove& c) {
                onLink(c.link, c.id, false,
                       [&](const QString& l) { applyOrRefuse(l, false, std::move(done)); });
            },
            [&](const FetchMap& c) {
                onLink(c.link, c.id, true,
                       [&](const QString& l) { m_stack->fetchMap(l.toStdString(), std::move(done)); });
            },
            [&](const ResetAssignment& c) {
                truckCommand(what, c.id, std::move(done),
                             [this](const std::string& l, const std::string& truck, OutcomeCallback d) {
                                 m_stack->resetAssignment(l, truck, std::move(d));
                             });
            },
            [&](const Assign& c) {
                if (c.tasks.isEmpty())
                    return done({refusal(c.id, OutcomeReason::InvalidArgument,
                                         tr("assign refused: %1; nothing sent").arg(tr("no task given")))});
                truckCommand(what, c.id, std::move(done),
                             [this, tasks = c.tasks](const std::string& l, const std::string& truck,
                                                     OutcomeCallback d) {
                                 m_stack->requestAssignment(l, truck, toAssignmentItems(tasks), std::move(d));
                             });
            },
            [&](const auto&) { FleetBridge::command(command, std::move(done)); },
        },
        command);
}

} // namespace ocu
