// MachinePositionV1 fast path: it accepts the clean position frames (benchmark message, catalogue examples,
// research note §6 example 5, the simulator's own output) and, whenever it accepts, its Envelope equals the
// DOM path's field for field, doubles bit for bit. Over a corpus of variants and 20,000 seeded mutations it
// either declines or agrees, and the public decodeMessage always equals the DOM path.
#include "protocols/iso23725/PositionFastPath.h"

#include "tests/protocols/iso23725/IsoTestData.h"

#include <QtTest>

#include <chrono>
#include <cstring>
#include <fstream>
#include <random>

using namespace ocu;
using namespace ocu::iso23725;
using nlohmann::json;

namespace {

// The message of bench_iso23725's BM_ParseValidatePosition (= catalogue line 6).
const std::string kPosition =
    R"({"Protocol":"ISO23725","Version":1,"Timestamp":"2025-03-14T02:15:07.412Z","EquipmentId":"c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78",)"
    R"("MachinePositionV1":{"Timestamp":"2025-03-14T02:15:07.380Z","Heading":87,"Latitude":-23.360114,"Longitude":119.730552,"Elevation":512.34,)"
    R"("LatitudeAccuracy":0.05,"LongitudeAccuracy":0.06,"ElevationAccuracy":0.11,"HeadingAccuracy":0.8,"Speed":34}})";

// shared/research/iso23725.md §6 example 5, verbatim with its line breaks and indentation.
const std::string kNoteExample5 =
    "{\"Protocol\":\"ISO23725\",\"Version\":1,\"Timestamp\":\"2025-03-14T02:15:07.412Z\","
    "\"EquipmentId\":\"c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78\",\n"
    " \"MachinePositionV1\":{\"Timestamp\":\"2025-03-14T02:15:07.380Z\",\"Heading\":87,\"Latitude\":-23."
    "360114,"
    "\"Longitude\":119.730552,\"Elevation\":512.34,\n"
    "  "
    "\"LatitudeAccuracy\":0.05,\"LongitudeAccuracy\":0.06,\"ElevationAccuracy\":0.11,\"HeadingAccuracy\":0.8,"
    "\"Speed\":34}}";

// ---- comparison: every Envelope field; doubles bit for bit (-0.0 vs +0.0 differ here, not under ==)

bool sameBits(const std::optional<double>& a, const std::optional<double>& b) {
    if (a.has_value() != b.has_value())
        return false;
    return !a || std::memcmp(&*a, &*b, sizeof(double)) == 0;
}

bool samePose(const PoseFields& a, const PoseFields& b) {
    return a == b && sameBits(a.latitude, b.latitude) && sameBits(a.longitude, b.longitude) &&
           sameBits(a.elevation, b.elevation) && sameBits(a.latitudeAccuracy, b.latitudeAccuracy) &&
           sameBits(a.longitudeAccuracy, b.longitudeAccuracy) &&
           sameBits(a.elevationAccuracy, b.elevationAccuracy) &&
           sameBits(a.headingAccuracy, b.headingAccuracy);
}

std::string join(const std::vector<std::string>& v) {
    std::string s;
    for (auto& x : v)
        s += "[" + x + "]";
    return s;
}

// Empty when a and b are equal, else what differs.
std::string differences(const Result<Envelope>& a, const Result<Envelope>& b) {
    if (a.ok() != b.ok())
        return std::string("one decoded, the other failed: ") + (a.ok() ? b.error() : a.error());
    if (!a.ok())
        return a.error() == b.error() ? std::string() : "failures differ: " + a.error() + " | " + b.error();
    const Envelope& x = *a;
    const Envelope& y = *b;
    if (!(x.header == y.header))
        return "headers differ";
    if (x.errors != y.errors)
        return "errors differ: " + join(x.errors) + " | " + join(y.errors);
    if (x.warnings != y.warnings)
        return "warnings differ: " + join(x.warnings) + " | " + join(y.warnings);
    if (x.outOfStandard != y.outOfStandard)
        return "outOfStandard differs";
    if (x.members.size() != y.members.size())
        return "member counts differ";
    for (std::size_t i = 0; i < x.members.size(); ++i) {
        const Member& m = x.members[i];
        const Member& n = y.members[i];
        if (!(m.body == n.body))
            return "member " + std::string(memberName(m.body)) + " differs";
        if (m.extra != n.extra || m.extra.type() != n.extra.type())
            return "extra json differs: " + m.extra.dump() + " | " + n.extra.dump();
        auto* p = std::get_if<MachinePositionV1>(&m.body);
        auto* q = std::get_if<MachinePositionV1>(&n.body);
        if (p && q) {
            if (!samePose(p->pose, q->pose))
                return "pose doubles differ in their bits";
            for (std::size_t k = 0; p->attachment && k < p->attachment->size(); ++k)
                if (!samePose((*p->attachment)[k].pose, (*q->attachment)[k].pose))
                    return "attachment pose doubles differ in their bits";
        }
    }
    return {};
}

// Checks one frame; returns whether the fast path accepted it. Fails the test (QVERIFY2) on any disagreement.
struct Outcome {
    bool accepted = false;
    std::string problem; // empty when the fast path (if it accepted) and decodeMessage equal the DOM path
};

Outcome check(const std::string& text, const InferredRules& rules) {
    Outcome o;
    const Result<Envelope> dom = decodeMessageDom(text, rules);
    if (auto fast = tryDecodePositionFast(text, rules)) {
        o.accepted = true;
        std::string d = differences(Result<Envelope>(*fast), dom);
        if (!d.empty())
            o.problem = "fast path != DOM path: " + d;
    }
    if (o.problem.empty()) {
        std::string d = differences(decodeMessage(text, rules), dom);
        if (!d.empty())
            o.problem = "decodeMessage != DOM path: " + d;
    }
    return o;
}

// ---- frame builder for the variant corpus

using Fields = std::vector<std::pair<std::string, std::string>>; // member name, raw JSON value

Fields header() {
    return {{"Protocol", R"("ISO23725")"},
            {"Version", "1"},
            {"Timestamp", R"("2025-03-14T02:15:07.412Z")"},
            {"EquipmentId", R"("c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78")"}};
}
Fields pose() {
    return {{"Timestamp", R"("2025-03-14T02:15:07.380Z")"},
            {"Heading", "87"},
            {"Latitude", "-23.360114"},
            {"Longitude", "119.730552"},
            {"Elevation", "512.34"},
            {"LatitudeAccuracy", "0.05"},
            {"LongitudeAccuracy", "0.06"},
            {"ElevationAccuracy", "0.11"},
            {"HeadingAccuracy", "0.8"},
            {"Speed", "34"}};
}
const char* kPoseNumbers[] = {"Heading",           "Latitude",         "Longitude",
                              "Elevation",         "LatitudeAccuracy", "LongitudeAccuracy",
                              "ElevationAccuracy", "HeadingAccuracy",  "Speed"};

std::string object(const Fields& f) {
    std::string s = "{";
    for (auto& [k, v] : f)
        s += (s.size() > 1 ? ",\"" : "\"") + k + "\":" + v;
    return s + "}";
}
Fields with(Fields f, const std::string& key, const std::string& value) {
    for (auto& [k, v] : f)
        if (k == key) {
            v = value;
            return f;
        }
    f.emplace_back(key, value);
    return f;
}
Fields without(Fields f, const std::string& key) {
    std::erase_if(f, [&](auto& kv) { return kv.first == key; });
    return f;
}
Fields renamed(Fields f, const std::string& key, const std::string& to) {
    for (auto& kv : f)
        if (kv.first == key)
            kv.first = to;
    return f;
}
Fields plus(Fields f, const std::string& key, const std::string& value) {
    f.emplace_back(key, value);
    return f;
}
std::string frame(const Fields& h = header(), const Fields& p = pose()) {
    return object(plus(h, "MachinePositionV1", object(p)));
}
std::string framePose(const std::string& key, const std::string& value) {
    return frame(header(), with(pose(), key, value));
}
std::string frameHeader(const std::string& key, const std::string& value) {
    return frame(with(header(), key, value), pose());
}

// Whitespace of every kind before and after every structural character outside strings.
std::string spaced(const std::string& text) {
    std::string out = " \r\n";
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (inString) {
            out += c;
            if (c == '\\')
                out += text[++i];
            else if (c == '"')
                inString = false;
            continue;
        }
        if (c == '"') {
            out += " \t\"";
            inString = true;
        } else if (std::strchr("{}[],:", c)) {
            out += "\n\t ";
            out += c;
            out += "\r\n ";
        } else {
            out += c;
        }
    }
    return out + " \t\r\n";
}

