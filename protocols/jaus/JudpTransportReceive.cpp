// Receiving JUDP datagrams: address learning, ACK answers, fragment reassembly, delivery.
#include "protocols/jaus/JudpTransport.h"

#include "protocols/common/Log.h"
#include "protocols/jaus/JudpTransportSockets.h"

namespace ocu::jaus {

namespace asio = boost::asio;

void JudpTransport::startReceive(Receiver& r) {
    r.socket.async_receive_from(asio::buffer(r.buffer), r.from,
                                [this, &r](boost::system::error_code ec, std::size_t n) {
                                    if (ec == asio::error::operation_aborted || !m_open)
                                        return;
                                    if (!ec)
                                        onDatagram(ByteSpan(r.buffer.data(), n), r.from);
                                    else
                                        m_counters.add("rx.socket_errors");
                                    startReceive(r);
                                });
}

void JudpTransport::onDatagram(ByteSpan data, const Endpoint& from) {
    m_counters.add("rx.datagrams");
    if (m_onRaw)
        m_onRaw(data, from.address().to_string() + ":" + std::to_string(from.port()));
    auto reject = [&](const std::string& err) {
        const std::string reason = rejectReason(err);
        m_counters.add("rx.rejected." + reason);
        // At most one log line per reason and second: a broken or hostile peer must not flood the log.
        const TimePoint t = m_clock.now();
        auto& last = m_lastLog[reason];
        if (last == TimePoint{} || t - last >= std::chrono::seconds(1)) {
            last = t;
            logWarning(m_log, "datagram from " + from.address().to_string() + ":" +
                                  std::to_string(from.port()) + " rejected: " + err);
        }
        if (m_onError)
            m_onError(reason, err);
    };
    auto d = decodeDatagram(data);
    if (!d)
        return reject(d.error());
    if (!d->error.empty())
        reject(d->error);
    const TimePoint now = m_clock.now();
    if (auto n = m_reassembler.expire(now))
        m_counters.add("rx.rejected.fragment_timeout", n);
    for (auto& m : d->messages) {
        const JudpHeader& h = m.header;
        // Learn where this JAUS ID lives (AEP-4818 §4.7.2: dynamic address list from every message).
        if (!h.source.isBroadcast() && h.source.subsystem != 0) {
            if (auto known = m_learned.find(h.source.value()); known != m_learned.end())
                known->second = from;
            else if (m_learned.size() < kMaxLearnedAddresses)
                m_learned.emplace(h.source.value(), from);
            else
                m_counters.add("rx.limited.learned_address");
        }
        if (h.ackNak == AckNak::Ack || h.ackNak == AckNak::Nak) {
            m_counters.add(h.ackNak == AckNak::Ack ? "rx.ack" : "rx.nak");
            continue;
        }
        // Answer ACK requests even when received by multicast: that is how a JTS peer finds us (§2.2).
        if (h.ackNak == AckNak::Request && m_isLocal && !h.destination.isBroadcast() &&
            m_isLocal(h.destination)) {
            rawSend(encodeDatagram(makeAckHeader(h), ByteSpan{}), from);
            m_counters.add("tx.ack");
        }
        deliver(std::move(m), now, reject);
    }
}

void JudpTransport::deliver(JudpMessage m, TimePoint now,
                            const std::function<void(const std::string&)>& reject) {
    const std::uint64_t evictedBefore = m_reassembler.evicted();
    auto r = m_reassembler.feed(std::move(m), now);
    if (m_reassembler.evicted() != evictedBefore) // a partial set made room (per-peer or total bound)
        m_counters.add("rx.rejected.fragment_evicted", m_reassembler.evicted() - evictedBefore);
    if (!r) {
        reject(r.error());
        return;
    }
    if (!*r)
        return;
    const JudpMessage& full = **r;
    if (full.payload.size() < 2) {
        reject("short: message without a message ID");
        return;
    }
    if (m_onMessage)
        m_onMessage(full.header.source, full.header.destination, full.payload);
}

} // namespace ocu::jaus
