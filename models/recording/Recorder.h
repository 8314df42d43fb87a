#pragma once
// The flight recorder (docs/recording.md): everything the console's models received - every
// machine state as delivered to the fleet model, every removal, every link change, every event and alarm,
// every acknowledgement, every operator command with its result and targets (the CommandGate's audit) and
// the site map - into one SQLite file per run.
//
// Threads: record*() may be called from any thread and only append to a bounded in-memory queue (items over
// the capacity are dropped and counted: the console is never slowed down by its recorder). A writer thread
// of its own wakes every flushIntervalMs, encodes what is queued and commits it in one transaction (WAL,
// synchronous=NORMAL: a killed process loses at most what was queued since the last commit, and the file
// opens cleanly - SQLite's WAL recovery). Every keyframeIntervalMs it also writes a keyframe (the full state
// of every machine) so a replay can seek anywhere quickly.
#include "models/FleetEvent.h"
#include "models/MachineState.h"
#include "models/ModelClock.h"
#include "models/SiteMapData.h"
#include "models/recording/Retention.h"

#include <QObject>
#include <QPointer>
#include <QRectF>
#include <QSize>
#include <QString>
#include <QStringList>
#include <QVector>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

class QTimer;

namespace ocu {

class MessageTap;
class PassCountLayer;
class FleetContext;
class FleetBridge;
struct LinkStatus;

namespace recording {

struct RecorderOptions {
    QString path;               // the SQLite file of this run (created; an existing file is refused)
    int queueCapacity = 200000; // items waiting for the writer; beyond: dropped and counted
    int flushIntervalMs = 200;  // the writer commits at least this often
    int keyframeIntervalMs = 10000;
    qint64 maxFileBytes = 0; // 0 = unlimited; beyond it the oldest machine data of this file is deleted
    // Retention while the run lasts (record.max_total_mb / max_age_days): every retentionIntervalMs of
    // recording time the writer applies applyRetention() to retentionDir, keeping this run's file, so a long
    // run cannot fill the disk with the folder's older runs. Empty dir = only at start (the caller's job).
    QString retentionDir;
    qint64 maxTotalBytes = 0;
    double maxAgeDays = 0;
    int retentionIntervalMs = 60000;
    // A writer that falls behind is told to the operator at most this often (with the count of dropped
    // records).
    int dropReportIntervalMs = 5000;
    bool raw = false; // record.raw: raw frames (recordRaw); off by default
    // record.messages: every decoded inbound message (the tap's onDecoded). Off by default: the replay is
    // driven by the machine states alone, and the messages cost several times what the states cost
    // (docs/recording.md, "What replay needs").
    bool messages = false;
    // Writes the previous format (schema 3: fixed-width headers, exact Delta records, zlib) instead of
    // schema 4: the benchmark's figures before schema 4 and the old-schema fixtures of the tests.
    bool legacySchema3 = false;
    int zstdLevel = 6; // schema 4's state chunks, keyframes and message chunks
    QString siteName;
    double originLat = 0, originLon = 0, originAlt = 0; // the site frame, for replay's map
    // Record times: the models' clock, so a state's data age is the one the fleet model saw (null: the
    // system clock).
    std::shared_ptr<const ModelClock> clock;
};

// An acknowledgement names its alarm by ocu::alarmKey (models/FleetEvent.h), the key AlarmModel and the
// consoles share.

class Recorder : public QObject {
    Q_OBJECT
public:
    explicit Recorder(QObject* parent = nullptr);
    ~Recorder() override; // stop()

    // Creates the file and starts the writer thread; returns an empty string or what went wrong.
    QString start(const RecorderOptions& options);
    // Writes what is queued, the end time, checkpoints the WAL and ends the writer thread.
    void stop();
    bool running() const { return m_running; }
    QString path() const { return m_options.path; }

    // GUI thread: records the context's models - fleet changes and removals, events and acknowledgements,
    // the gate's audit, and the links of every bridge (added now or later).
    void attach(FleetContext* ctx);

