#include "sim/jaus/UgvMessageTable.h"

#include <stdexcept>
#include <string>

#include "protocols/jaus/Messages.h"

namespace ocu::sim {

using jaus::JausId;

void UgvMessageTable::onCommand(std::uint16_t id, std::optional<JausId> component, CommandHandler handler) {
    add(id, Entry{component, std::move(handler), {}});
}

void UgvMessageTable::onQuery(std::uint16_t id, std::optional<JausId> component, QueryHandler handler) {
    add(id, Entry{component, {}, std::move(handler)});
}

void UgvMessageTable::add(std::uint16_t id, Entry entry) {
    if (!m_entries.emplace(id, std::move(entry)).second)
        throw std::logic_error(std::string("two simulated UGV services handle ") + jaus::messageName(id));
}

bool UgvMessageTable::serves(const JausId& component, std::uint16_t id) const {
    auto it = m_entries.find(id);
    return it != m_entries.end() && (!it->second.component || *it->second.component == component);
}

std::optional<Bytes> UgvMessageTable::handle(const JausId& component, const JausId& source, std::uint16_t id,
                                             ByteSpan payload) const {
    auto it = m_entries.find(id);
    if (it == m_entries.end())
        return std::nullopt;
    if (it->second.command) {
        it->second.command(component, source, payload);
        return std::nullopt;
    }
    return it->second.query(component, payload);
}

std::optional<Bytes> UgvMessageTable::report(const JausId& component, ByteSpan query) const {
    auto it = m_entries.find(jaus::peekMessageId(query));
    if (it == m_entries.end() || !it->second.query)
        return std::nullopt;
    return it->second.query(component, query);
}

} // namespace ocu::sim
