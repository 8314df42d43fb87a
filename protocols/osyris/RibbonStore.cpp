#include "protocols/osyris/RibbonStore.h"

#include "protocols/common/Log.h"

#include <sqlite3.h>

#include <algorithm>

namespace ocu::osyris {

namespace {

Bytes encodeProps(const std::vector<PosProp>& props) {
    Bytes b;
    ByteWriter w(b);
    for (auto& p : props) {
        w.u32(p.value);
        w.u32(p.id);
    }
    return b;
}

std::vector<PosProp> decodeProps(ByteSpan s) {
    std::vector<PosProp> out;
    ByteReader r(s);
    while (r.remaining() >= kPosPropSize) {
        PosProp p;
        p.value = r.u32();
        p.id = r.u32();
        out.push_back(p);
    }
    return out;
}

bool exec(sqlite3* db, const char* sql, std::string& err) {
    char* msg = nullptr;
    if (sqlite3_exec(db, sql, nullptr, nullptr, &msg) != SQLITE_OK) {
        err = msg ? msg : "unknown error";
        sqlite3_free(msg);
        return false;
    }
    return true;
}

} // namespace

std::unique_ptr<RibbonStore> RibbonStore::inMemory() {
    return std::unique_ptr<RibbonStore>(new RibbonStore());
}

bool RibbonStore::initDb(const std::string& path, bool temporary, std::string& err) {
    if (sqlite3_open_v2(path.c_str(), &m_db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX,
                        nullptr) != SQLITE_OK) {
        err = m_db ? sqlite3_errmsg(m_db) : "cannot open";
        return false;
    }
    sqlite3_busy_timeout(m_db, 2000);
    // A site file: WAL + synchronous=FULL, a committed transaction survives an application or OS crash.
    // The temporary database only spills memory: nothing to survive.
    const char* pragmas = temporary ? "PRAGMA journal_mode=OFF; PRAGMA synchronous=OFF;"
                                    : "PRAGMA journal_mode=WAL; PRAGMA synchronous=FULL;";
    if (!exec(m_db, pragmas, err) ||
        !exec(m_db,
              "CREATE TABLE IF NOT EXISTS ribbon_pos(idx INTEGER NOT NULL, slot INTEGER NOT NULL, pos BLOB "
              "NOT NULL,"
              " props BLOB, PRIMARY KEY(idx, slot)) WITHOUT ROWID;",
              err))
        return false;
    auto prepare = [&](const char* sql, sqlite3_stmt** st) {
        if (sqlite3_prepare_v2(m_db, sql, -1, st, nullptr) == SQLITE_OK)
            return true;
        err = sqlite3_errmsg(m_db);
        return false;
    };
    return prepare("INSERT OR IGNORE INTO ribbon_pos(idx, slot, pos, props) VALUES(?,?,?,?)", &m_insert) &&
           prepare("UPDATE ribbon_pos SET props=? WHERE idx=? AND slot=?", &m_update) &&
           prepare("SELECT slot, pos, props FROM ribbon_pos WHERE idx=? AND slot=?", &m_selectOne) &&
           prepare("SELECT slot, pos, props FROM ribbon_pos WHERE idx=? AND slot>=? ORDER BY slot",
                   &m_selectFrom);
}

Result<std::unique_ptr<RibbonStore>> RibbonStore::open(const std::string& path) {
    auto store = inMemory();
    if (path == ":memory:")
        return store;
    store->m_path = path;
    auto fail = [&](const std::string& what) -> Result<std::unique_ptr<RibbonStore>> {
        std::string msg = "ribbon store " + (path.empty() ? std::string("(temporary)") : path) + ": " + what;
        return makeError(msg);
    };
    std::string err;
    if (!store->initDb(path, path.empty(), err))
        return fail(err);
    if (path.empty())
        return store;
    // Which slots the file holds, and the newest positions of each machine into memory.
    sqlite3_stmt* sel = nullptr;
    if (sqlite3_prepare_v2(store->m_db, "SELECT idx, slot, length(pos) FROM ribbon_pos", -1, &sel, nullptr) !=
        SQLITE_OK)
        return fail(sqlite3_errmsg(store->m_db));
    std::uint64_t bad = 0;
    while (sqlite3_step(sel) == SQLITE_ROW) {
        int idx = sqlite3_column_int(sel, 0);
        if (idx < 0 || idx >= kIdxNobody || sqlite3_column_int(sel, 2) != static_cast<int>(kPosBodySize)) {
            ++bad;
            continue;
        }
        store->m_held[static_cast<std::uint8_t>(idx)].insert(
            static_cast<std::uint32_t>(sqlite3_column_int64(sel, 1)));
    }
    sqlite3_finalize(sel);
    if (bad)
        logWarning("osyris", "ribbon store " + path + ": skipped " + std::to_string(bad) + " malformed rows");
    for (auto& [idx, held] : store->m_held) {
        if (held.empty())
            continue;
        const std::uint32_t top = held.max();
        const std::uint32_t from = top >= store->m_hotSlots ? top - std::uint32_t(store->m_hotSlots) + 1 : 0;
        auto& rib = store->m_ribbons[idx];
        bool stopped = false;
        for (const SlotRange& r : held.intersect(from, top))
            store->readConsecutive(
                idx, r.from, std::uint64_t(r.to) + 1,
                [&](const PositionRecord& rec) {
                    rib.emplace(rec.pos.slot, rec);
                    return true;
                },
                stopped);
    }
    return store;
}

void RibbonStore::setHotSlots(std::size_t slots) {
    std::lock_guard lock(m_mutex);
    m_hotSlots = std::max<std::size_t>(16, slots);
}

std::size_t RibbonStore::hotSlots() const {
    std::lock_guard lock(m_mutex);
    return m_hotSlots;
}

std::uint64_t RibbonStore::cachedCount() const {
    std::lock_guard lock(m_mutex);
    std::uint64_t n = 0;
    for (auto& [i, r] : m_ribbons)
        n += r.size();
    return n;
}

void RibbonStore::evict(std::map<std::uint32_t, PositionRecord>& ribbon) {
    // Only with SQLite behind: what leaves memory is read back from there.
    if (!m_db)
        return;
    while (ribbon.size() > m_hotSlots)
        ribbon.erase(ribbon.begin());
}

namespace {

std::optional<PositionRecord> rowRecord(sqlite3_stmt* st) {
    auto* blob = static_cast<const std::uint8_t*>(sqlite3_column_blob(st, 1));
    const int n = sqlite3_column_bytes(st, 1);
    if (!blob || n != static_cast<int>(kPosBodySize))
        return std::nullopt;
    ByteReader r(ByteSpan(blob, static_cast<std::size_t>(n)));
    PositionRecord rec;
    rec.pos = decodePosBody(r);
    if (auto* pb = static_cast<const std::uint8_t*>(sqlite3_column_blob(st, 2)))
        rec.props = decodeProps(ByteSpan(pb, static_cast<std::size_t>(sqlite3_column_bytes(st, 2))));
    return rec;
}

} // namespace

std::optional<PositionRecord> RibbonStore::readRow(std::uint8_t idx, std::uint32_t slot) const {
    if (!m_db)
        return std::nullopt;
    sqlite3_bind_int(m_selectOne, 1, idx);
    sqlite3_bind_int64(m_selectOne, 2, slot);
    std::optional<PositionRecord> out;
    if (sqlite3_step(m_selectOne) == SQLITE_ROW)
        out = rowRecord(m_selectOne);
    sqlite3_reset(m_selectOne);
    return out;
}

std::uint32_t RibbonStore::readConsecutive(std::uint8_t idx, std::uint32_t slot, std::uint64_t end,
                                           const std::function<bool(const PositionRecord&)>& fn,
                                           bool& stopped) const {
    stopped = false;
    if (!m_db)
        return slot;
    sqlite3_bind_int(m_selectFrom, 1, idx);
    sqlite3_bind_int64(m_selectFrom, 2, slot);
    std::uint64_t next = slot;
    while (next < end && sqlite3_step(m_selectFrom) == SQLITE_ROW) {
        if (static_cast<std::uint64_t>(sqlite3_column_int64(m_selectFrom, 0)) != next)
            break;
        auto rec = rowRecord(m_selectFrom);
        if (!rec)
            break;
        if (!fn(*rec)) {
            stopped = true;
            break;
        }
        ++next;
    }
    sqlite3_reset(m_selectFrom);
    return static_cast<std::uint32_t>(next);
}

RibbonStore::~RibbonStore() {
    if (m_db) {
        commit();
        sqlite3_finalize(m_insert);
        sqlite3_finalize(m_update);
        sqlite3_finalize(m_selectOne);
        sqlite3_finalize(m_selectFrom);
        sqlite3_close(m_db);
    }
}

void RibbonStore::beginIfNeeded() {
    if (!m_db || m_inTransaction)
        return;
    std::string err;
    if (exec(m_db, "BEGIN", err))
        m_inTransaction = true;
    else
        logWarning("osyris", "ribbon store " + m_path + ": BEGIN failed: " + err);
}

void RibbonStore::commit() {
    std::lock_guard lock(m_mutex);
    if (!m_db || !m_inTransaction)
        return;
    std::string err;
    if (!exec(m_db, "COMMIT", err))
        logWarning("osyris", "ribbon store " + m_path + ": COMMIT failed: " + err);
    m_inTransaction = false;
}

bool RibbonStore::put(std::uint8_t idx, const PositionRecord& rec) {
    std::lock_guard lock(m_mutex);
    IntervalSet& held = m_held[idx];
    if (held.contains(rec.pos.slot))
        return false;
    held.insert(rec.pos.slot);
    auto& rib = m_ribbons[idx];
    rib.emplace(rec.pos.slot, rec);
    evict(rib);
    if (m_db) {
        beginIfNeeded();
        Bytes body;
        ByteWriter w(body);
        encodePosBody(w, rec.pos);
        Bytes props = encodeProps(rec.props);
        sqlite3_bind_int(m_insert, 1, idx);
        sqlite3_bind_int64(m_insert, 2, rec.pos.slot);
        sqlite3_bind_blob(m_insert, 3, body.data(), static_cast<int>(body.size()), SQLITE_TRANSIENT);
        if (props.empty())
            sqlite3_bind_null(m_insert, 4);
        else
            sqlite3_bind_blob(m_insert, 4, props.data(), static_cast<int>(props.size()), SQLITE_TRANSIENT);
        if (sqlite3_step(m_insert) != SQLITE_DONE)
            logWarning("osyris", "ribbon store " + m_path + ": insert failed: " + sqlite3_errmsg(m_db));
        sqlite3_reset(m_insert);
    }
    return true;
}

bool RibbonStore::addProps(std::uint8_t idx, std::uint32_t slot, const std::vector<PosProp>& props) {
    std::lock_guard lock(m_mutex);
    auto h = m_held.find(idx);
    if (props.empty() || h == m_held.end() || !h->second.contains(slot))
        return false;
    auto& rib = m_ribbons[idx];
    if (auto it = rib.find(slot); it != rib.end()) {
        if (!it->second.props.empty())
            return false;
        it->second.props = props;
    } else {
        auto old = readRow(idx, slot); // left memory already: its row decides
        if (!old || !old->props.empty())
            return false;
    }
    if (m_db) {
        beginIfNeeded();
        Bytes b = encodeProps(props);
        sqlite3_bind_blob(m_update, 1, b.data(), static_cast<int>(b.size()), SQLITE_TRANSIENT);
        sqlite3_bind_int(m_update, 2, idx);
        sqlite3_bind_int64(m_update, 3, slot);
        if (sqlite3_step(m_update) != SQLITE_DONE)
            logWarning("osyris", "ribbon store " + m_path + ": update failed: " + sqlite3_errmsg(m_db));
        sqlite3_reset(m_update);
    }
    return true;
}

bool RibbonStore::has(std::uint8_t idx, std::uint32_t slot) const {
    std::lock_guard lock(m_mutex);
    auto h = m_held.find(idx);
    return h != m_held.end() && h->second.contains(slot);
}

std::optional<PositionRecord> RibbonStore::get(std::uint8_t idx, std::uint32_t slot) const {
    std::lock_guard lock(m_mutex);
    if (auto r = m_ribbons.find(idx); r != m_ribbons.end())
        if (auto it = r->second.find(slot); it != r->second.end())
            return it->second;
    auto h = m_held.find(idx);
    if (h == m_held.end() || !h->second.contains(slot))
        return std::nullopt;
    return readRow(idx, slot);
}

std::optional<PositionRecord> RibbonStore::newest(std::uint8_t idx) const {
    std::lock_guard lock(m_mutex);
    auto r = m_ribbons.find(idx);
    if (r == m_ribbons.end() || r->second.empty())
        return std::nullopt;
    return std::prev(r->second.end())->second;
}

IntervalSet RibbonStore::held(std::uint8_t idx) const {
    std::lock_guard lock(m_mutex);
    auto h = m_held.find(idx);
    return h == m_held.end() ? IntervalSet{} : h->second;
}

std::uint64_t RibbonStore::count(std::uint8_t idx) const {
    std::lock_guard lock(m_mutex);
    auto h = m_held.find(idx);
    return h == m_held.end() ? 0 : h->second.count();
}

std::uint64_t RibbonStore::totalCount() const {
    std::lock_guard lock(m_mutex);
    std::uint64_t n = 0;
    for (auto& [i, h] : m_held)
        n += h.count();
    return n;
}

std::vector<std::uint8_t> RibbonStore::machines() const {
    std::lock_guard lock(m_mutex);
    std::vector<std::uint8_t> out;
    for (auto& [i, h] : m_held)
        if (!h.empty())
            out.push_back(i);
    return out;
}

std::uint32_t RibbonStore::forEachConsecutive(std::uint8_t idx, std::uint32_t slot,
                                              const std::function<bool(const PositionRecord&)>& fn) const {
    std::lock_guard lock(m_mutex);
    auto h = m_held.find(idx);
    if (h == m_held.end())
        return slot;
    auto r = m_ribbons.find(idx);
    const std::map<std::uint32_t, PositionRecord>* rib = r == m_ribbons.end() ? nullptr : &r->second;
    for (;;) {
        if (!h->second.contains(slot))
            return slot;
        if (rib) {
            auto it = rib->find(slot);
            if (it != rib->end()) {
                while (it != rib->end() && it->first == slot) {
                    if (!fn(it->second))
                        return slot;
                    ++it;
                    ++slot;
                    if (slot == 0)
                        return slot; // wrapped: end of the slot space
                }
                continue;
            }
        }
        // Older than memory holds: from SQLite up to the first slot memory holds.
        const std::uint64_t end =
            rib && !rib->empty() && rib->begin()->first > slot ? rib->begin()->first : std::uint64_t(1) << 32;
        bool stopped = false;
        const std::uint32_t next = readConsecutive(idx, slot, end, fn, stopped);
        if (stopped || next == slot)
            return next;
        slot = next;
        if (slot == 0)
            return slot;
    }
}

} // namespace ocu::osyris