    // ---- any thread: queue only ----
    void recordStates(const QVector<MachineState>& states);
    void recordRemoval(const QString& id);
    void recordEvent(const FleetEvent& event);
    void recordAck(const QString& key, const QString& by, qint64 atMs);
    // One operator command: the gate's audit line (JSON: time, origin, action, target, ok, targets, message).
    void recordCommand(const QString& auditJson);
    void recordLink(const QString& protocol, const LinkStatus& status);
    void recordSiteMap(const SiteMapData& map);
    // A protocol's own record about a machine (FleetBridge::publishDetail, e.g. a UGV's mission), kept as it
    // is for the protocol's replay.
    void recordDetail(const QString& machineId, const QString& kind, const QByteArray& data);
    // record.raw: one raw frame/datagram as received on `link` (ignored when raw is off).
    void recordRaw(const QString& link, const QByteArray& frame);
    // The stacks' tap: every decoded inbound message with its receive time, protocol, link,
    // peer and type, and with record.raw every raw frame. Its calls only pack the message into one buffer and
    // queue it (io threads never wait for the writer); valid while the recorder lives.
    MessageTap* messageTap() const;

    // GUI thread: records the pass-count layer (OSYRIS): the whole grid now, then after each
    // passCountsChanged() (connect FleetBridge::passCountChanged) its changed cells, at most once a second.
    // The layer must outlive the recorder's run (or be unwatched with nullptr).
    void watchPassCounts(const PassCountLayer* layer);
    void passCountsChanged();
    void recordPassCountsNow();

    // Blocks until everything queued before the call is committed (tests, benchmarks, shutdown).
    void flush();

    struct Stats {
        quint64 queued = 0;  // accepted into the queue
        quint64 dropped = 0; // refused: queue full
        quint64 written = 0; // committed
        quint64 commits = 0;
        quint64 stateBytes = 0;    // machine-state chunk bytes as stored (compressed)
        quint64 stateRawBytes = 0; // the same before compression
        quint64 keyframeBytes = 0; // keyframe blobs as stored
        quint64 messages = 0;      // inbound messages (and raw frames) committed
        quint64 messageBytes = 0;  // their encoded chunk bytes
        quint64 writerCpuNs = 0;   // CPU time of the writer thread
    };
    Stats stats() const;
    // The older recordings the run's retention deleted so far (file names).
    QStringList deletedByRetention() const;

private:
    struct Item;
    struct Writer;
    bool push(Item&& item);
    // The writer thread (RecorderWriter.cpp): commits what is queued every flushIntervalMs until stopped.
    void run();
    void commit(const std::vector<Item>& batch);
    void retainDuringRun(qint64 t);
    qint64 now() const;

    RecorderOptions m_options;
    std::unique_ptr<Writer> m_writer;
    std::thread m_thread;
    mutable std::mutex m_mutex;
    std::condition_variable m_cv;
    std::condition_variable m_flushedCv;
    std::vector<Item> m_queue;
    quint64 m_pushedSeq = 0;  // items accepted so far (incl. those already taken by the writer)
    quint64 m_writtenSeq = 0; // items committed
    bool m_stopRequested = false;
    bool m_flushRequested = false;
    std::atomic<bool> m_running{false};
    std::atomic<quint64> m_dropped{0};
    std::atomic<quint64> m_commits{0};
    std::atomic<quint64> m_stateBytes{0};
    std::atomic<quint64> m_stateRawBytes{0};
    std::atomic<quint64> m_keyframeBytes{0};
    std::atomic<quint64> m_writerCpuNs{0};
    std::atomic<qint64> m_lastT{0};
    QPointer<FleetContext> m_ctx;
    class Tap;
    std::unique_ptr<Tap> m_tap;
    std::atomic<quint64> m_messages{0};
    std::atomic<quint64> m_messageBytes{0};
    QStringList m_retentionDeleted; // m_mutex
    quint64 m_droppedReported = 0;  // GUI thread: drops already told to the operator
    // GUI thread: the watched pass-count layer, the revision and grid last recorded.
    const PassCountLayer* m_passLayer = nullptr;
    quint64 m_passRevision = 0;
    QRectF m_passGrid;
    QSize m_passSize;
    QTimer* m_passTimer = nullptr;
};

} // namespace recording
} // namespace ocu
