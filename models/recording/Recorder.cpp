// The recorder's face to the console: starting and stopping a run, queueing what the models deliver (any
// thread), the models it watches, and the pass-count layer. The writer thread is RecorderWriter.cpp, the
// stacks' tap RecorderTap.cpp, the folder's retention Retention.cpp.
#include "models/recording/Recorder.h"

#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/FleetBridge.h"
#include "models/FleetContext.h"
#include "models/FleetModel.h"
#include "models/recording/PassCountLog.h"
#include "models/recording/RecordSchema.h"
#include "models/recording/RecorderTap.h"
#include "models/recording/RecorderWriter.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

#include <algorithm>

namespace ocu::recording {

Recorder::Recorder(QObject* parent) : QObject(parent), m_tap(std::make_unique<Tap>(*this)) {}

Recorder::~Recorder() {
    stop();
}

qint64 Recorder::now() const {
    return m_options.clock ? m_options.clock->nowMs() : systemModelClock()->nowMs();
}

QString Recorder::start(const RecorderOptions& options) {
    if (m_running)
        return tr("the recorder is already running");
    m_options = options;
    if (QFileInfo::exists(options.path))
        return tr("%1 exists already; a recording is never overwritten").arg(options.path);
    QDir().mkpath(QFileInfo(options.path).absolutePath());
    auto w = std::make_unique<Writer>();
    w->keyframeIntervalMs = std::max(100, options.keyframeIntervalMs);
    const qint64 t = now();
    if (const QString e = createRecordingFile(options, t, w->keyframeIntervalMs); !e.isEmpty())
        return e;
    if (const QString e = w->open(options); !e.isEmpty())
        return e;
    m_lastT = t;
    w->lastKeyframeT = t;
    w->lastRetentionT = t;
    m_writer = std::move(w);
    m_stopRequested = false;
    m_running = true;
    m_thread = std::thread([this] { run(); });
    return {};
}

void Recorder::stop() {
    if (!m_running)
        return;
    {
        std::lock_guard lk(m_mutex);
        m_stopRequested = true;
    }
    m_cv.notify_all();
    m_thread.join();
    m_writer.reset();
    m_running = false;
}

bool Recorder::push(Item&& item) {
    if (!m_running)
        return false;
    std::lock_guard lk(m_mutex);
    if (m_stopRequested || int(m_queue.size()) >= m_options.queueCapacity) {
        m_dropped.fetch_add(1, std::memory_order_relaxed);
        return false;
    }
    // Record times never go backwards (a stepped wall clock), so the file stays in time order.
    item.t = std::max(now(), m_lastT.load(std::memory_order_relaxed));
    m_lastT.store(item.t, std::memory_order_relaxed);
    m_queue.push_back(std::move(item));
    ++m_pushedSeq;
    return true;
}

void Recorder::recordStates(const QVector<MachineState>& states) {
    for (const MachineState& s : states) {
        Item it;
        it.kind = Item::State;
        it.state = s;
        push(std::move(it));
    }
}

void Recorder::recordRemoval(const QString& id) {
    Item it;
    it.kind = Item::Removed;
    it.a = id;
    push(std::move(it));
}

void Recorder::recordEvent(const FleetEvent& event) {
    Item it;
    it.kind = Item::Event;
    it.event = event;
    push(std::move(it));
}

void Recorder::recordAck(const QString& key, const QString& by, qint64 atMs) {
    Item it;
    it.kind = Item::Ack;
    it.a = key;
    it.b = by;
    it.x = atMs;
    push(std::move(it));
}

void Recorder::recordCommand(const QString& auditJson) {
    Item it;
    it.kind = Item::Command;
    it.a = auditJson;
    push(std::move(it));
}

void Recorder::recordLink(const QString& protocol, const LinkStatus& status) {
    Item it;
    it.kind = Item::Link;
    it.a = protocol;
    it.b = status.link;
    it.c = status.detail;
    it.i = int(status.state);
    it.x = status.dataAgeMs;
    push(std::move(it));
}

void Recorder::recordSiteMap(const SiteMapData& map) {
    Item it;
    it.kind = Item::SiteMap;
    it.blob = siteMapToJson(map);
    push(std::move(it));
}

void Recorder::recordDetail(const QString& machineId, const QString& kind, const QByteArray& data) {
    Item it;
    it.kind = Item::Detail;
    it.a = machineId;
    it.b = kind;
    it.blob = data;
    push(std::move(it));
}

void Recorder::flush() {
    if (!m_running)
        return;
    std::unique_lock lk(m_mutex);
    const quint64 target = m_pushedSeq;
    m_flushRequested = true;
    m_cv.notify_all();
    m_flushedCv.wait(lk, [&] { return m_writtenSeq >= target || !m_running; });
}

Recorder::Stats Recorder::stats() const {
    Stats s;
    {
        std::lock_guard lk(m_mutex);
        s.queued = m_pushedSeq;
        s.written = m_writtenSeq;
    }
    s.dropped = m_dropped.load();
    s.commits = m_commits.load();
    s.stateBytes = m_stateBytes.load();
    s.stateRawBytes = m_stateRawBytes.load();
    s.keyframeBytes = m_keyframeBytes.load();
    s.writerCpuNs = m_writerCpuNs.load();
    s.messages = m_messages.load();
    s.messageBytes = m_messageBytes.load();
    return s;
}

void Recorder::attach(FleetContext* ctx) {
    m_ctx = ctx;
    FleetModel* fleet = ctx->fleet();
    connect(fleet, &FleetModel::machinesChanged, this, [this, fleet](const QStringList& ids) {
        QVector<MachineState> out;
        out.reserve(ids.size());
        for (const QString& id : ids)
            if (const MachineState* m = fleet->machine(id))
                out.push_back(*m);
        recordStates(out);
    });
    connect(fleet, &FleetModel::machineRemoved, this, &Recorder::recordRemoval);
    connect(ctx->alarms(), &AlarmModel::eventAdded, this, &Recorder::recordEvent);
    connect(ctx->alarms(), &AlarmModel::alarmAcknowledged, this, &Recorder::recordAck);
    connect(ctx->gate(), &CommandGate::audited, this, &Recorder::recordCommand);
    auto watch = [this](FleetBridge* b) {
        const QString protocol = toText(b->protocol());
        connect(b, &FleetBridge::linkChanged, this,
                [this, protocol](const LinkStatus& s) { recordLink(protocol, s); });
        connect(b, &FleetBridge::detailRecorded, this, &Recorder::recordDetail);
        for (const LinkStatus& s : b->links())
            recordLink(protocol, s);
    };
    for (FleetBridge* b : ctx->bridges())
        watch(b);
    connect(ctx, &FleetContext::bridgeAdded, this, watch);
    // The staleness thresholds, so a replay greys out what the console greyed out.
    QJsonObject stale;
    for (Protocol p : {Protocol::Jaus, Protocol::Iso23725, Protocol::Osyris, Protocol::Other})
        stale[toText(p)] = double(fleet->staleAfterMs(p));
    Item it;
    it.kind = Item::Meta;
    it.a = QStringLiteral("stale_after_ms");
    it.c = QString::fromUtf8(QJsonDocument(stale).toJson(QJsonDocument::Compact));
    push(std::move(it));
    // What is already in the models when the recorder starts late.
    recordStates(fleet->machinesSnapshot());
    // A writer that falls behind drops (the io threads never wait for it): the operator hears of it, at most
    // once per dropReportIntervalMs (5 s), with the count.
    auto* dropWatch = new QTimer(this);
    connect(dropWatch, &QTimer::timeout, this, [this] {
        const quint64 dropped = m_dropped.load(std::memory_order_relaxed);
        if (dropped == m_droppedReported || !m_ctx)
            return;
        const quint64 n = dropped - m_droppedReported;
        m_droppedReported = dropped;
        m_ctx->alarms()->add(makeEvent(EventSeverity::Warning, EventKind::Info, {},
                                       tr("Flight recorder behind: %n record(s) dropped (%1 in all)", nullptr,
                                          int(std::min<quint64>(n, INT32_MAX)))
                                           .arg(dropped),
                                       QStringLiteral("recorder")));
    });
    dropWatch->start(std::max(50, m_options.dropReportIntervalMs));
}

void Recorder::watchPassCounts(const PassCountLayer* layer) {
    m_passLayer = layer;
    m_passRevision = 0;
    m_passSize = QSize();
    if (!m_passTimer) {
        m_passTimer = new QTimer(this);
        m_passTimer->setSingleShot(true);
        m_passTimer->setInterval(1000);
        connect(m_passTimer, &QTimer::timeout, this, &Recorder::recordPassCountsNow);
    }
    recordPassCountsNow();
}

void Recorder::passCountsChanged() {
    if (m_passLayer && m_passTimer && !m_passTimer->isActive())
        m_passTimer->start();
}

void Recorder::recordPassCountsNow() {
    const PassCountLayer* l = m_passLayer;
    if (!l || !m_running || (m_passRevision != 0 && l->revision() == m_passRevision))
        return;
    PassCountChange c;
    c.origin = l->origin();
    c.cellSize = l->cellSize();
    c.columns = l->columns();
    c.rows = l->rows();
    const QRectF grid(c.origin, QSizeF(c.cellSize, c.cellSize));
    const bool sameGrid = m_passRevision != 0 && grid == m_passGrid && m_passSize == QSize(c.columns, c.rows);
    const QRect all(0, 0, c.columns, c.rows);
    const QRect want = sameGrid ? l->changedCellsSince(m_passRevision).intersected(all) : all;
    const quint64 revision = l->revision();
    c.cells = want.isEmpty() ? QRect(0, 0, 0, 0) : l->countsIn(want, c.counts);
    if (c.counts.size() !=
        std::size_t(std::max(0, c.cells.width())) * std::size_t(std::max(0, c.cells.height())))
        c.cells = QRect(0, 0, 0, 0), c.counts.clear();
    m_passRevision = revision;
    m_passGrid = grid;
    m_passSize = QSize(c.columns, c.rows);
    Item it;
    it.kind = Item::PassCounts;
    it.blob = encodePassCounts(c);
    push(std::move(it));
}

QStringList Recorder::deletedByRetention() const {
    std::lock_guard lk(m_mutex);
    return m_retentionDeleted;
}

} // namespace ocu::recording
