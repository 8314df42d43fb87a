#pragma once
// Ribbon store: per machine, slot-indexed positions with their properties. Kept in memory
// and, when a file is given, in SQLite (one file per site, WAL): rows are written inside a transaction
// that commit() closes, so a crash loses nothing that was committed. Thread-safe (one mutex), so the GUI
// may read while the station's io thread writes.
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
    // path empty or ":memory:" = memory only. Errors name the file and SQLite's message.
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

private:
    RibbonStore() = default;
    void beginIfNeeded();

    mutable std::mutex m_mutex;
    std::map<std::uint8_t, std::map<std::uint32_t, PositionRecord>> m_ribbons;
    std::map<std::uint8_t, IntervalSet> m_held;
    std::string m_path;
    sqlite3* m_db = nullptr;
    sqlite3_stmt* m_insert = nullptr;
    sqlite3_stmt* m_update = nullptr;
    bool m_inTransaction = false;
};

} // namespace ocu::osyris
