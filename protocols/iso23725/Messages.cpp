#include "protocols/iso23725/Messages.h"
#include "protocols/iso23725/PositionFastPath.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <random>
#include <unordered_map>

namespace ocu::iso23725 {

using nlohmann::json;

const InferredRules& defaultInferredRules() {
    static const InferredRules rules;
    return rules;
}

namespace enums {
const std::vector<std::string_view> equipmentType = {
    "HaulTruck",   "Shovel",           "Excavator", "Loader",          "LightVehicle", "WaterCart", "Grader",
    "FuelTruck",   "LubeTruck",        "Dozer",     "RubberTireDozer", "Drill",        "Crusher",   "Scraper",
    "BellyDumper", "EmergencyVehicle", "Ambulance", "Dragline",        "SurfaceMiner", "Bus",       "Train",
    "Trailer"};
const std::vector<std::string_view> actor = {"AHS", "FMS"};
const std::vector<std::string_view> actionRequest = {"Apply", "Remove"};
const std::vector<std::string_view> actionResponse = {"Accepted", "Rejected"};
const std::vector<std::string_view> actionStatus = {"On", "Off"};
const std::vector<std::string_view> autonomyMode = {
    "Manual",  "Autonomous",    "TransitionToAutonomous", "TransitionToManual",
    "AllStop", "EmergencyStop", "RemoteControl"};
const std::vector<std::string_view> haulTask = {"Load", "Offload", "Fuel", "Park", "Wait"};
const std::vector<std::string_view> productionState = {"Off",     "Driving", "Spotting", "Loading", "Hauling",
                                                       "Dumping", "Queued",  "Stopped",  "Parked"};
const std::vector<std::string_view> wayType = {"Road", "Area"};
const std::vector<std::string_view> defaultTask = {"Load", "Offload", "Supply", "Park",
                                                   "Wait", "Drive",   "Fuel"};
const std::vector<std::string_view> severity = {"Info", "Warning", "Error"};
const std::vector<std::string_view> assignmentStatus = {"Pending", "Active", "Completed", "Cancelled"};
} // namespace enums

// ---------------------------------------------------------------- time, GUID helpers

namespace {

bool digits(std::string_view s, std::size_t pos, std::size_t n, int& out) {
    if (pos + n > s.size())
        return false;
    int v = 0;
    for (std::size_t i = pos; i < pos + n; ++i) {
        if (s[i] < '0' || s[i] > '9')
            return false;
        v = v * 10 + (s[i] - '0');
    }
    out = v;
    return true;
}

std::optional<std::int64_t> parseStrict(std::string_view s) {
    int y, mo, d, h, mi, sec;
    if (!digits(s, 0, 4, y) || s.size() < 19 || s[4] != '-' || !digits(s, 5, 2, mo) || s[7] != '-' ||
        !digits(s, 8, 2, d) || (s[10] != 'T' && s[10] != 't') || !digits(s, 11, 2, h) || s[13] != ':' ||
        !digits(s, 14, 2, mi) || s[16] != ':' || !digits(s, 17, 2, sec))
        return std::nullopt;
    if (mo < 1 || mo > 12 || d < 1 || d > 31 || h > 23 || mi > 59 || sec > 60)
        return std::nullopt;
    std::size_t pos = 19;
    std::int64_t ms = 0;
    if (pos < s.size() && s[pos] == '.') {
        ++pos;
        std::size_t start = pos;
        int scale = 100;
        while (pos < s.size() && s[pos] >= '0' && s[pos] <= '9') {
            ms += (s[pos] - '0') * scale;
            scale /= 10;
            ++pos;
        }
        if (pos == start)
            return std::nullopt;
    }
    std::int64_t offsetMin = 0;
    if (pos < s.size() && (s[pos] == 'Z' || s[pos] == 'z')) {
        ++pos;
    } else if (pos < s.size() && (s[pos] == '+' || s[pos] == '-')) {
        int oh, om;
        if (!digits(s, pos + 1, 2, oh) || pos + 3 >= s.size() || s[pos + 3] != ':' ||
            !digits(s, pos + 4, 2, om))
            return std::nullopt;
        offsetMin = (s[pos] == '+' ? 1 : -1) * (oh * 60 + om);
        pos += 6;
    } else {
        return std::nullopt; // UTC designator required (§3 Time)
    }
    if (pos != s.size())
        return std::nullopt;
    using namespace std::chrono;
    year_month_day ymd{year(y), month(unsigned(mo)), day(unsigned(d))};
    if (!ymd.ok())
        return std::nullopt;
    auto days = sys_days(ymd).time_since_epoch().count();
    return ((days * 86400LL + h * 3600LL + mi * 60LL + sec) - offsetMin * 60) * 1000 + ms;
}

} // namespace

std::optional<std::int64_t> parseTimestamp(std::string_view text, bool repair, bool* repaired) {
    if (repaired)
        *repaired = false;
    if (auto v = parseStrict(text))
        return v;
    if (!repair || text.size() < 19)
        return std::nullopt;
    // §9 repairs: extra dots inside the fraction ("10.43.511Z"), a space for 'T', a missing 'Z'.
    std::string s(text);
    if (s[10] == ' ')
        s[10] = 'T';
    if (s.size() > 20 && s[19] == '.') {
        std::string frac;
        std::size_t i = 20;
        for (; i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.'); ++i)
            if (s[i] != '.')
                frac += s[i];
        s = s.substr(0, 20) + frac + s.substr(i);
    }
    if (s.back() != 'Z' && s.back() != 'z' && s.find('+', 19) == std::string::npos &&
        s.find('-', 19) == std::string::npos)
        s += 'Z';
    auto v = parseStrict(s);
    if (v && repaired)
        *repaired = true;
    return v;
}

std::string formatTimestamp(std::int64_t unixMs) {
    std::int64_t secs = unixMs >= 0 ? unixMs / 1000 : (unixMs - 999) / 1000;
    int ms = static_cast<int>(unixMs - secs * 1000);
    std::time_t t = static_cast<std::time_t>(secs);
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[80];
    std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", tm.tm_year + 1900, tm.tm_mon + 1,
                  tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec, ms);
    return buf;
}

Timestamp makeTimestamp(std::int64_t unixMs) {
    return Timestamp{formatTimestamp(unixMs), unixMs};
}

bool isGuid(std::string_view s) {
    if (s.size() != 36)
        return false;
    for (std::size_t i = 0; i < 36; ++i) {
        char c = s[i];
        if (i == 8 || i == 13 || i == 18 || i == 23) {
            if (c != '-')
                return false;
        } else if (!std::isxdigit(static_cast<unsigned char>(c))) {
            return false;
        }
    }
    return true;
}

Guid newGuid() {
    thread_local std::mt19937_64 rng{
        std::random_device{}() ^
        static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count())};
    std::uint64_t a = rng(), b = rng();
    a = (a & 0xffffffffffff0fffULL) | 0x0000000000004000ULL;
    b = (b & 0x3fffffffffffffffULL) | 0x8000000000000000ULL;
    char buf[40];
    std::snprintf(buf, sizeof buf, "%08x-%04x-%04x-%04x-%012llx", unsigned(a >> 32),
                  unsigned((a >> 16) & 0xffff), unsigned(a & 0xffff), unsigned(b >> 48),
                  static_cast<unsigned long long>(b & 0xffffffffffffULL));
    return buf;
}

