#include "protocols/iso23725/PositionFastPath.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace ocu::iso23725 {

namespace {

// A number token checked against the RFC 8259 §6 grammar; converted only once the frame's shape is known.
struct NumTok {
    std::string_view text;
    bool integral = false; // no fraction and no exponent
};

// A pose member value: a number, or null = unavailable (§3, ISO 4.2.3).
struct PoseTok {
    bool null = false;
    NumTok num;
};

// The pose members in PoseFields order; every one is a shall member (§5 row 5, ISO §7.4).
constexpr std::array<std::string_view, 9> kPoseKeys = {
    "Heading",           "Latitude",          "Longitude",       "Elevation", "LatitudeAccuracy",
    "LongitudeAccuracy", "ElevationAccuracy", "HeadingAccuracy", "Speed"};
enum PoseIndex : std::size_t {
    kHeading,
    kLatitude,
    kLongitude,
    kElevation,
    kLatitudeAccuracy,
    kLongitudeAccuracy,
    kElevationAccuracy,
    kHeadingAccuracy,
    kSpeed
};
constexpr unsigned kPoseTimestampBit = 1u << kPoseKeys.size();
constexpr unsigned kAllPoseBits = (kPoseTimestampBit << 1) - 1;

constexpr std::string_view kPositionMember = "MachinePositionV1";

// Strict scanner over the frame text; every method returns false (decline) at the first surprise.
class Scanner {
public:
    explicit Scanner(std::string_view t) : m_p(t.data()), m_end(t.data() + t.size()) {}

    // RFC 8259 §2: insignificant whitespace is space, tab, LF and CR, nothing else.
    void ws() {
        while (m_p != m_end && (*m_p == ' ' || *m_p == '\n' || *m_p == '\r' || *m_p == '\t'))
            ++m_p;
    }
    bool eat(char c) {
        ws();
        if (m_p == m_end || *m_p != c)
            return false;
        ++m_p;
        return true;
    }
    bool atEnd() {
        ws();
        return m_p == m_end;
    }

    // Printable ASCII without escapes only: that text is byte for byte what the DOM holds. Escapes, control
    // characters (rejected by the DOM) and non-ASCII bytes (UTF-8 the DOM validates) decline.
    bool string(std::string_view& out) {
        if (!eat('"'))
            return false;
        const char* s = m_p;
        while (m_p != m_end) {
            const auto c = static_cast<unsigned char>(*m_p);
            if (c == '"') {
                out = std::string_view(s, static_cast<std::size_t>(m_p - s));
                ++m_p;
                return true;
            }
            if (c < 0x20 || c == '\\' || c >= 0x80)
                return false;
            ++m_p;
        }
        return false;
    }

    // RFC 8259 §6: -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)? ; what follows is checked by the caller.
    bool number(NumTok& out) {
        ws();
        const char* s = m_p;
        if (m_p != m_end && *m_p == '-')
            ++m_p;
        if (m_p == m_end)
            return false;
        if (*m_p == '0')
            ++m_p;
        else if (!digits())
            return false;
        bool integral = true;
        if (m_p != m_end && *m_p == '.') {
            ++m_p;
            if (!digits())
                return false;
            integral = false;
        }
        if (m_p != m_end && (*m_p == 'e' || *m_p == 'E')) {
            ++m_p;
            if (m_p != m_end && (*m_p == '+' || *m_p == '-'))
                ++m_p;
            if (!digits())
                return false;
            integral = false;
        }
        out = NumTok{std::string_view(s, static_cast<std::size_t>(m_p - s)), integral};
        return true;
    }

    bool poseValue(PoseTok& out) {
        ws();
        if (m_end - m_p >= 4 && std::memcmp(m_p, "null", 4) == 0) {
            m_p += 4;
            out.null = true;
            return true;
        }
        out.null = false;
        return number(out.num);
    }

    // {"key": value, ...} with at least one member; member(key) reads the value.
    template <class F> bool object(F&& member) {
        if (!eat('{'))
            return false;
        do {
            std::string_view key;
            if (!string(key) || !eat(':') || !member(key))
                return false;
        } while (eat(','));
        return eat('}');
    }

private:
    bool digits() {
        const char* s = m_p;
        while (m_p != m_end && *m_p >= '0' && *m_p <= '9')
            ++m_p;
        return m_p != s;
    }

    const char* m_p;
    const char* m_end;
};

// Sets bit in seen; false for a duplicate member (the DOM would silently keep the last one).
bool once(unsigned& seen, unsigned bit) {
    if (seen & bit)
        return false;
    seen |= bit;
    return true;
}

// Up to 18 digits: nlohmann stores the token as an exact integer and get<int64_t> returns it. Decimals for
// integer members are rounded by the DOM path (§9); rare on the wire, so they decline.
bool toInt(const NumTok& n, std::int64_t& out) {
    if (!n.integral)
        return false;
    std::string_view d = n.text;
    const bool negative = d.front() == '-';
    if (negative)
        d.remove_prefix(1);
    if (d.size() > 18)
        return false;
    std::int64_t v = 0;
    for (char c : d)
        v = v * 10 + (c - '0');
    out = negative ? -v : v;
    return true;
}

// Bit-identical to nlohmann's get<double>(): an integer token is converted from the integer (so "-0" gives
// +0.0), any other token is correctly rounded, as strtod does. Overflow and underflow decline.
bool toDouble(const NumTok& n, double& out) {
    if (std::int64_t i = 0; toInt(n, i)) {
        out = static_cast<double>(i);
        return true;
    }
    const char* b = n.text.data();
    const char* e = b + n.text.size();
    auto [p, ec] = std::from_chars(b, e, out);
    return ec == std::errc() && p == e && std::isfinite(out);
}

bool poseInt(const PoseTok& t, std::optional<std::int64_t>& out) {
    if (t.null)
        return true;
    std::int64_t v = 0;
    if (!toInt(t.num, v))
        return false;
    out = v;
    return true;
}

bool poseDouble(const PoseTok& t, std::optional<double>& out) {
    if (t.null)
        return true;
    double v = 0;
    if (!toDouble(t.num, v))
        return false;
    out = v;
    return true;
}

} // namespace