enum class Expect { Accept, Decline, Either };

struct Variant {
    std::string name;
    std::string text;
    Expect expect;
};

std::vector<Variant> corpus() {
    using E = Expect;
    std::vector<Variant> v;
    auto add = [&](std::string name, std::string text, Expect e) {
        v.push_back(Variant{std::move(name), std::move(text), e});
    };
    Fields h = header(), p = pose();

    // Accepted shapes.
    add("builder = benchmark", frame(), E::Accept);
    add("header reordered", frame(Fields(h.rbegin(), h.rend()), p), E::Accept);
    add("pose reordered", frame(h, Fields(p.rbegin(), p.rend())), E::Accept);
    add("position member first", object(Fields{{"MachinePositionV1", object(p)}, h[2], h[0], h[3], h[1]}),
        E::Accept);
    add("whitespace everywhere", spaced(kPosition), E::Accept);
    add("leading and trailing whitespace", " \t\r\n" + kPosition + "\n\r\t ", E::Accept);
    Fields allNull = p;
    for (const char* k : kPoseNumbers) {
        add(std::string("null ") + k, framePose(k, "null"), E::Accept);
        allNull = with(allNull, k, "null");
    }
    add("all pose numbers null", frame(h, allNull), E::Accept);
    for (const char* n : {"-0",
                          "-0.0",
                          "0",
                          "-23",
                          "512",
                          "-12.5",
                          "5.1234e2",
                          "5.1234E+2",
                          "51234e-2",
                          "0e0",
                          "-0e-0",
                          "1E-7",
                          "-2.3360114e1",
                          "123456789012345678901234",
                          "18446744073709551615",
                          "18446744073709551616",
                          "9223372036854775807",
                          "-9223372036854775808",
                          "-9223372036854775809",
                          "9007199254740993",
                          "999999999999999999",
                          "-999999999999999999",
                          "1000000000000000000",
                          "0.1000000000000000055511151231257827021181583404541015625",
                          "2.2250738585072011e-308",
                          "1.7976931348623157e308",
                          "-23.36011400000000000000000001",
                          "0.30000000000000004",
                          "5e-324"}) {
        add(std::string("Elevation ") + n, framePose("Elevation", n), E::Accept);
        add(std::string("LatitudeAccuracy ") + n, framePose("LatitudeAccuracy", n), E::Accept);
    }
    for (const char* n : {"-0", "-0.0", "-90", "90", "-89.999999999999999999", "9e1", "0.9E2"})
        add(std::string("Latitude ") + n, framePose("Latitude", n), E::Accept);
    for (const char* n : {"-180", "180", "-0", "1.8e2"})
        add(std::string("Longitude ") + n, framePose("Longitude", n), E::Accept);
    for (const char* n : {"0", "-0", "359", "1"})
        add(std::string("Heading ") + n, framePose("Heading", n), E::Accept);
    for (const char* n : {"0", "-3", "-0", "999999999999999999", "-999999999999999999"})
        add(std::string("Speed ") + n, framePose("Speed", n), E::Accept);
    for (const char* n : {"2", "0", "-1", "-0", "123456789012345678"})
        add(std::string("Version ") + n, frameHeader("Version", n), E::Accept);
    add("upper-case GUID", frameHeader("EquipmentId", R"("C3A51F7E-0D24-4B9A-8F63-1E2D4C5B6A78")"),
        E::Accept);
    for (const char* t : {R"("2025-03-14t02:15:07.412z")", R"("2025-03-14T02:15:07Z")",
                          R"("2025-03-14T10:15:07.412+08:00")", R"("2025-03-14T02:15:07.412-03:30")",
                          R"("2025-03-14T02:15:07.4123456Z")", R"("2016-12-31T23:59:60.000Z")"}) {
        add(std::string("header Timestamp ") + t, frameHeader("Timestamp", t), E::Accept);
        add(std::string("pose Timestamp ") + t, framePose("Timestamp", t), E::Accept);
    }

    // Integer members given otherwise: the DOM path rounds or converts them (§9), the fast path declines.
    for (const char* n : {"87.0", "1e2", "87.5", "8.7e1", "87.49999999999999", "-0.4", R"("87")", R"("87.5")",
                          "1234567890123456789", "123456789012345678901", "360", "-1", "true", "[]", "{}"}) {
        add(std::string("Heading ") + n, framePose("Heading", n), E::Decline);
        add(std::string("Speed ") + n, framePose("Speed", n),
            n == std::string("360") || n == std::string("-1") ? E::Accept : E::Decline);
    }
    for (const char* n : {"1.0", "1e0", R"("1")", "null", "true", "1234567890123456789", "[1]"})
        add(std::string("Version ") + n, frameHeader("Version", n), E::Decline);

    // Out-of-range values, wrong types, numbers as strings.
    for (const char* n : {"90.0000001", "-91", "1e3", R"("-23.36")", "true", "false", "[1]", "{}", R"("")"})
        add(std::string("Latitude ") + n, framePose("Latitude", n), E::Decline);
    for (const char* n : {"180.5", "-181", R"("119.7")"})
        add(std::string("Longitude ") + n, framePose("Longitude", n), E::Decline);
    for (const char* k : {"Elevation", "HeadingAccuracy", "ElevationAccuracy"})
        add(std::string(k) + " as string", framePose(k, R"("0.8")"), E::Decline);

    // Missing members.
    for (auto& [k, val] : p)
        add("pose without " + k, frame(h, without(p, k)), E::Decline);
    for (auto& [k, val] : h)
        add("header without " + k, frame(without(h, k), p), E::Decline);
    add("no position member", object(h), E::Decline);
    add("empty pose", frame(h, {}), E::Decline);

    // Wrong header types and values.
    for (const char* n : {"1", "null", R"("iso23725")", R"("Open-Autonomy")", R"("")", R"("ISO23725 ")"})
        add(std::string("Protocol ") + n, frameHeader("Protocol", n), E::Decline);
    for (const char* n :
         {"5", "null", R"("2025-03-14T02:15:07.41.2Z")", R"("2025-03-14 02:15:07.412Z")",
          R"("2025-03-14T02:15:07.412")", R"("2025-02-30T02:15:07.412Z")", R"("yesterday")", R"("")"}) {
        add(std::string("header Timestamp ") + n, frameHeader("Timestamp", n), E::Decline);
        add(std::string("pose Timestamp ") + n, framePose("Timestamp", n), E::Decline);
    }
    for (const char* n :
         {"5", "null", R"("c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a7")",
          R"("g3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78")", R"("c3a51f7e0d244b9a8f631e2d4c5b6a78")",
          R"("{c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78}")"})
        add(std::string("EquipmentId ") + n, frameHeader("EquipmentId", n), E::Decline);
    for (const char* n : {"[]", "null", R"("x")", "5", "true", "[{}]"})
        add(std::string("position member ") + n, object(plus(h, "MachinePositionV1", n)), E::Decline);

    // Unknown members, Attachment, aliases (§9), other members.
    add("unknown top member", object(plus(plus(h, "MachinePositionV1", object(p)), "Foo", "1")), E::Decline);
    add("unknown pose member", frame(h, plus(p, "Foo", "1")), E::Decline);
    add("unknown pose member null", frame(h, plus(p, "Pitch", "null")), E::Decline);
    add("empty Attachment", frame(h, plus(p, "Attachment", "[]")), E::Decline);
    add("Attachment",
        frame(h, plus(p, "Attachment",
                      "[" +
                          object(with(without(p, "Timestamp"), "EquipmentId",
                                      R"("5e8b2c91-7a4f-4d3e-b016-9c8d7e6f5a42")")) +
                          "]")),
        E::Decline);
    add("AttachmentV1", frame(h, plus(p, "AttachmentV1", "[]")), E::Decline);
    add("HeightAccuracy alias", frame(h, renamed(p, "ElevationAccuracy", "HeightAccuracy")), E::Decline);
    add("HeightAccuracy and ElevationAccuracy", frame(h, plus(p, "HeightAccuracy", "0.2")), E::Decline);
    add("EquipmentID alias", frame(renamed(h, "EquipmentId", "EquipmentID"), p), E::Decline);
    add("EquipmentID and EquipmentId",
        frame(plus(h, "EquipmentID", R"("5e8b2c91-7a4f-4d3e-b016-9c8d7e6f5a42")"), p), E::Decline);
    add("piggy-backed with autonomy mode",
        object(plus(plus(h, "MachineAutonomyModeV1", R"({"AutonomyMode":"Manual"})"), "MachinePositionV1",
                    object(p))),
        E::Decline);
    add("two position-like members",
        object(plus(plus(h, "MachinePositionV1", object(p)), "MachinePositionV2", object(p))), E::Decline);
    add("lower-case member name", object(plus(h, "machinePositionV1", object(p))), E::Decline);

    // Duplicate members (the DOM silently keeps the last one).
    add("duplicate Protocol", frame(plus(h, "Protocol", R"("ISO23725")"), p), E::Decline);
    add("duplicate Version", frame(plus(h, "Version", "2"), p), E::Decline);
    add("duplicate Heading", frame(h, plus(p, "Heading", "88")), E::Decline);
    add("duplicate Heading null", frame(h, plus(p, "Heading", "null")), E::Decline);
    add("duplicate pose Timestamp", frame(h, plus(p, "Timestamp", R"("2025-03-14T02:15:08.000Z")")),
        E::Decline);
    add("duplicate position member",
        object(plus(plus(h, "MachinePositionV1", object(p)), "MachinePositionV1",
                    object(with(p, "Speed", "1")))),
        E::Decline);

    // Escapes and non-ASCII text.
    add("escaped Protocol", frameHeader("Protocol", R"("ISO\u00323725")"), E::Decline);
    add("escaped key", frame(h, renamed(p, "Heading", R"(Head\u0069ng)")), E::Decline);
    add("escaped GUID", frameHeader("EquipmentId", R"("\u00633a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78")"),
        E::Decline);
    add("escaped Z in Timestamp", framePose("Timestamp", R"("2025-03-14T02:15:07.380\u005A")"), E::Decline);
    add("bad escape", frameHeader("Protocol", R"("ISO\x23725")"), E::Decline);
    add("UTF-8 in Protocol", frameHeader("Protocol", "\"ISO23725\xC3\xA9\""), E::Decline);
    add("invalid UTF-8 in Protocol", frameHeader("Protocol", "\"ISO23725\xC3\""), E::Decline);
    add("control character in Protocol",
        frameHeader("Protocol", "\"ISO\x01"
                                "23725\""),
        E::Decline);
    add("tab inside a string", frameHeader("Protocol", "\"ISO\t23725\""), E::Decline);

    // Number and literal grammar (RFC 8259 §6, §3).
    for (const char* n : {"01",  "-01",      "1.",        ".5",    "+1",    "-",      "1e",  "1e+",   "1E-",
                          "NaN", "Infinity", "-Infinity", "0x10",  "1e400", "-1e400", "--1", "1..2",  "1.2.3",
                          "- 1", "1 2",      "nul",       "nulll", "NULL",  "Null",   "n",   "1_000", "1,5"})
        add(std::string("Elevation ") + n, framePose("Elevation", n), E::Decline);
    add("Elevation 1e-400 (underflow)", framePose("Elevation", "1e-400"), E::Either);
    add("Elevation 2e-324 (underflow)", framePose("Elevation", "2e-324"), E::Either);

    // Broken structure and trailing text.
    std::string noClose = kPosition.substr(0, kPosition.size() - 1);
    for (const char* t : {"x", "}", " {}", ",", "//", "/* c */", "\x01", "0", "\"\"", "\xEF\xBB\xBF"})
        add(std::string("trailing ") + t, kPosition + t, E::Decline);
    add("trailing NUL", kPosition + std::string(1, '\0'), E::Decline);
    add("missing outer brace", noClose, E::Decline);
    add("trailing comma in pose", frame(h, p).replace(frame(h, p).find("34}"), 3, "34,}"), E::Decline);
    add("trailing comma at top", noClose + ",}", E::Decline);
    add("missing comma", frame(h, p).replace(frame(h, p).find(",\"Speed\""), 1, " "), E::Decline);
    add("missing colon", frame(h, p).replace(frame(h, p).find("\"Speed\":"), 8, "\"Speed\" "), E::Decline);
    add("single quotes", frameHeader("Protocol", "'ISO23725'"), E::Decline);
    add("leading BOM", "\xEF\xBB\xBF" + kPosition, E::Decline);
    add("leading comment", "/**/" + kPosition, E::Decline);
    add("vertical tab", "\v" + kPosition, E::Decline);
    add("form feed inside", frame(h, p).replace(frame(h, p).find(",\"Speed\""), 1, "\f,"), E::Decline);
    add("array of the frame", "[" + kPosition + "]", E::Decline);
    for (const char* t : {"", " ", "{}", "[]", "null", "\"x\"", "{", "}", "{\"Protocol\"", "1"})
        add(std::string("frame ") + t, t, E::Decline);
    for (std::size_t n = 0; n < kPosition.size(); ++n)
        add("truncated at " + std::to_string(n), kPosition.substr(0, n), E::Decline);
    return v;
}