// ---------------------------------------------------------------- decoding

namespace {

struct DecodeError {
    std::string message;
};

const char* typeName(const json& v) {
    switch (v.type()) {
    case json::value_t::null:
        return "null";
    case json::value_t::boolean:
        return "boolean";
    case json::value_t::string:
        return "string";
    case json::value_t::array:
        return "array";
    case json::value_t::object:
        return "object";
    case json::value_t::binary:
        return "binary";
    case json::value_t::discarded:
        return "invalid";
    default:
        return "number";
    }
}

std::string joinSet(const std::vector<std::string_view>& set) {
    std::string s;
    for (auto v : set) {
        if (!s.empty())
            s += ", ";
        s += v;
    }
    return s;
}

struct Ctx {
    const InferredRules& rules;
    std::vector<std::string>& warnings;
};

// Reads one JSON object, naming "<path>.<Member>" in every error, and remembers which keys it consumed.
class Obj {
public:
    Obj(const json& j, std::string path, Ctx& ctx) : m_j(j), m_path(std::move(path)), m_ctx(ctx) {
        if (!j.is_object())
            fail("", std::string("expected an object, got ") + typeName(j));
    }
    // Hot path (one per message): a literal path needs no allocation.
    Obj(const json& j, const char* path, Ctx& ctx) : m_j(j), m_literal(path), m_ctx(ctx) {
        if (!j.is_object())
            fail("", std::string("expected an object, got ") + typeName(j));
    }

    std::string path() const { return m_literal ? std::string(m_literal) : m_path; }

    [[noreturn]] void fail(std::string_view key, const std::string& what) const {
        throw DecodeError{key.empty() ? path() + ": " + what : path() + "." + std::string(key) + ": " + what};
    }

    // Finds key (or an accepted alias); nullptr when absent.
    const json* find(std::string_view key, std::string_view alias = {}) {
        see(key);
        if (const json* v = lookup(key)) {
            ++m_found;
            return v;
        }
        if (!alias.empty()) {
            see(alias);
            if (m_ctx.rules.acceptAliases) {
                if (const json* a = lookup(alias)) {
                    ++m_found;
                    m_ctx.warnings.push_back(path() + ": alias '" + std::string(alias) + "' accepted for '" +
                                             std::string(key) + "'");
                    return a;
                }
            }
        }
        return nullptr;
    }
    const json& need(std::string_view key, std::string_view alias = {}) {
        const json* v = find(key, alias);
        if (!v)
            fail(key, "required member missing");
        return *v;
    }

    std::string str(std::string_view key) { return asString(key, need(key)); }
    std::optional<std::string> optStr(std::string_view key) {
        const json* v = find(key);
        if (!v || v->is_null())
            return std::nullopt;
        return asString(key, *v);
    }
    std::string asString(std::string_view key, const json& v) const {
        if (!v.is_string())
            fail(key, std::string("expected a string, got ") + typeName(v));
        return v.get<std::string>();
    }

    Guid guid(std::string_view key, std::string_view alias = {}) { return asGuid(key, need(key, alias)); }
    std::optional<Guid> nullableGuid(std::string_view key, bool required) {
        const json* v = required ? &need(key) : find(key);
        if (!v || v->is_null())
            return std::nullopt;
        return asGuid(key, *v);
    }
    Guid asGuid(std::string_view key, const json& v) const {
        if (!v.is_string())
            fail(key, std::string("expected a GUID string, got ") + typeName(v));
        const auto& s = v.get_ref<const std::string&>();
        if (!isGuid(s))
            fail(key, "malformed GUID '" + s + "'");
        Guid g = s;
        std::transform(g.begin(), g.end(), g.begin(), [](unsigned char c) { return std::tolower(c); });
        return g;
    }

    bool boolean(std::string_view key) {
        const json& v = need(key);
        if (!v.is_boolean())
            fail(key, std::string("expected a boolean, got ") + typeName(v));
        return v.get<bool>();
    }
    std::optional<bool> optBool(std::string_view key) {
        const json* v = find(key);
        if (!v || v->is_null())
            return std::nullopt;
        if (!v->is_boolean())
            fail(key, std::string("expected a boolean, got ") + typeName(*v));
        return v->get<bool>();
    }

