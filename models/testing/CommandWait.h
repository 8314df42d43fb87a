#pragma once
// Tests: wait (processing events) for the final result of an asynchronous command - a CommandGate command or
// a bridge command's outcomes. Returns a failure "no result" if nothing arrived within the timeout.
#include "models/CommandGate.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QThread>

#include <memory>
#include <mutex>
#include <optional>

namespace ocu::testing {

template <class Issue> CommandResult gateResult(Issue&& issue, int timeoutMs = 30000) {
    auto r = std::make_shared<std::optional<CommandResult>>();
    issue([r](const CommandResult& x) { *r = x; });
    QDeadlineTimer deadline(timeoutMs);
    while (!*r && !deadline.hasExpired())
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    return r->value_or(CommandResult::failure(QStringLiteral("no result")));
}

// For a bridge command: issue(done) with an OutcomeCallback; the outcomes may arrive on any thread.
template <class Issue> CommandResult bridgeResult(Issue&& issue, int timeoutMs = 30000) {
    struct Box {
        std::mutex m;
        std::optional<std::vector<TargetOutcome>> out;
    };
    auto box = std::make_shared<Box>();
    issue([box](std::vector<TargetOutcome> o) {
        std::lock_guard lock(box->m);
        box->out = std::move(o);
    });
    QDeadlineTimer deadline(timeoutMs);
    for (;;) {
        {
            std::lock_guard lock(box->m);
            if (box->out)
                return CommandResult::fromTargets(QVector<TargetOutcome>(box->out->begin(), box->out->end()));
        }
        if (deadline.hasExpired())
            return CommandResult::failure(QStringLiteral("no result"));
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        QThread::msleep(1);
    }
}

} // namespace ocu::testing
