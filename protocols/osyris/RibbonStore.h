#pragma once
// Ribbon store: per machine, slot-indexed positions with their properties, in SQLite (one file per site,
// WAL; rows are written inside a transaction that commit() closes, so a crash loses nothing that was
// committed). Without a file the rows go to a private temporary SQLite database (deleted when the store
// closes), so that a shift's ribbons live on disk, not in memory: memory holds which slots are held and
// only the newest hotSlots() positions of each machine; older ones are read back from SQLite when asked
// for (repairs, recounts). inMemory() keeps everything in memory (tests, benchmarks, fuzzing).
// Thread-safe (one mutex), so the GUI may read while the station's io thread writes.
#include "protocols/osyris/IntervalSet.h"
#include "protocols/osyris/OsyrisCodec.h"

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

struct sqlite3;
struct sqlite3_stmt;

namespace ocu::osyris {

struct PositionRecord {
    CmPos pos;
    std::vector<PosProp> props;
    bool operator==(const PositionRecord&) const = default;
};

class RibbonStore {
public:
    // How many of each machine's newest positions stay in memory when the store has SQLite behind it.
    static constexpr std::size_t kDefaultHotSlots = 8192;

    // path empty = a private temporary database; ":memory:" = memory only. Errors name the file and
    // SQLite's message.
    static Result<std::unique_ptr<RibbonStore>> open(const std::string& path);
    static std::unique_ptr<RibbonStore> inMemory();
    ~RibbonStore();
    RibbonStore(const RibbonStore&) = delete;
    RibbonStore& operator=(const RibbonStore&) = delete;

    // Returns false when the slot is already held (duplicates never overwrite: a slot is immutable).
    bool put(std::uint8_t idx, const PositionRecord& rec);
    // Adds properties to a held slot that has none yet (props may arrive in a later datagram).
    bool addProps(std::uint8_t idx, std::uint32_t slot, const std::vector<PosProp>& props);
    // Closes the open transaction (no-op in memory mode). Called once per Beat by the station.
    void commit();

    bool has(std::uint8_t idx, std::uint32_t slot) const;
    std::optional<PositionRecord> get(std::uint8_t idx, std::uint32_t slot) const;
    std::optional<PositionRecord> newest(std::uint8_t idx) const;
    IntervalSet held(std::uint8_t idx) const;
    std::uint64_t count(std::uint8_t idx) const;
    std::uint64_t totalCount() const;
    std::vector<std::uint8_t> machines() const;
    // Calls fn for consecutive held slots starting at slot, while fn returns true. Returns the slot after
    // the last one visited.
    std::uint32_t forEachConsecutive(std::uint8_t idx, std::uint32_t slot,
                                     const std::function<bool(const PositionRecord&)>& fn) const;
    const std::string& path() const { return m_path; }

    // At least 16; applies from the next put (tests use a small window to read through SQLite).
    void setHotSlots(std::size_t slots);
    std::size_t hotSlots() const;
    // Positions held in memory now (diagnostics and tests: bounded by machines x hotSlots with SQLite).
    std::uint64_t cachedCount() const;

private:
    RibbonStore() = default;
    void beginIfNeeded();
    bool initDb(const std::string& path, bool temporary, std::string& err);
    void evict(std::map<std::uint32_t, PositionRecord>& ribbon);
    // From SQLite: one slot, or the consecutive slots from `slot` while fn returns true and below `end`.
    std::optional<PositionRecord> readRow(std::uint8_t idx, std::uint32_t slot) const;
    std::uint32_t readConsecutive(std::uint8_t idx, std::uint32_t slot, std::uint64_t end,
                                  const std::function<bool(const PositionRecord&)>& fn, bool& stopped) const;

    mutable std::mutex m_mutex;
    // The newest hotSlots positions of each machine (all of them in memory-only mode).
    std::map<std::uint8_t, std::map<std::uint32_t, PositionRecord>> m_ribbons;
    std::size_t m_hotSlots = kDefaultHotSlots;
    std::map<std::uint8_t, IntervalSet> m_held;
    std::string m_path;
    sqlite3* m_db = nullptr;
    sqlite3_stmt* m_insert = nullptr;
    sqlite3_stmt* m_update = nullptr;
    sqlite3_stmt* m_selectOne = nullptr;
    sqlite3_stmt* m_selectFrom = nullptr;
    bool m_inTransaction = false;
};

} // namespace ocu::osyris