    // Numbers: null = unavailable (§4.2.3) when nullable; numeric strings tolerated per InferredRules.
    std::optional<double> number(std::string_view key, bool required, bool nullable,
                                 std::string_view alias = {}) {
        const json* v = required ? &need(key, alias) : find(key, alias);
        if (!v)
            return std::nullopt;
        return asNumber(key, *v, nullable);
    }
    std::optional<double> asNumber(std::string_view key, const json& v, bool nullable) const {
        if (v.is_number())
            return v.get<double>();
        if (v.is_null()) {
            if (!nullable)
                fail(key, "must not be null");
            return std::nullopt;
        }
        if (v.is_string() && m_ctx.rules.acceptNumericStrings) {
            const auto& s = v.get_ref<const std::string&>();
            double d = 0;
            auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), d);
            if (ec == std::errc() && p == s.data() + s.size() && std::isfinite(d)) {
                m_ctx.warnings.push_back(path() + "." + std::string(key) + ": number sent as a string");
                return d;
            }
        }
        fail(key, std::string("expected a number, got ") + typeName(v));
    }
    std::optional<std::int64_t> integer(std::string_view key, bool required, bool nullable) {
        const json* v = required ? &need(key) : find(key);
        if (!v)
            return std::nullopt;
        return asInteger(key, *v, nullable);
    }
    std::optional<std::int64_t> asInteger(std::string_view key, const json& v, bool nullable) const {
        if (v.is_number_integer())
            return v.get<std::int64_t>();
        if (v.is_number_float() && !m_ctx.rules.acceptNumericStrings)
            fail(key, "expected an integer, got a decimal");
        auto d = asNumber(key, v, nullable);
        if (!d)
            return std::nullopt;
        if (std::fabs(*d) > 9.0e18)
            fail(key, "integer out of range");
        return static_cast<std::int64_t>(std::llround(*d));
    }
    std::int64_t reqInt(std::string_view key) { return *integer(key, true, false); }

    std::string enumeration(std::string_view key, const std::vector<std::string_view>& set) {
        return asEnum(key, need(key), set);
    }
    std::optional<std::string> optEnum(std::string_view key, const std::vector<std::string_view>& set) {
        const json* v = find(key);
        if (!v || v->is_null())
            return std::nullopt;
        return asEnum(key, *v, set);
    }
    std::string asEnum(std::string_view key, const json& v, const std::vector<std::string_view>& set) const {
        if (!v.is_string())
            fail(key, std::string("expected an enumeration string, got ") + typeName(v));
        const auto& s = v.get_ref<const std::string&>();
        for (auto e : set)
            if (e == s)
                return s;
        if (m_ctx.rules.caseInsensitiveEnums)
            for (auto e : set)
                if (e.size() == s.size() && std::equal(e.begin(), e.end(), s.begin(), [](char a, char b) {
                        return std::tolower(static_cast<unsigned char>(a)) ==
                               std::tolower(static_cast<unsigned char>(b));
                    }))
                    return std::string(e);
        fail(key, "'" + s + "' is not one of " + joinSet(set));
    }

    Timestamp timestamp(std::string_view key) { return asTimestamp(key, need(key)); }
    std::optional<Timestamp> optTimestamp(std::string_view key) {
        const json* v = find(key);
        if (!v || v->is_null())
            return std::nullopt;
        return asTimestamp(key, *v);
    }
    Timestamp asTimestamp(std::string_view key, const json& v) const {
        if (!v.is_string())
            fail(key, std::string("expected an ISO 8601 timestamp string, got ") + typeName(v));
        Timestamp t{v.get<std::string>(), std::nullopt};
        bool repaired = false;
        t.unixMs = parseTimestamp(t.text, m_ctx.rules.repairTimestamps, &repaired);
        if (!t.unixMs)
            fail(key, "malformed timestamp '" + t.text + "'");
        if (repaired)
            m_ctx.warnings.push_back(path() + "." + std::string(key) + ": malformed timestamp '" + t.text +
                                     "' repaired");
        return t;
    }

    // An array that must not be null (ISO: "can be empty but not null").
    const json& array(std::string_view key, std::string_view alias = {}) {
        const json& v = need(key, alias);
        return asArray(key, v);
    }
    const json* optArray(std::string_view key, std::string_view alias = {}) {
        const json* v = find(key, alias);
        if (!v)
            return nullptr;
        return &asArray(key, *v);
    }
    const json& asArray(std::string_view key, const json& v) const {
        if (!v.is_array())
            fail(key, v.is_null() ? std::string("must be an array (may be empty, not null)")
                                  : std::string("expected an array, got ") + typeName(v));
        return v;
    }
    std::string item(std::string_view key, std::size_t i) const {
        return path() + "." + std::string(key) + "[" + std::to_string(i) + "]";
    }

    // Unknown members are kept (returned) and reported, never fatal (§4.2).
    json extras() const {
        json out; // null unless there are unknown members (no allocation on the hot path)
        if (m_j.size() == m_found)
            return out; // every key present was consumed (looked-up names are distinct)
        for (auto it = m_j.begin(); it != m_j.end(); ++it) {
            if (seen(it.key()))
                continue;
            out[it.key()] = it.value();
            m_ctx.warnings.push_back(path() + ": unknown member '" + it.key() + "' kept");
        }
        return out;
    }

    // Hot messages: one pass over the object resolves these keys, instead of one map lookup per key.
    void prefetch(std::initializer_list<std::string_view> keys) {
        m_npk = 0;
        for (auto k : keys)
            if (m_npk < m_pk.size()) {
                m_pk[m_npk] = k;
                m_pv[m_npk++] = nullptr;
            }
        for (auto it = m_j.begin(); it != m_j.end(); ++it) {
            const std::string& key = it.key();
            for (std::size_t i = 0; i < m_npk; ++i)
                if (m_pk[i].size() == key.size() && m_pk[i] == key) {
                    m_pv[i] = &*it;
                    break;
                }
        }
    }

private:
    const json* lookup(std::string_view key) const {
        for (std::size_t i = 0; i < m_npk; ++i)
            if (m_pk[i] == key)
                return m_pv[i];
        auto it = m_j.find(key);
        return it == m_j.end() ? nullptr : &*it;
    }
    void see(std::string_view k) {
        if (m_nSeen < m_seen.size())
            m_seen[m_nSeen++] = k;
        else
            m_more.push_back(k);
    }
    bool seen(std::string_view k) const {
        for (std::size_t i = 0; i < m_nSeen; ++i)
            if (m_seen[i] == k)
                return true;
        return std::find(m_more.begin(), m_more.end(), k) != m_more.end();
    }

    const json& m_j;
    const char* m_literal = nullptr;
    std::string m_path;
    Ctx& m_ctx;
    std::array<std::string_view, 16> m_seen;
    std::size_t m_nSeen = 0;
    std::size_t m_found = 0;
    std::array<std::string_view, 16> m_pk;
    std::array<const json*, 16> m_pv{};
    std::size_t m_npk = 0;
    std::vector<std::string_view> m_more;
};

PoseFields readPose(Obj& o) {
    PoseFields p;
    // All pose numbers are shall members but may be null = unavailable (§4.2.3).
    p.heading = o.integer("Heading", true, true);
    if (p.heading && (*p.heading < 0 || *p.heading > 359))
        o.fail("Heading", "out of range 0-359: " + std::to_string(*p.heading));
    p.latitude = o.number("Latitude", true, true);
    if (p.latitude && (*p.latitude < -90 || *p.latitude > 90))
        o.fail("Latitude", "out of range -90..90");
    p.longitude = o.number("Longitude", true, true);
    if (p.longitude && (*p.longitude < -180 || *p.longitude > 180))
        o.fail("Longitude", "out of range -180..180");
    p.elevation = o.number("Elevation", true, true);
    p.latitudeAccuracy = o.number("LatitudeAccuracy", true, true);
    p.longitudeAccuracy = o.number("LongitudeAccuracy", true, true);
    p.elevationAccuracy = o.number("ElevationAccuracy", true, true, "HeightAccuracy");
    p.headingAccuracy = o.number("HeadingAccuracy", true, true);
    p.speed = o.integer("Speed", true, true);
    return p;
}

MachinePositionV1 readPosition(Obj& o, Ctx& ctx) {
    o.prefetch({"Timestamp", "Heading", "Latitude", "Longitude", "Elevation", "LatitudeAccuracy",
                "LongitudeAccuracy", "ElevationAccuracy", "HeightAccuracy", "HeadingAccuracy", "Speed",
                "Attachment", "AttachmentV1"});
    MachinePositionV1 m;
    m.timestamp = o.timestamp("Timestamp");
    m.pose = readPose(o);
    if (const json* a = o.optArray("Attachment", "AttachmentV1")) {
        m.attachment.emplace();
        for (std::size_t i = 0; i < a->size(); ++i) {
            Obj it((*a)[i], o.item("Attachment", i), ctx);
            AttachmentPose ap;
            ap.equipmentId = it.guid("EquipmentId", "EquipmentID");
            ap.pose = readPose(it);
            it.extras();
            m.attachment->push_back(std::move(ap));
        }
    }
    return m;
}