// The §9 tolerances switched off, and a site whose configured Protocol differs (§4.2).
InferredRules strictRules() {
    InferredRules r;
    r.acceptAliases = false;
    r.repairTimestamps = false;
    r.acceptNumericStrings = false;
    r.acceptMissingVersion = false;
    r.caseInsensitiveEnums = false;
    return r;
}

} // namespace

class TestIsoPositionFast : public QObject {
    Q_OBJECT
private slots:
    // 1. The clean position frames are accepted, and the result equals the DOM path's in every field.
    void acceptsCleanPositionFrames() {
        QCOMPARE(frame(), kPosition); // the corpus builder starts from the benchmark message
        const InferredRules& rules = defaultInferredRules();
        for (const std::string& text : {kPosition, kNoteExample5}) {
            auto fast = tryDecodePositionFast(text, rules);
            QVERIFY2(fast.has_value(), text.c_str());
            auto dom = decodeMessageDom(text, rules);
            QVERIFY(dom.ok());
            std::string d = differences(Result<Envelope>(*fast), dom);
            QVERIFY2(d.empty(), d.c_str());
            d = differences(decodeMessage(text, rules), dom);
            QVERIFY2(d.empty(), d.c_str());
            // Not vacuous: the values are the message's.
            QCOMPARE(fast->header.protocol, std::string("ISO23725"));
            QCOMPARE(fast->header.version, std::optional<std::int64_t>(1));
            QCOMPARE(fast->header.timestamp.text, std::string("2025-03-14T02:15:07.412Z"));
            QCOMPARE(fast->header.timestamp.unixMs, std::optional<std::int64_t>(1741918507412));
            QCOMPARE(fast->header.equipmentId, std::optional<Guid>("c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78"));
            QVERIFY(fast->errors.empty() && fast->warnings.empty() && !fast->outOfStandard);
            QCOMPARE(int(fast->members.size()), 1);
            QVERIFY(fast->members[0].extra.is_null());
            const auto* m = fast->find<MachinePositionV1>();
            QVERIFY(m);
            QCOMPARE(m->timestamp.unixMs, std::optional<std::int64_t>(1741918507380));
            QCOMPARE(m->pose.heading, std::optional<std::int64_t>(87));
            QCOMPARE(m->pose.latitude, std::optional<double>(-23.360114));
            QCOMPARE(m->pose.longitude, std::optional<double>(119.730552));
            QCOMPARE(m->pose.elevation, std::optional<double>(512.34));
            QCOMPARE(m->pose.headingAccuracy, std::optional<double>(0.8));
            QCOMPARE(m->pose.speed, std::optional<std::int64_t>(34));
            QVERIFY(!m->attachment);
        }
    }

