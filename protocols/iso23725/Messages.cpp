// The codec's value-level helpers declared in Messages.h: the enumerations of the catalogue, timestamps and
// GUIDs as they appear on the wire, member names. Decoding is in MessageDecoder.cpp, encoding in
// MessageEncoder.cpp.
#include "protocols/iso23725/Messages.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <random>

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

// ---------------------------------------------------------------- member names

namespace {

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

} // namespace ocu::iso23725