template <class F> auto eachItem(Obj& o, const json& arr, std::string_view key, Ctx& ctx, F&& f) {
    for (std::size_t i = 0; i < arr.size(); ++i) {
        Obj it(arr[i], o.item(key, i), ctx);
        f(it);
        it.extras();
    }
}

// An array-valued member (MachineDiagnosticV2, MapConnectivityV1, ...): each element read with f.
template <class F> void eachTop(const json& v, std::string_view name, Ctx& ctx, F&& f) {
    if (!v.is_array())
        throw DecodeError{std::string(name) + ": " +
                          (v.is_null() ? std::string("must be an array (may be empty, not null)")
                                       : std::string("expected an array, got ") + typeName(v))};
    for (std::size_t i = 0; i < v.size(); ++i) {
        Obj it(v[i], std::string(name) + "[" + std::to_string(i) + "]", ctx);
        f(it);
        it.extras();
    }
}

using Decoder = Body (*)(const json&, Ctx&, json& extra);

template <class T, class F> Body objectMember(const json& v, const char* name, Ctx& ctx, json& extra, F&& f) {
    Obj o(v, name, ctx);
    T t;
    f(o, t);
    extra = o.extras();
    return t;
}

Body decFleet(const json& v, Ctx& c, json& x) {
    return objectMember<FleetDefinitionV2>(v, "FleetDefinitionV2", c, x, [&](Obj& o, FleetDefinitionV2& m) {
        m.ahsId = o.guid("AHSId");
        const json& arr = o.array("Equipment");
        eachItem(o, arr, "Equipment", c, [&](Obj& it) {
            Equipment e;
            e.equipmentId = it.guid("EquipmentId", "EquipmentID");
            e.hid = it.str("HID");
            e.type = it.enumeration("Type", enums::equipmentType);
            e.oem = it.str("OEM");
            e.model = it.str("Model");
            e.autonomous = it.boolean("Autonomous");
            e.length = it.number("Length", true, true);
            e.width = it.number("Width", true, true);
            m.equipment.push_back(std::move(e));
        });
    });
}
Body decAllStopReq(const json& v, Ctx& c, json& x) {
    return objectMember<MachineAllStopRequestV1>(v, "MachineAllStopRequestV1", c, x, [](Obj& o, auto& m) {
        m.modeAllStop = o.enumeration("ModeAllStop", enums::actionRequest);
        m.modeAllStopId = o.guid("ModeAllStopId");
    });
}
Body decAllStopResp(const json& v, Ctx& c, json& x) {
    return objectMember<MachineAllStopResponseV1>(v, "MachineAllStopResponseV1", c, x, [](Obj& o, auto& m) {
        m.response = o.enumeration("Response", enums::actionResponse);
        m.modeAllStopId = o.guid("ModeAllStopId");
        m.detail = o.optStr("Detail");
    });
}
Body decAllStop(const json& v, Ctx& c, json& x) {
    return objectMember<MachineAllStopV1>(v, "MachineAllStopV1", c, x, [](Obj& o, auto& m) {
        m.modeAllStop = o.enumeration("ModeAllStop", enums::actionStatus);
        m.modeAllStopId = o.nullableGuid("ModeAllStopId", true);
    });
}
Body decPosition(const json& v, Ctx& c, json& x) {
    Obj o(v, "MachinePositionV1", c);
    MachinePositionV1 m = readPosition(o, c);
    x = o.extras();
    return m;
}
Body decHealth(const json& v, Ctx& c, json& x) {
    return objectMember<BasicMachineHealthV2>(v, "BasicMachineHealthV2", c, x, [&](Obj& o, auto& m) {
        m.fuelLevel = o.integer("FuelLevel", true, true);
        if (m.fuelLevel && (*m.fuelLevel < 0 || *m.fuelLevel > 100))
            o.fail("FuelLevel", "out of range 0-100: " + std::to_string(*m.fuelLevel));
        m.totalMachineHour = o.number("TotalMachineHour", false, true);
        m.totalEngineHour = o.number("TotalEngineHour", true, true);
        m.primeMoverTemp = o.integer("PrimeMoverTemp", false, true);
        if (const json* t = o.optArray("Tire")) {
            m.tire.emplace();
            eachItem(o, *t, "Tire", c, [&](Obj& it) {
                Tire tire;
                tire.tirePosition = it.str("TirePosition");
                tire.tirePressure = it.integer("TirePressure", true, true);
                tire.tireTemperature = it.integer("TireTemperature", true, true);
                m.tire->push_back(std::move(tire));
            });
        }
    });
}
Body decAutonomy(const json& v, Ctx& c, json& x) {
    return objectMember<MachineAutonomyModeV1>(v, "MachineAutonomyModeV1", c, x, [](Obj& o, auto& m) {
        m.autonomyMode = o.enumeration("AutonomyMode", enums::autonomyMode);
    });
}
Body decAvailability(const json& v, Ctx& c, json& x) {
    return objectMember<MachineDispatchAvailabilityV1>(
        v, "MachineDispatchAvailabilityV1", c, x, [](Obj& o, auto& m) {
            m.dispatchingCustodian = o.enumeration("DispatchingCustodian", enums::actor);
            m.impendingCustodian = o.optEnum("ImpendingCustodian", enums::actor);
            m.impendingTime = o.optTimestamp("ImpendingTime");
        });
}
Body decDiagnostic(const json& v, Ctx& c, json&) {
    MachineDiagnosticV2 m;
    eachTop(v, "MachineDiagnosticV2", c, [&](Obj& it) {
        m.entries.push_back(DiagnosticEntry{it.reqInt("ComponentId"), it.reqInt("FaultCode")});
    });
    return m;
}
Body decConnectivity(const json& v, Ctx& c, json&) {
    MapConnectivityV1 m;
    eachTop(v, "MapConnectivityV1", c, [&](Obj& it) {
        ConnectivityItem ci;
        ci.wayId = it.reqInt("WayId");
        ci.wayType = it.enumeration("WayType", enums::wayType);
        if (ci.wayType == "Road") {
            Obj rp(it.need("RoadProperty"), it.path() + ".RoadProperty", c);
            ci.roadLength = rp.number("Length", true, true);
            ci.roadName = rp.optStr("Name");
            rp.extras();
        } else {
            Obj ap(it.need("AreaProperty"), it.path() + ".AreaProperty", c);
            ci.areaDefaultTask = ap.enumeration("DefaultTask", enums::defaultTask);
            ci.areaName = ap.optStr("Name");
            ap.extras();
        }
        it.find(ci.wayType == "Road" ? "AreaProperty" : "RoadProperty"); // tolerated, not kept
        const json& conn = it.array("Connection");
        eachItem(it, conn, "Connection", c,
                 [&](Obj& w) { ci.connection.push_back(WayRef{w.reqInt("WayId")}); });
        m.items.push_back(std::move(ci));
    });
    return m;
}
Body decMapService(const json& v, Ctx& c, json& x) {
    return objectMember<MapServiceV1>(v, "MapServiceV1", c, x,
                                      [](Obj& o, auto& m) { m.api = o.reqInt("API"); });
}
Body decSummary(const json& v, Ctx& c, json& x) {
    return objectMember<MapSummaryV1>(v, "MapSummaryV1", c, x, [](Obj& o, auto& m) {
        m.timestamp = o.timestamp("Timestamp");
        m.changeSetMap = o.reqInt("ChangeSetMap");
        m.changeSetWay = o.reqInt("ChangeSetWay");
        m.uid = o.integer("uid", false, true);
        m.nodeCount = o.reqInt("NodeCount");
        m.wayCount = o.reqInt("WayCount");
        m.documentCount = o.reqInt("DocumentCount");
        if (m.documentCount < 0)
            o.fail("DocumentCount", "must not be negative");
    });
}
Body decMapCommand(const json& v, Ctx& c, json& x) {
    return objectMember<MapCommandV1>(v, "MapCommandV1", c, x, [](Obj& o, auto& m) {
        m.method = o.str("Method");
        std::string up = m.method;
        std::transform(up.begin(), up.end(), up.begin(), [](unsigned char ch) { return std::toupper(ch); });
        if (up != "GET") // the source says "Get", examples "GET": accept either case
            o.fail("Method", "'" + m.method + "' is not GET");
        m.method = up;
        m.scope = o.str("Scope");
    });
}
Body decInterfaceDiag(const json& v, Ctx& c, json& x) {
    return objectMember<InterfaceDiagnosticV1>(v, "InterfaceDiagnosticV1", c, x, [&](Obj& o, auto& m) {
        if (const json* a = o.optArray("Measurement"))
            eachItem(o, *a, "Measurement", c, [&](Obj& it) {
                m.measurement.push_back(
                    DiagMeasurement{it.str("Name"), it.number("Value", true, true), it.str("Unit")});
            });
        if (const json* a = o.optArray("Message"))
            eachItem(o, *a, "Message", c, [&](Obj& it) {
                DiagMessage d;
                d.severity = it.enumeration("Severity", enums::severity);
                d.code = it.str("Code");
                d.detail = it.optStr("Detail");
                d.refMember = it.optStr("RefMember");
                d.refTimestamp = it.optTimestamp("RefTimestamp");
                m.message.push_back(std::move(d));
            });
    });
}
Body decCycle(const json& v, Ctx& c, json& x) {
    return objectMember<HaulTruckProductionCycleV1>(
        v, "HaulTruckProductionCycleV1", c, x, [&](Obj& o, auto& m) {
            m.cycleId = o.guid("CycleId");
            m.assignmentId = o.nullableGuid("AssignmentId", false);
            m.loadWayId = o.reqInt("LoadWayId");
            m.dumpWayId = o.reqInt("DumpWayId");
            m.loaderEquipmentId = o.nullableGuid("LoaderEquipmentId", false);
            m.payloadWeight = o.integer("PayloadWeight", false, true);
            if (const json* a = o.optArray("StateTimes"))
                eachItem(o, *a, "StateTimes", c, [&](Obj& it) {
                    m.stateTimes.push_back(
                        StateTime{it.enumeration("ProductionState", enums::productionState),
                                  it.timestamp("Start"), it.number("Duration", true, true)});
                });
        });
}
Body decProdState(const json& v, Ctx& c, json& x) {
    return objectMember<HaulTruckProductionStateV2>(
        v, "HaulTruckProductionStateV2", c, x, [](Obj& o, auto& m) {
            m.assignmentId = o.nullableGuid("AssignmentId", true);
            m.wayId = o.integer("WayId", true, true);
            m.autonomyMode = o.enumeration("AutonomyMode", enums::autonomyMode);
            m.productionState = o.enumeration("ProductionState", enums::productionState);
        });
}
Body decSensor(const json& v, Ctx& c, json& x) {
    return objectMember<HaulTruckProductionStateSensorV1>(
        v, "HaulTruckProductionStateSensorV1", c, x, [](Obj& o, auto& m) {
            m.loaded = o.optBool("Loaded");
            m.bodyRaised = o.optBool("BodyRaised");
            m.parkBrake = o.optBool("ParkBrake");
            m.payloadWeight = o.integer("PayloadWeight", false, true);
            m.inLoadArea = o.optBool("InLoadArea");
            m.inDumpArea = o.optBool("InDumpArea");
        });
}
Body decPayload(const json& v, Ctx& c, json& x) {
    return objectMember<HaulTruckPayloadV1>(v, "HaulTruckPayloadV1", c, x, [](Obj& o, auto& m) {
        m.payloadWeight = o.integer("PayloadWeight", true, true);
        m.accuracy = o.number("Accuracy", false, true);
        if (const json* s = o.find("PayloadSourceId")) {
            if (s->is_string() && !isGuid(s->get_ref<const std::string&>()))
                o.fail("PayloadSourceId", "malformed GUID '" + s->get<std::string>() + "'");
            if (!s->is_string() && !s->is_number() && !s->is_null())
                o.fail("PayloadSourceId",
                       std::string("expected a GUID, a number or null, got ") + typeName(*s));
            m.payloadSourceId = *s;
        }
    });
}
Body decDump(const json& v, Ctx& c, json& x) {
    return objectMember<HaulTruckDumpV1>(v, "HaulTruckDumpV1", c, x, [](Obj& o, auto& m) {
        m.assignmentId = o.nullableGuid("AssignmentId", false);
        m.wayId = o.reqInt("WayId");
        m.dumpedWeight = o.integer("DumpedWeight", false, true);
        m.destinationSpotId = o.integer("DestinationSpotId", false, true);
        m.dumpEquipmentId = o.nullableGuid("DumpEquipmentId", false);
    });
}
Body decAssignReq(const json& v, Ctx& c, json&) {
    HaulTruckAssignmentRequestV2 m;
    eachTop(v, "HaulTruckAssignmentRequestV2", c, [&](Obj& it) {
        AssignmentItem a;
        a.assignmentId = it.guid("AssignmentId");
        a.task = it.enumeration("Task", enums::haulTask);
        a.destinationId = it.reqInt("DestinationId");
        a.destinationEquipmentId = it.nullableGuid("DestinationEquipmentId", false);
        a.destinationSpotId = it.integer("DestinationSpotId", false, true);
        if (a.destinationEquipmentId && a.destinationSpotId)
            it.fail("DestinationSpotId", "mutually exclusive with DestinationEquipmentId");
        if (const json* r = it.optArray("RouteV1")) {
            a.route.emplace();
            eachItem(it, *r, "RouteV1", c, [&](Obj& w) { a.route->push_back(WayRef{w.reqInt("WayId")}); });
        }
        m.items.push_back(std::move(a));
    });
    if (m.items.empty())
        throw DecodeError{"HaulTruckAssignmentRequestV2: must hold at least one assignment"};
    return m;
}
Body decAssignResp(const json& v, Ctx& c, json&) {
    HaulTruckAssignmentResponseV1 m;
    eachTop(v, "HaulTruckAssignmentResponseV1", c, [&](Obj& it) {
        m.items.push_back(AssignmentResponseItem{
            it.guid("AssignmentId"), it.enumeration("Response", enums::actionResponse), it.optStr("Detail")});
    });
    return m;
}
Body decReset(const json& v, Ctx& c, json& x) {
    return objectMember<HaulTruckAssignmentResetV1>(v, "HaulTruckAssignmentResetV1", c, x,
                                                    [](Obj& o, auto& m) { m.resetId = o.guid("ResetId"); });
}
Body decAssignment(const json& v, Ctx& c, json& x) {
    return objectMember<HaulTruckAssignmentV1>(v, "HaulTruckAssignmentV1", c, x, [](Obj& o, auto& m) {
        m.assignmentId = o.nullableGuid("AssignmentId", true);
        m.status = o.enumeration("Status", enums::assignmentStatus);
        m.task = o.optEnum("Task", enums::haulTask);
        m.destinationId = o.integer("DestinationId", false, true);
    });
}