    // 1b. Catalogue: the header-plus-position frames are accepted; the piggy-backed one (line 8, §3) and
    // every other message are declined; decodeMessage equals the DOM path for all 27 lines.
    void catalogueExamples() {
        auto examples = loadCatalogueExamples();
        QCOMPARE(int(examples.size()), 27);
        int accepted = 0, positions = 0;
        for (auto& text : examples) {
            json doc = json::parse(text);
            const bool pure = doc.contains("MachinePositionV1") && doc.size() == 5;
            positions += doc.contains("MachinePositionV1");
            Outcome o = check(text, defaultInferredRules());
            QVERIFY2(o.problem.empty(), (o.problem + "\n" + text).c_str());
            QVERIFY2(o.accepted == pure, text.c_str());
            accepted += o.accepted;
        }
        QCOMPARE(positions, 2);
        QCOMPARE(accepted, 1);
        // Line 8's position alone (its piggy-back member removed) is a clean frame and is accepted.
        std::string line8 = examples[7];
        const std::string piggy = R"("MachineAutonomyModeV1":{"AutonomyMode":"Manual"},)";
        QVERIFY(line8.find(piggy) != std::string::npos);
        line8.erase(line8.find(piggy), piggy.size());
        Outcome o = check(line8, defaultInferredRules());
        QVERIFY2(o.accepted && o.problem.empty(), (o.problem + "\n" + line8).c_str());
    }

