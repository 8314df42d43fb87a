#pragma once
// STOP ALL, per-machine stop and stop release across every registered bridge (issue 6 §6).
// Stopping never asks; releasing needs a confirmation token obtained from requestClearToken() (the GUI's
// hold-to-confirm button, or the headless "confirm": true), valid once, for one machine, for a short time.
// Every action is audited: an AlarmModel entry (kind Audit) and, when configured, one JSON line appended
// to the audit log file. The stop state shown everywhere is what the machines report, not what we asked.
#include "models/FleetBridge.h"

#include <QHash>
#include <QJsonObject>
#include <QObject>
#include <QPointer>
#include <QVector>

namespace ocu {

class AlarmModel;

class CommandGate : public QObject {
    Q_OBJECT
public:
    explicit CommandGate(AlarmModel* alarms = nullptr, QObject* parent = nullptr);

    void addBridge(FleetBridge* bridge);
    QVector<FleetBridge*> bridges() const;
    FleetBridge* bridgeFor(const QString& machineId) const;

    // Append-only audit log (JSON lines); empty = none.
    void setAuditLogPath(const QString& path) { m_auditPath = path; }
    QString auditLogPath() const { return m_auditPath; }
    void setTokenLifetimeMs(qint64 ms) { m_tokenLifetimeMs = ms; }

    // Fans out to every bridge; ok when every bridge accepted. `origin` is "gui", "headless", "shortcut"...
    CommandResult stopAll(const QString& origin = QStringLiteral("gui"));
    CommandResult stopMachine(const QString& id, const QString& origin = QStringLiteral("gui"));

    // Release: first obtain a token (after the operator's deliberate confirmation), then clear.
    QString requestClearToken(const QString& id);
    CommandResult clearStop(const QString& id, const QString& token,
                            const QString& origin = QStringLiteral("gui"));

    // Protocol-specific commands routed to the bridge owning args["id"] (request_control, release_control,
    // drive, ...), or, without an id, to the bridge of args["protocol"] (e.g. {"protocol":"jaus"} for
    // release_all); audited like the rest.
    CommandResult command(const QString& name, const QJsonObject& args,
                          const QString& origin = QStringLiteral("gui"));

signals:
    void stopAllIssued(const ocu::CommandResult& result);
    void audited(const QString& jsonLine);

private:
    void audit(const QString& origin, const QString& action, const QString& target,
               const CommandResult& result);

    QVector<QPointer<FleetBridge>> m_bridges;
    QPointer<AlarmModel> m_alarms;
    QString m_auditPath;
    qint64 m_tokenLifetimeMs = 10000;
    struct Token {
        QString id;
        qint64 expiresMs = 0;
    };
    QHash<QString, Token> m_tokens;
};

} // namespace ocu