struct MemberInfo {
    Decoder decode;
    bool perMachine; // header EquipmentId required (§4.1)
};

const std::unordered_map<std::string_view, MemberInfo>& decoders() {
    static const std::unordered_map<std::string_view, MemberInfo> m = {
        {"FleetDefinitionV2", {decFleet, false}},
        {"MachineAllStopRequestV1", {decAllStopReq, false}},
        {"MachineAllStopResponseV1", {decAllStopResp, false}},
        {"MachineAllStopV1", {decAllStop, false}},
        {"MachinePositionV1", {decPosition, true}},
        {"BasicMachineHealthV2", {decHealth, true}},
        {"MachineAutonomyModeV1", {decAutonomy, true}},
        {"MachineDispatchAvailabilityV1", {decAvailability, true}},
        {"MachineDiagnosticV2", {decDiagnostic, true}},
        {"MapConnectivityV1", {decConnectivity, false}},
        {"MapServiceV1", {decMapService, false}},
        {"MapSummaryV1", {decSummary, false}},
        {"MapCommandV1", {decMapCommand, false}},
        {"InterfaceDiagnosticV1", {decInterfaceDiag, false}},
        {"HaulTruckProductionCycleV1", {decCycle, true}},
        {"HaulTruckProductionStateV2", {decProdState, true}},
        {"HaulTruckProductionStateSensorV1", {decSensor, true}},
        {"HaulTruckPayloadV1", {decPayload, true}},
        {"HaulTruckDumpV1", {decDump, true}},
        {"HaulTruckAssignmentRequestV2", {decAssignReq, true}},
        {"HaulTruckAssignmentResponseV1", {decAssignResp, true}},
        {"HaulTruckAssignmentResetV1", {decReset, true}},
        {"HaulTruckAssignmentV1", {decAssignment, true}},
    };
    return m;
}