    // 1c. What the simulator and encodeMessage emit (sorted keys, nlohmann's shortest doubles, nulls) is
    // accepted and decodes back to the very same pose, bit for bit.
    void encoderOutputRoundTrips() {
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<double> lat(-90, 90), lon(-180, 180), ele(-500, 5000), acc(0, 10);
        auto maybe = [&](double v) {
            return rng() % 7 == 0 ? std::optional<double>() : std::optional<double>(v);
        };
        for (int i = 0; i < 500; ++i) {
            MachinePositionV1 m;
            m.timestamp = makeTimestamp(1741918507380 + i * 100);
            m.pose.heading = rng() % 7 == 0 ? std::nullopt : std::optional<std::int64_t>(rng() % 360);
            m.pose.latitude = maybe(lat(rng));
            m.pose.longitude = maybe(lon(rng));
            m.pose.elevation = maybe(i % 50 == 0 ? -0.0 : ele(rng));
            m.pose.latitudeAccuracy = maybe(acc(rng));
            m.pose.longitudeAccuracy = maybe(i % 3 == 0 ? 1.0 : acc(rng));
            m.pose.elevationAccuracy = maybe(acc(rng) * 1e-9);
            m.pose.headingAccuracy = maybe(acc(rng) * 1e9);
            m.pose.speed = rng() % 7 == 0 ? std::nullopt : std::optional<std::int64_t>(int(rng() % 120) - 10);
            std::string text =
                encodeMessage(m, Guid("5e8b2c91-7a4f-4d3e-b016-9c8d7e6f5a42"), 1741918507412 + i);
            Outcome o = check(text, defaultInferredRules());
            QVERIFY2(o.accepted && o.problem.empty(), (o.problem + "\n" + text).c_str());
            auto fast = tryDecodePositionFast(text, defaultInferredRules());
            const auto* back = fast->find<MachinePositionV1>();
            QVERIFY2(back && samePose(back->pose, m.pose) && back->timestamp == m.timestamp, text.c_str());
        }
    }

