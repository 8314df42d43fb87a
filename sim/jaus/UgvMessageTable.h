#pragma once
// Which of the simulated UGV's services handles which JAUS message, and on which component: a dispatch table
// keyed by message ID, filled by the services themselves (UgvCore's register* functions), as the console's
// MessageTable is filled by its client services. Two kinds of entries: commands (acted on; the handler sends
// any answer) and queries (answered by a report, which also feeds the events service).
#include <cstdint>
#include <functional>
#include <optional>
#include <unordered_map>

#include "protocols/common/Bytes.h"
#include "protocols/jaus/JudpCodec.h"

namespace ocu::sim {

class UgvMessageTable {
public:
    using CommandHandler =
        std::function<void(const jaus::JausId& component, const jaus::JausId& source, ByteSpan payload)>;
    using QueryHandler = std::function<std::optional<Bytes>(const jaus::JausId& component, ByteSpan query)>;

    // `component`: the one component offering the service; nullopt for services every component offers
    // (Events, Liveness). Each ID has one entry: a second registration throws std::logic_error.
    void onCommand(std::uint16_t id, std::optional<jaus::JausId> component, CommandHandler handler);
    void onQuery(std::uint16_t id, std::optional<jaus::JausId> component, QueryHandler handler);

    // True when `component` offers the service that handles message `id`.
    bool serves(const jaus::JausId& component, std::uint16_t id) const;
    // A command: runs its handler and returns nullopt. A query: returns its report (nullopt when the query
    // has no answer). Call only for an ID `component` serves.
    std::optional<Bytes> handle(const jaus::JausId& component, const jaus::JausId& source, std::uint16_t id,
                                ByteSpan payload) const;
    // The report answering `query` (its ID read from the payload); nullopt for commands and unknown IDs.
    std::optional<Bytes> report(const jaus::JausId& component, ByteSpan query) const;

private:
    struct Entry {
        std::optional<jaus::JausId> component;
        CommandHandler command;
        QueryHandler query;
    };
    void add(std::uint16_t id, Entry entry);

    std::unordered_map<std::uint16_t, Entry> m_entries;
};

} // namespace ocu::sim