bool isHeaderKey(std::string_view k) {
    return k == "Protocol" || k == "Version" || k == "Timestamp" || k == "EquipmentId" || k == "EquipmentID";
}

} // namespace

Result<Envelope> decodeJson(const json& doc, const InferredRules& rules) {
    Envelope env;
    if (!doc.is_object())
        return makeError(std::string("message: expected a JSON object, got ") + typeName(doc));
    Ctx ctx{rules, env.warnings};
    try {
        Obj h(doc, "header", ctx);
        h.prefetch({"Protocol", "Version", "Timestamp", "EquipmentId", "EquipmentID"});
        env.header.protocol = h.str("Protocol");
        if (const json* v = h.find("Version")) {
            env.header.version = h.asInteger("Version", *v, false);
        } else if (rules.acceptMissingVersion) {
            env.header.version.reset();
            env.warnings.push_back("header.Version: required member missing (tolerated)");
        } else {
            h.fail("Version", "required member missing");
        }
        env.header.timestamp = h.timestamp("Timestamp");
        env.header.equipmentId = h.nullableGuid("EquipmentId", false);
        if (!env.header.equipmentId) {
            if (const json* v = h.find("EquipmentID"); v && rules.acceptAliases) {
                env.header.equipmentId = h.asGuid("EquipmentID", *v);
                env.warnings.push_back("header: alias 'EquipmentID' accepted for 'EquipmentId'");
            }
        }
    } catch (const DecodeError& e) {
        return makeError(e.message);
    }
    if (env.header.protocol != rules.protocol) {
        env.outOfStandard = true;
        env.warnings.push_back("header.Protocol: out-of-standard protocol '" + env.header.protocol + "'");
    }
    const auto& table = decoders();
    for (auto it = doc.begin(); it != doc.end(); ++it) {
        const std::string& key = it.key();
        if (isHeaderKey(key))
            continue;
        std::string_view name = key;
        bool alias = false;
        if (name == rules.allStopStatusAlias) {
            name = "MachineAllStopV1";
            alias = true;
        } else if (name == rules.mapServiceMember) {
            name = "MapServiceV1";
        }
        auto d = table.find(name);
        if (d == table.end()) {
            env.members.push_back(Member{UnknownMember{key, it.value()}, json()});
            env.warnings.push_back("unknown member '" + key + "' kept");
            continue;
        }
        if (alias)
            env.warnings.push_back("member '" + key + "' accepted as MachineAllStopV1");
        try {
            if (d->second.perMachine && !env.header.equipmentId)
                throw DecodeError{std::string(name) + ": header EquipmentId required for this message"};
            json extra;
            Body body = d->second.decode(it.value(), ctx, extra);
            env.members.push_back(Member{std::move(body), std::move(extra)});
        } catch (const DecodeError& e) {
            env.errors.push_back(e.message);
        } catch (const json::exception& e) {
            env.errors.push_back(std::string(name) + ": " + e.what());
        }
    }
    if (env.members.empty() && env.errors.empty())
        env.errors.push_back("message: no message member besides the header");
    return env;
}

Result<Envelope> decodeMessage(std::string_view text, const InferredRules& rules) {
    // Hot path (ISO §7.4, note §5 row 5: 1-10 Hz per machine): clean MachinePositionV1 frames skip the DOM.
    if (auto fast = tryDecodePositionFast(text, rules))
        return std::move(*fast);
    return decodeMessageDom(text, rules);
}

Result<Envelope> decodeMessageDom(std::string_view text, const InferredRules& rules) {
    json doc = json::parse(text.begin(), text.end(), nullptr, false);
    if (doc.is_discarded())
        return makeError("message: invalid JSON");
    return decodeJson(doc, rules);
}

// ---------------------------------------------------------------- encoding