    // 2. Variants: each is declined or decoded exactly as the DOM path does, as expected; decodeMessage
    // always equals the DOM path. Also under strict rules and a site-specific Protocol.
    void variantsAgreeWithDomPath() {
        const auto variants = corpus();
        int accepted = 0;
        for (const auto& v : variants) {
            Outcome o = check(v.text, defaultInferredRules());
            std::string what = v.name + ": " + o.problem + "\n" + v.text;
            QVERIFY2(o.problem.empty(), what.c_str());
            if (v.expect == Expect::Accept)
                QVERIFY2(o.accepted, ("expected the fast path to accept " + what).c_str());
            if (v.expect == Expect::Decline)
                QVERIFY2(!o.accepted, ("expected the fast path to decline " + what).c_str());
            accepted += o.accepted;
        }
        QVERIFY(accepted > 100);

        InferredRules other;
        other.protocol = "Open-Autonomy";
        InferredRules
            renamedMember; // Q10 set to the position member's name: decodeJson then reads MapServiceV1
        renamedMember.mapServiceMember = "MachinePositionV1";
        InferredRules renamedStatus; // Q4 likewise: decodeJson reads it as MachineAllStopV1
        renamedStatus.allStopStatusAlias = "MachinePositionV1";
        struct RuleCase {
            const char* name;
            InferredRules rules;
            bool declinesAll;
        };
        for (const RuleCase& rc :
             {RuleCase{"strict", strictRules(), false}, RuleCase{"Open-Autonomy", other, false},
              RuleCase{"Q10 renamed", renamedMember, true}, RuleCase{"Q4 renamed", renamedStatus, true}})
            for (const auto& v : variants) {
                Outcome o = check(v.text, rc.rules);
                std::string what =
                    std::string(rc.name) + " rules, " + v.name + ": " + o.problem + "\n" + v.text;
                QVERIFY2(o.problem.empty(), what.c_str());
                if (rc.declinesAll || (v.expect == Expect::Decline && rc.rules.protocol == "ISO23725"))
                    QVERIFY2(!o.accepted, what.c_str());
            }
        QVERIFY(check(kPosition, strictRules()).accepted);
        QVERIFY(!check(kPosition, other).accepted); // out of standard for that site
        QVERIFY(!check(kPosition, renamedMember).accepted);
        QVERIFY(!check(kPosition, renamedStatus).accepted);
        const std::string oa = frameHeader("Protocol", R"("Open-Autonomy")");
        Outcome o = check(oa, other);
        QVERIFY2(o.accepted && o.problem.empty(), o.problem.c_str());
    }