std::optional<Envelope> tryDecodePositionFast(std::string_view text, const InferredRules& rules) {
    // decodeJson renames the configured all-stop alias (Q4) and map service member (Q10): never this one.
    if (rules.allStopStatusAlias == kPositionMember || rules.mapServiceMember == kPositionMember)
        return std::nullopt;

    // Pass 1: the shape. Values are kept as text views; unknown, duplicate and missing members decline.
    enum : unsigned {
        kProtocol = 1,
        kVersion = 2,
        kTimestamp = 4,
        kEquipmentId = 8,
        kPosition = 16,
        kAll = 31
    };
    unsigned seen = 0, poseSeen = 0;
    std::string_view protocol, timestamp, equipmentId, poseTimestamp;
    NumTok version;
    std::array<PoseTok, kPoseKeys.size()> pose{};
    Scanner sc(text);

    auto poseMember = [&](std::string_view key) {
        if (key == "Timestamp")
            return once(poseSeen, kPoseTimestampBit) && sc.string(poseTimestamp);
        for (std::size_t i = 0; i < kPoseKeys.size(); ++i)
            if (key == kPoseKeys[i])
                return once(poseSeen, 1u << i) && sc.poseValue(pose[i]);
        return false; // unknown member, alias (HeightAccuracy, §9) or Attachment: the DOM path
    };
    auto topMember = [&](std::string_view key) {
        if (key == "Protocol")
            return once(seen, kProtocol) && sc.string(protocol);
        if (key == "Version")
            return once(seen, kVersion) && sc.number(version);
        if (key == "Timestamp")
            return once(seen, kTimestamp) && sc.string(timestamp);
        if (key == "EquipmentId")
            return once(seen, kEquipmentId) && sc.string(equipmentId);
        if (key == kPositionMember)
            return once(seen, kPosition) && sc.object(poseMember);
        return false; // other members (even a clean piggy-back, §3) and the EquipmentID alias: the DOM path
    };
    if (!sc.object(topMember) || !sc.atEnd() || seen != kAll || poseSeen != kAllPoseBits)
        return std::nullopt;

    // Pass 2: the values, with exactly the DOM path's checks; anything it would warn about or reject
    // declines.
    if (protocol != rules.protocol) // §4.2: out of standard, flagged by the DOM path
        return std::nullopt;
    std::int64_t ver = 0;
    if (!toInt(version, ver))
        return std::nullopt;
    // Strict ISO 8601 only: a timestamp that needs the §9 repair gets a warning from the DOM path.
    auto headerMs = parseTimestamp(timestamp, false);
    auto poseMs = parseTimestamp(poseTimestamp, false);
    if (!headerMs || !poseMs || !isGuid(equipmentId))
        return std::nullopt;

    MachinePositionV1 m;
    PoseFields& p = m.pose;
    if (!poseInt(pose[kHeading], p.heading) || !poseDouble(pose[kLatitude], p.latitude) ||
        !poseDouble(pose[kLongitude], p.longitude) || !poseDouble(pose[kElevation], p.elevation) ||
        !poseDouble(pose[kLatitudeAccuracy], p.latitudeAccuracy) ||
        !poseDouble(pose[kLongitudeAccuracy], p.longitudeAccuracy) ||
        !poseDouble(pose[kElevationAccuracy], p.elevationAccuracy) ||
        !poseDouble(pose[kHeadingAccuracy], p.headingAccuracy) || !poseInt(pose[kSpeed], p.speed))
        return std::nullopt;
    // Ranges of §3 (ISO 4.2.4: heading 0-359 compass degrees, WGS84 degrees): out of range is a DOM error.
    if ((p.heading && (*p.heading < 0 || *p.heading > 359)) ||
        (p.latitude && !(*p.latitude >= -90 && *p.latitude <= 90)) ||
        (p.longitude && !(*p.longitude >= -180 && *p.longitude <= 180)))
        return std::nullopt;
    m.timestamp = Timestamp{std::string(poseTimestamp), poseMs};

    Envelope env;
    env.header.protocol = std::string(protocol);
    env.header.version = ver;
    env.header.timestamp = Timestamp{std::string(timestamp), headerMs};
    Guid id(equipmentId); // GUIDs are kept in canonical lower case
    std::transform(id.begin(), id.end(), id.begin(), [](unsigned char c) { return std::tolower(c); });
    env.header.equipmentId = std::move(id);
    env.members.push_back(Member{std::move(m), nlohmann::json()}); // no unknown members: extra stays null
    return env;
}

} // namespace ocu::iso23725