namespace {

json num(const std::optional<double>& v) {
    return v ? json(*v) : json(nullptr);
}
json num(const std::optional<std::int64_t>& v) {
    return v ? json(*v) : json(nullptr);
}
json ts(const Timestamp& t) {
    return t.text.empty() && t.unixMs ? json(formatTimestamp(*t.unixMs)) : json(t.text);
}
template <class T> void putOpt(json& o, const char* k, const std::optional<T>& v) {
    if (v)
        o[k] = *v;
}
void putOptTs(json& o, const char* k, const std::optional<Timestamp>& v) {
    if (v)
        o[k] = ts(*v);
}
json guidOrNull(const std::optional<Guid>& g) {
    return g ? json(*g) : json(nullptr);
}

void putPose(json& o, const PoseFields& p) {
    o["Heading"] = num(p.heading);
    o["Latitude"] = num(p.latitude);
    o["Longitude"] = num(p.longitude);
    o["Elevation"] = num(p.elevation);
    o["LatitudeAccuracy"] = num(p.latitudeAccuracy);
    o["LongitudeAccuracy"] = num(p.longitudeAccuracy);
    o["ElevationAccuracy"] = num(p.elevationAccuracy);
    o["HeadingAccuracy"] = num(p.headingAccuracy);
    o["Speed"] = num(p.speed);
}

json wayRefs(const std::vector<WayRef>& v) {
    json a = json::array();
    for (auto& w : v)
        a.push_back({{"WayId", w.wayId}});
    return a;
}

struct Encoder {
    json operator()(const FleetDefinitionV2& m) const {
        json eq = json::array();
        for (auto& e : m.equipment)
            eq.push_back({{"EquipmentId", e.equipmentId},
                          {"HID", e.hid},
                          {"Type", e.type},
                          {"OEM", e.oem},
                          {"Model", e.model},
                          {"Autonomous", e.autonomous},
                          {"Length", num(e.length)},
                          {"Width", num(e.width)}});
        return {{"AHSId", m.ahsId}, {"Equipment", eq}};
    }
    json operator()(const MachineAllStopRequestV1& m) const {
        return {{"ModeAllStop", m.modeAllStop}, {"ModeAllStopId", m.modeAllStopId}};
    }
    json operator()(const MachineAllStopResponseV1& m) const {
        json o = {{"Response", m.response}, {"ModeAllStopId", m.modeAllStopId}};
        putOpt(o, "Detail", m.detail);
        return o;
    }
    json operator()(const MachineAllStopV1& m) const {
        return {{"ModeAllStop", m.modeAllStop}, {"ModeAllStopId", guidOrNull(m.modeAllStopId)}};
    }
    json operator()(const MachinePositionV1& m) const {
        json o = json::object();
        o["Timestamp"] = ts(m.timestamp);
        putPose(o, m.pose);
        if (m.attachment) {
            json a = json::array();
            for (auto& at : *m.attachment) {
                json x = {{"EquipmentId", at.equipmentId}};
                putPose(x, at.pose);
                a.push_back(std::move(x));
            }
            o["Attachment"] = std::move(a);
        }
        return o;
    }
    json operator()(const BasicMachineHealthV2& m) const {
        json o = {{"FuelLevel", num(m.fuelLevel)},
                  {"TotalMachineHour", num(m.totalMachineHour)},
                  {"TotalEngineHour", num(m.totalEngineHour)}};
        if (m.tire) {
            json a = json::array();
            for (auto& t : *m.tire)
                a.push_back({{"TirePosition", t.tirePosition},
                             {"TirePressure", num(t.tirePressure)},
                             {"TireTemperature", num(t.tireTemperature)}});
            o["Tire"] = std::move(a);
        }
        if (m.primeMoverTemp)
            o["PrimeMoverTemp"] = *m.primeMoverTemp;
        return o;
    }
    json operator()(const MachineAutonomyModeV1& m) const { return {{"AutonomyMode", m.autonomyMode}}; }
    json operator()(const MachineDispatchAvailabilityV1& m) const {
        json o = {{"DispatchingCustodian", m.dispatchingCustodian}};
        putOpt(o, "ImpendingCustodian", m.impendingCustodian);
        putOptTs(o, "ImpendingTime", m.impendingTime);
        return o;
    }
    json operator()(const MachineDiagnosticV2& m) const {
        json a = json::array();
        for (auto& d : m.entries)
            a.push_back({{"ComponentId", d.componentId}, {"FaultCode", d.faultCode}});
        return a;
    }
    json operator()(const MapConnectivityV1& m) const {
        json a = json::array();
        for (auto& c : m.items) {
            json o = {{"WayId", c.wayId}, {"WayType", c.wayType}, {"Connection", wayRefs(c.connection)}};
            if (c.wayType == "Road") {
                json p = {{"Length", num(c.roadLength)}};
                putOpt(p, "Name", c.roadName);
                o["RoadProperty"] = p;
            } else {
                json p = {{"DefaultTask", c.areaDefaultTask.value_or("Drive")}};
                putOpt(p, "Name", c.areaName);
                o["AreaProperty"] = p;
            }
            a.push_back(std::move(o));
        }
        return a;
    }
    json operator()(const MapServiceV1& m) const { return {{"API", m.api}}; }
    json operator()(const MapSummaryV1& m) const {
        json o = {{"Timestamp", ts(m.timestamp)},   {"ChangeSetMap", m.changeSetMap},
                  {"ChangeSetWay", m.changeSetWay}, {"NodeCount", m.nodeCount},
                  {"WayCount", m.wayCount},         {"DocumentCount", m.documentCount}};
        putOpt(o, "uid", m.uid);
        return o;
    }
    json operator()(const MapCommandV1& m) const { return {{"Method", m.method}, {"Scope", m.scope}}; }
    json operator()(const InterfaceDiagnosticV1& m) const {
        json me = json::array(), ms = json::array();
        for (auto& x : m.measurement)
            me.push_back({{"Name", x.name}, {"Value", num(x.value)}, {"Unit", x.unit}});
        for (auto& x : m.message) {
            json o = {{"Severity", x.severity}, {"Code", x.code}};
            putOpt(o, "Detail", x.detail);
            putOpt(o, "RefMember", x.refMember);
            putOptTs(o, "RefTimestamp", x.refTimestamp);
            ms.push_back(std::move(o));
        }
        return {{"Measurement", me}, {"Message", ms}};
    }
    json operator()(const HaulTruckProductionCycleV1& m) const {
        json o = {{"CycleId", m.cycleId}, {"LoadWayId", m.loadWayId}, {"DumpWayId", m.dumpWayId}};
        putOpt(o, "AssignmentId", m.assignmentId);
        putOpt(o, "LoaderEquipmentId", m.loaderEquipmentId);
        putOpt(o, "PayloadWeight", m.payloadWeight);
        json st = json::array();
        for (auto& s : m.stateTimes)
            st.push_back({{"ProductionState", s.productionState},
                          {"Start", ts(s.start)},
                          {"Duration", num(s.duration)}});
        o["StateTimes"] = std::move(st);
        return o;
    }
    json operator()(const HaulTruckProductionStateV2& m) const {
        return {{"AssignmentId", guidOrNull(m.assignmentId)},
                {"WayId", num(m.wayId)},
                {"AutonomyMode", m.autonomyMode},
                {"ProductionState", m.productionState}};
    }
    json operator()(const HaulTruckProductionStateSensorV1& m) const {
        json o = json::object();
        putOpt(o, "Loaded", m.loaded);
        putOpt(o, "BodyRaised", m.bodyRaised);
        putOpt(o, "ParkBrake", m.parkBrake);
        putOpt(o, "PayloadWeight", m.payloadWeight);
        putOpt(o, "InLoadArea", m.inLoadArea);
        putOpt(o, "InDumpArea", m.inDumpArea);
        return o;
    }
    json operator()(const HaulTruckPayloadV1& m) const {
        json o = {{"PayloadWeight", num(m.payloadWeight)}};
        putOpt(o, "Accuracy", m.accuracy);
        if (m.payloadSourceId)
            o["PayloadSourceId"] = *m.payloadSourceId;
        return o;
    }
    json operator()(const HaulTruckDumpV1& m) const {
        json o = {{"WayId", m.wayId}};
        putOpt(o, "AssignmentId", m.assignmentId);
        putOpt(o, "DumpedWeight", m.dumpedWeight);
        putOpt(o, "DestinationSpotId", m.destinationSpotId);
        putOpt(o, "DumpEquipmentId", m.dumpEquipmentId);
        return o;
    }
    json operator()(const HaulTruckAssignmentRequestV2& m) const {
        json a = json::array();
        for (auto& x : m.items) {
            json o = {{"AssignmentId", x.assignmentId}, {"Task", x.task}, {"DestinationId", x.destinationId}};
            putOpt(o, "DestinationEquipmentId", x.destinationEquipmentId);
            putOpt(o, "DestinationSpotId", x.destinationSpotId);
            if (x.route)
                o["RouteV1"] = wayRefs(*x.route);
            a.push_back(std::move(o));
        }
        return a;
    }
    json operator()(const HaulTruckAssignmentResponseV1& m) const {
        json a = json::array();
        for (auto& x : m.items) {
            json o = {{"AssignmentId", x.assignmentId}, {"Response", x.response}};
            putOpt(o, "Detail", x.detail);
            a.push_back(std::move(o));
        }
        return a;
    }
    json operator()(const HaulTruckAssignmentResetV1& m) const { return {{"ResetId", m.resetId}}; }
    json operator()(const HaulTruckAssignmentV1& m) const {
        json o = {{"AssignmentId", guidOrNull(m.assignmentId)}, {"Status", m.status}};
        putOpt(o, "Task", m.task);
        putOpt(o, "DestinationId", m.destinationId);
        return o;
    }
    json operator()(const UnknownMember& m) const { return m.value; }
};

struct NameOf {
    std::string_view operator()(const FleetDefinitionV2&) const { return "FleetDefinitionV2"; }
    std::string_view operator()(const MachineAllStopRequestV1&) const { return "MachineAllStopRequestV1"; }
    std::string_view operator()(const MachineAllStopResponseV1&) const { return "MachineAllStopResponseV1"; }
    std::string_view operator()(const MachineAllStopV1&) const { return "MachineAllStopV1"; }
    std::string_view operator()(const MachinePositionV1&) const { return "MachinePositionV1"; }
    std::string_view operator()(const BasicMachineHealthV2&) const { return "BasicMachineHealthV2"; }
    std::string_view operator()(const MachineAutonomyModeV1&) const { return "MachineAutonomyModeV1"; }
    std::string_view operator()(const MachineDispatchAvailabilityV1&) const {
        return "MachineDispatchAvailabilityV1";
    }
    std::string_view operator()(const MachineDiagnosticV2&) const { return "MachineDiagnosticV2"; }
    std::string_view operator()(const MapConnectivityV1&) const { return "MapConnectivityV1"; }
    std::string_view operator()(const MapServiceV1&) const { return defaultInferredRules().mapServiceMember; }
    std::string_view operator()(const MapSummaryV1&) const { return "MapSummaryV1"; }
    std::string_view operator()(const MapCommandV1&) const { return "MapCommandV1"; }
    std::string_view operator()(const InterfaceDiagnosticV1&) const { return "InterfaceDiagnosticV1"; }
    std::string_view operator()(const HaulTruckProductionCycleV1&) const {
        return "HaulTruckProductionCycleV1";
    }
    std::string_view operator()(const HaulTruckProductionStateV2&) const {
        return "HaulTruckProductionStateV2";
    }
    std::string_view operator()(const HaulTruckProductionStateSensorV1&) const {
        return "HaulTruckProductionStateSensorV1";
    }
    std::string_view operator()(const HaulTruckPayloadV1&) const { return "HaulTruckPayloadV1"; }
    std::string_view operator()(const HaulTruckDumpV1&) const { return "HaulTruckDumpV1"; }
    std::string_view operator()(const HaulTruckAssignmentRequestV2&) const {
        return "HaulTruckAssignmentRequestV2";
    }
    std::string_view operator()(const HaulTruckAssignmentResponseV1&) const {
        return "HaulTruckAssignmentResponseV1";
    }
    std::string_view operator()(const HaulTruckAssignmentResetV1&) const {
        return "HaulTruckAssignmentResetV1";
    }
    std::string_view operator()(const HaulTruckAssignmentV1&) const { return "HaulTruckAssignmentV1"; }
    std::string_view operator()(const UnknownMember& m) const { return m.name; }
};

} // namespace

