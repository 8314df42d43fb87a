#pragma once
// OSYRIS station configuration: the §7 parameters plus the OCU's own (station index, SQLite file,
// geo-referencing, pass-count grid). Keys are documented in docs/osyris.md.
#include "protocols/osyris/OsyrisCodec.h"
#include "protocols/osyris/PassCountGrid.h"

#include "protocols/common/Result.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace ocu {
class ConfigObject;
}

namespace ocu::osyris {

enum class Addressing { Multicast, Broadcast, Unicast };

// Active bitmap (§7).
constexpr int kActiveSendPositions = 1;
constexpr int kActiveAnswerRequests = 2;
constexpr int kActiveAskRequests = 4;
constexpr int kActiveDisplayMessages = 8;

struct OsyrisConfig {
    Addressing addressing = Addressing::Multicast;
    std::string group = "233.1.1.1";          // multicast group, broadcast address or unicast peer
    std::uint16_t port = 50010;               // IANA dynamic range 49152-65535
    std::string interfaceAddress = "0.0.0.0"; // interface for IGMP join and outbound multicast
    std::vector<std::string> unicastPeers;    // extra "ip:port" destinations (unicast testing)
    int multicastTtl = 1;                     // §7: TTL scoping 1
    int beatMs = 100;                         // Beat
    int minLen = 0;                           // MinLen (bytes queued before a flush)
    int maxLen = 1400;                        // MaxLen (datagram size)
    int sendPeriodMs = 5000;                  // SendPeriod
    std::uint32_t tailPos = 0;                // TailPos; 0 = all
    int ttlBeats = 20;                        // TTL of requests/responses in beats
    int active = 15;                          // Active bitmap; OCU default also displays messages
    double maxRange = 0;                      // MaxRange [m]; 0 = unlimited
    Checksum checksum = Checksum::None;
    std::uint8_t stationIndex = 200;                    // this station's Idx (0..253)
    std::string sqlitePath;                             // empty = a private temporary database
    double originLat = 0, originLon = 0, originAlt = 0; // worksite centre (local x/y are ENU around it)
    PassCountSettings passCount;
    std::map<std::uint8_t, std::string> machineNames; // Idx -> display name (the wire carries only Idx)
    std::map<std::uint8_t, std::string> machineTypes; // Idx -> "roller", "paver", "relay", ... (free text)
    // Engine tuning (not in §7)
    int lossWaitBeats = 3; // wait before requesting a gap (§5: until the loss can be estimated)
    int maxNakSlots = 256; // slots per NAK
    // NAK rounds (after NORM, RFC 5740 §5.5.1): a station sends its NAKs in rounds at least nakRoundBeats
    // apart, every gap due by then in one datagram (at most maxNaksPerBeat NAK messages), after a random
    // back-off of up to nakBackoffBeats (truncated exponential over the number of stations heard, RFC 5740
    // §5.5.1) during which overheard NAKs, NCFs and repairs suppress the same wishes.
    int maxNaksPerBeat = 64;
    int nakRoundBeats = 30;
    int nakBackoffBeats = 4;
    std::uint64_t nakRoundSlots = 64; // this many slots due start a round at once (late join, long outages)
    int maxRetxPerBeat = 200;         // positions re-sent per beat
    int maxDatagramsPerBeat = 16;
    int answerHoldBeats = 3; // a slot re-sent this recently is not re-sent for another NAK
    // Ribbon store bounds (docs/reliability.md "Bounds"): positions of another station beyond
    // these are refused (rx.rejected.ribbon_full / store_full, a warning a minute) and their gaps are not
    // NAKed; nothing held is ever dropped (it is in the pass counts already). 2^22 slots are 116 h of one
    // machine at 10 Hz, the widest range an ALIVE may announce; 2^24 = four such ribbons.
    std::uint64_t maxRibbonSlots = std::uint64_t(1) << 22;
    std::uint64_t maxStoreSlots = std::uint64_t(1) << 24;
    // Late join and gaps: the slots a ribbon's pass counting waits for are given up as
    // unobtainable (counted without, their cells marked incomplete) once this station asked for them
    // gapGiveUpNaks times, or gapGiveUpMs after counting first stopped at them, whichever comes first
    // (0 = that rule off).
    int gapGiveUpNaks = 5;
    int gapGiveUpMs = 120000;
    // Pass-count snapshots for the GUI: at most one per this many ms (and per Beat), only after a change.
    int passCountPublishMs = 100;
};

// Reads the site configuration's "osyris" object strictly (calls section.finish()).
OsyrisConfig parseOsyrisConfig(ConfigObject& section);
// Imports the §7 XML configuration file (elements or attributes named as in the table), over base.
Result<OsyrisConfig> importOsyrisXml(const std::string& xmlText, OsyrisConfig base = {});
Result<OsyrisConfig> importOsyrisXmlFile(const std::string& path, OsyrisConfig base = {});

} // namespace ocu::osyris
