// The JSON-lines export of a recording: every change of the fleet picture and every other record, in time
// order.
#include "models/recording/Recording.h"

#include "models/MachineJson.h"
#include "models/recording/RecordingQuery.h"

#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPair>
#include <QVector>

#include <algorithm>

namespace ocu::recording {

bool Recording::exportJsonLines(QIODevice* out, qint64 from, qint64 to, QString* error) const {
    if (!out || !out->isWritable()) {
        if (error)
            *error = QCoreApplication::translate("Recording", "the output is not writable");
        return false;
    }
    // Merge the tables in time order: machine changes stream; the rest is small and loaded whole.
    QVector<QPair<qint64, QJsonObject>> other;
    for (const RecordedEvent& e : events(from - 1, to)) {
        QJsonObject o{{QStringLiteral("type"), QStringLiteral("event")},
                      {QStringLiteral("time"), isoTime(e.event.timeMs)},
                      {QStringLiteral("severity"), toText(e.event.severity)},
                      {QStringLiteral("kind"), toText(e.event.kind)},
                      {QStringLiteral("machine"), e.event.machineId},
                      {QStringLiteral("source"), e.event.source},
                      {QStringLiteral("text"), e.event.text},
                      {QStringLiteral("requires_ack"), e.event.requiresAck}};
        other.push_back({e.t, o});
    }
    for (const RecordedAck& a : acks(from - 1, to))
        other.push_back({a.t, QJsonObject{{QStringLiteral("type"), QStringLiteral("ack")},
                                          {QStringLiteral("key"), a.key},
                                          {QStringLiteral("by"), a.by}}});
    for (const RecordedCommand& c : commands(from - 1, to)) {
        QJsonObject o = QJsonDocument::fromJson(c.audit.toUtf8()).object();
        o[QStringLiteral("type")] = QStringLiteral("command");
        other.push_back({c.t, o});
    }
    for (const RecordedLink& l : links(from - 1, to))
        other.push_back({l.t, QJsonObject{{QStringLiteral("type"), QStringLiteral("link")},
                                          {QStringLiteral("protocol"), l.protocol},
                                          {QStringLiteral("link"), l.link},
                                          {QStringLiteral("state"), toText(l.state)},
                                          {QStringLiteral("age_ms"), double(l.dataAgeMs)},
                                          {QStringLiteral("detail"), l.detail}}});
    for (const RecordedDetail& d : details(QString(), from - 1, to)) {
        const QJsonDocument doc = QJsonDocument::fromJson(d.data);
        other.push_back(
            {d.t, QJsonObject{{QStringLiteral("type"), QStringLiteral("detail")},
                              {QStringLiteral("machine"), d.machine},
                              {QStringLiteral("kind"), d.kind},
                              {QStringLiteral("data"),
                               doc.isObject() ? QJsonValue(doc.object())
                                              : QJsonValue(QString::fromLatin1(d.data.toBase64()))}}});
    }
    {
        const QHash<std::uint32_t, MessageChannel> channels = messageChannels();
        messages(from, to, [&](const RecordedMessage& m) {
            other.push_back({m.t, messageJson(m, channels.value(m.channel))});
            return true;
        });
    }
    std::stable_sort(other.begin(), other.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    int next = 0;
    bool ok = true;
    auto write = [&](qint64 t, QJsonObject o) {
        o[QStringLiteral("t")] = double(t);
        ok = ok && out->write(QJsonDocument(o).toJson(QJsonDocument::Compact) + '\n') > 0;
    };
    changes(from - 1, to, [&](const StateChange& c) {
        while (next < other.size() && other[next].first <= c.t) {
            write(other[next].first, other[next].second);
            ++next;
        }
        write(c.t, c.removed ? QJsonObject{{QStringLiteral("type"), QStringLiteral("machine_removed")},
                                           {QStringLiteral("id"), c.state.id}}
                             : machineStateJson(c.state));
        return ok;
    });
    for (; next < other.size(); ++next)
        write(other[next].first, other[next].second);
    if (!ok && error)
        *error = QCoreApplication::translate("Recording", "write failed: %1").arg(out->errorString());
    return ok;
}

} // namespace ocu::recording