std::string_view memberName(const Body& body) {
    return std::visit(NameOf{}, body);
}

json toJson(const Envelope& env) {
    json o = json::object();
    o["Protocol"] = env.header.protocol;
    if (env.header.version)
        o["Version"] = *env.header.version;
    o["Timestamp"] = ts(env.header.timestamp);
    if (env.header.equipmentId)
        o["EquipmentId"] = *env.header.equipmentId;
    for (auto& m : env.members) {
        json v = std::visit(Encoder{}, m.body);
        if (v.is_object() && m.extra.is_object())
            for (auto it = m.extra.begin(); it != m.extra.end(); ++it)
                v[it.key()] = it.value();
        o[std::string(memberName(m.body))] = std::move(v);
    }
    return o;
}

std::string encodeMessage(const Envelope& env) {
    return toJson(env).dump();
}

std::string encodeMessage(const Body& body, std::optional<Guid> equipmentId, std::int64_t unixMs) {
    Envelope env;
    env.header.timestamp = makeTimestamp(unixMs < 0 ? std::chrono::duration_cast<std::chrono::milliseconds>(
                                                          std::chrono::system_clock::now().time_since_epoch())
                                                          .count()
                                                    : unixMs);
    env.header.equipmentId = std::move(equipmentId);
    env.members.push_back(Member{body, json::object()});
    return encodeMessage(env);
}

} // namespace ocu::iso23725
