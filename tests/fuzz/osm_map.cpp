// Fuzz harness: the OSM map XML of the ISO 23725 map service (MapModel: chunked OSM 0.6 documents, ID and
// reference rules, road/lane/area shapes, connectivity). The input holds the chunks separated by NUL bytes.
// Invariant: a map that parses is written back (writeOsmChunks) and parses again to the same nodes and ways.
#include "protocols/iso23725/MapModel.h"
#include "tests/fuzz/FuzzSupport.h"

using namespace ocu;
using namespace ocu::iso23725;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ocu::fuzz::quietLogs();
    std::string_view text(reinterpret_cast<const char*>(data), data ? size : 0);
    std::vector<std::string> chunks;
    for (std::size_t pos = 0; pos <= text.size() && chunks.size() < 16;) {
        std::size_t end = text.find('\0', pos);
        if (end == std::string_view::npos)
            end = text.size();
        chunks.emplace_back(text.substr(pos, end - pos));
        pos = end + 1;
    }
    auto map = parseMapDocument(chunks);
    if (!map)
        return 0;
    auto again = parseMapDocument(writeOsmChunks(*map, 64, 1));
    OCU_FUZZ_CHECK(again.ok());
    OCU_FUZZ_CHECK(again->nodes.size() == map->nodes.size());
    OCU_FUZZ_CHECK(again->ways.size() == map->ways.size());
    return 0;
}