    // 2b. A configured Protocol (§4.2) with a backslash, a control character or a broken UTF-8 byte: the raw
    // text must still not be taken for the decoded string (the DOM unescapes, or rejects the frame).
    void oddConfiguredProtocols() {
        for (const std::string protocol : {"ISO\\23725", "ISO\\u0032",
                                           "ISO\x01"
                                           "23725",
                                           "ISO\xC3", "ISO\xC3\xA9"}) {
            InferredRules rules;
            rules.protocol = protocol;
            std::string escaped;
            for (char c : protocol)
                escaped += c == '\\' ? std::string("\\\\") : std::string(1, c);
            for (const std::string& value : {protocol, escaped}) {
                const std::string text = frameHeader("Protocol", "\"" + value + "\"");
                Outcome o = check(text, rules);
                QVERIFY2(o.problem.empty(), (o.problem + "\n" + text).c_str());
                QVERIFY2(!o.accepted, text.c_str());
            }
        }
    }

    // 3. Seeded mutation fuzz: flips, insertions, deletions, truncations and duplicated slices of clean
    // frames. The fast path never crashes and never disagrees with the DOM path when it accepts.
    void mutationFuzz() {
        const auto t0 = std::chrono::steady_clock::now();
        Fields nulls = pose();
        for (const char* k : {"Latitude", "Elevation", "Speed"})
            nulls = with(nulls, k, "null");
        const std::vector<std::string> seeds = {kPosition, spaced(kPosition), frame(header(), nulls),
                                                kNoteExample5};
        const std::string alphabet = "0123456789-+.eE\"{}[],: \t\n\r\\nulltrufasZTx/";
        std::mt19937 rng(23725);
        auto below = [&](std::size_t n) { return n == 0 ? std::size_t(0) : std::size_t(rng() % n); };
        int accepted = 0, declined = 0;
        for (int i = 0; i < 20000; ++i) {
            std::string s = seeds[below(seeds.size())];
            const int edits = 1 + int(below(3));
            for (int e = 0; e < edits; ++e) {
                const std::size_t pos = below(s.size() + 1);
                const char c = rng() % 4 == 0 ? char(rng() % 256) : alphabet[below(alphabet.size())];
                switch (rng() % 8) {
                case 0:
                case 1: { // change a digit: mostly still a clean frame, so the accepting path is fuzzed too
                    const std::size_t d = s.find_first_of("0123456789", pos);
                    if (d != std::string::npos)
                        s[d] = char('0' + below(10));
                    break;
                }
                case 2: // flip a byte
                    if (pos < s.size())
                        s[pos] = c;
                    break;
                case 3:
                    s.insert(pos, 1, c);
                    break;
                case 4:
                    s.erase(pos, 1 + below(3));
                    break;
                case 5:
                    s.resize(pos);
                    break;
                case 6: // whitespace (RFC 8259 §2 and not)
                    s.insert(pos, 1, " \t\n\r\f\v"[below(6)]);
                    break;
                default: { // duplicate a slice elsewhere
                    const std::size_t from = below(s.size()), len = 1 + below(24);
                    s.insert(pos, s.substr(from, len));
                }
                }
            }
            Outcome o = check(s, defaultInferredRules());
            QVERIFY2(o.problem.empty(), (o.problem + "\n" + s).c_str());
            (o.accepted ? accepted : declined) += 1;
        }
        const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        qInfo("fuzz: %d accepted, %d declined, %.2f s", accepted, declined, secs);
        QVERIFY(accepted >= 1000); // the accepting path is exercised too, not only the declines
        QVERIFY(declined >= 1000);
    }
};

QTEST_GUILESS_MAIN(TestIsoPositionFast)
#include "test_iso_position_fast.moc"
