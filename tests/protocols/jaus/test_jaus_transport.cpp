// JudpTransport over real loopback sockets: multicast for unknown destinations with an ACK request and
// endpoint learning from the ACK (jaus-wire.md §2.2), unicast replies, static table, fragmentation of a
// large message across datagrams, and JTCP client/server with route learning.
#include "tests/support/IoContextWaits.h"
#include <QtTest>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/udp.hpp>

#include <atomic>
#include <set>
#include <thread>

#include "protocols/common/Log.h"
#include "protocols/common/Udp.h"
#include "protocols/jaus/JudpTransport.h"
#include "protocols/jaus/Messages.h"
#include "tests/support/JausLoopback.h"

using namespace ocu;
using namespace ocu::jaus;

namespace {

struct Rx {
    JausId src, dst;
    Bytes payload;
};

struct Node {
    Node(boost::asio::io_context& io, TransportSettings s, JausId id)
        : self(id), transport(io, std::move(s), counters, SteadyClock::instance(), "test.jaus") {
        transport.setLocalIds([this](const JausId& x) { return x == self; });
        transport.setHandlers(
            [this](const JausId& s, const JausId& d, ByteSpan p) {
                got.push_back({s, d, Bytes(p.begin(), p.end())});
            },
            {});
    }
    JausId self;
    Counters counters;
    JudpTransport transport;
    std::vector<Rx> got;
};

using ocu::testing::runUntil;

} // namespace

class TestJausTransport : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { setLogThreshold(LogLevel::Warning); }

    // The STOP ALL fast path: a datagram planned on the io thread and sent from another thread
    // while the io thread sends too. Every datagram arrives byte-exact (the planned one equals what send()
    // encodes with its sequence number) and the source's sequence numbers stay unique and consecutive.
    void plannedSendFromAnotherThreadIsByteExactAndSharesTheSequence() {
        namespace asio = boost::asio;
        boost::asio::io_context io;
        asio::ip::udp::socket peer(io, asio::ip::udp::endpoint(asio::ip::make_address_v4("127.0.0.1"), 0));
        peer.set_option(asio::socket_base::receive_buffer_size(4 << 20));
        const std::uint16_t mc = findFreeUdpPort();
        auto s = jaustest::loopback(mc);
        const JausId vehicle{126, 1, 1};
        s.staticEndpoints.push_back(
            {JausId{126, 255, 255}, "127.0.0.1", peer.local_endpoint().port(), false});
        Node ocu(io, s, JausId{200, 1, 1});
        ocu.transport.open();
        const Bytes stop = encodeU16(msg::SetEmergency, std::uint16_t(EmergencyCode::Safety));
        const SendOptions safety{Priority::Safety, false};
        auto planned = ocu.transport.plan(ocu.self, vehicle, stop, safety);
        QVERIFY(planned);
        QCOMPARE(planned->to.size(), std::size_t(1));
        QCOMPARE(planned->to[0].port(), peer.local_endpoint().port());
        // Nothing is planned where send() would do more than one plain datagram.
        QVERIFY(!ocu.transport.plan(ocu.self, JausId{77, 1, 1}, stop, safety));  // unknown address
        QVERIFY(!ocu.transport.plan(ocu.self, vehicle, Bytes(5000, 0), safety)); // fragmented

        constexpr int kEach = 300;
        std::vector<Bytes> got;
        std::thread rx([&] {
            std::array<std::uint8_t, 2048> buf{};
            peer.non_blocking(true);
            const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
            while (int(got.size()) < 2 * kEach && std::chrono::steady_clock::now() < end) {
                boost::system::error_code ec;
                const std::size_t n = peer.receive(asio::buffer(buf), 0, ec);
                if (ec == asio::error::would_block) {
                    std::this_thread::sleep_for(std::chrono::microseconds(200));
                    continue;
                }
                if (!ec)
                    got.emplace_back(buf.begin(), buf.begin() + long(n));
            }
        });
        std::atomic<int> fastFailures{0};
        std::thread fast([&] {
            for (int i = 0; i < kEach; ++i)
                if (!ocu.transport.sendPlanned(ocu.self, *planned).empty())
                    ++fastFailures;
        });
        for (int i = 0; i < kEach; ++i) // this thread plays the io thread
            QVERIFY(ocu.transport.send(ocu.self, vehicle, encodeEmpty(msg::QueryStatus), {}).empty());
        fast.join();
        rx.join();
        QCOMPARE(fastFailures.load(), 0);
        QCOMPARE(int(got.size()), 2 * kEach);
        std::set<std::uint16_t> seqs;
        int stops = 0;
        for (const Bytes& d : got) {
            auto dec = decodeDatagram(d);
            QVERIFY(dec);
            QCOMPARE(dec->messages.size(), std::size_t(1));
            const JudpMessage& m = dec->messages[0];
            QCOMPARE(m.header.source, ocu.self);
            QVERIFY(seqs.insert(m.header.sequence).second); // unique
            if (m.messageId() == msg::SetEmergency) {
                ++stops;
                JudpHeader h;
                h.priority = Priority::Safety;
                h.source = ocu.self;
                h.destination = vehicle;
                h.sequence = m.header.sequence;
                QCOMPARE(d, encodeDatagram(h, stop)); // byte-exact, as send() would have encoded it
            }
        }
        QCOMPARE(stops, kEach);
        QCOMPARE(*seqs.begin(), std::uint16_t(0));
        QCOMPARE(*seqs.rbegin(), std::uint16_t(2 * kEach - 1)); // consecutive: no number lost or reused
        QCOMPARE(ocu.counters.get("tx.planned"), std::uint64_t(kEach));
        // Closed: the fast path refuses instead of writing to a closed descriptor.
        ocu.transport.close();
        QVERIFY(!ocu.transport.sendPlanned(ocu.self, *planned).empty());
    }

    void unknownDestinationGoesMulticastAndAckTeachesTheAddress() {
        boost::asio::io_context io;
        const std::uint16_t mc = findFreeUdpPort();
        Node a(io, jaustest::loopback(mc), JausId{126, 1, 1});
        Node b(io, jaustest::loopback(mc), JausId{200, 1, 1});
        a.transport.open();
        b.transport.open();
        b.transport.send(b.self, a.self, encodeEmpty(msg::QueryStatus), {});
        QVERIFY(runUntil(io, [&] { return a.got.size() == 1; }));
        QCOMPARE(b.counters.get("tx.unknown_destination"), std::uint64_t(1));
        QVERIFY(runUntil(io, [&] { return b.counters.get("rx.ack") == 1; }));
        QCOMPARE(a.counters.get("tx.ack"), std::uint64_t(1));
        QCOMPARE(b.transport.endpointOf(a.self), "127.0.0.1:" + std::to_string(a.transport.localPort()));
        // A replies by unicast to the port B sent from (learned), B's next message is unicast too.
        a.transport.send(a.self, b.self, encode(ReportStatus{ManagementState::Ready, 0}), {});
        QVERIFY(runUntil(io, [&] { return b.got.size() == 1; }));
        QCOMPARE(a.counters.get("tx.unknown_destination"), std::uint64_t(0));
        b.transport.send(b.self, a.self, encodeEmpty(msg::QueryStatus), {});
        QVERIFY(runUntil(io, [&] { return a.got.size() == 2; }));
        QCOMPARE(b.counters.get("tx.unknown_destination"), std::uint64_t(1));
        // Broadcasts reach everybody on the group (and loop back to the sender, which filters by ID
        // upstream).
        b.transport.send(b.self, kBroadcastAll, encode(QueryIdentification{}), {});
        QVERIFY(runUntil(io, [&] { return a.got.size() == 3; }));
        QCOMPARE(a.got.back().dst, kBroadcastAll);
    }

    // Every source ID a datagram named became a learned address for good; a peer inventing IDs
    // grew the table without end. Bounded, and the addresses learned first (the real vehicles) stay.
    void learnedAddressesAreBounded() {
        boost::asio::io_context io;
        const std::uint16_t mc = findFreeUdpPort();
        Node a(io, jaustest::loopback(mc), JausId{200, 1, 1});
        Node vehicle(io, jaustest::loopback(mc), JausId{126, 1, 1});
        a.transport.open();
        vehicle.transport.open();
        vehicle.transport.send(vehicle.self, a.self, encode(ReportStatus{ManagementState::Ready, 0}), {});
        QVERIFY(runUntil(io, [&] { return a.got.size() == 1; }));
        const std::string vehicleAt = a.transport.endpointOf(vehicle.self);
        QVERIFY(!vehicleAt.empty());
        boost::asio::ip::udp::socket raw(
            io, boost::asio::ip::udp::endpoint(boost::asio::ip::make_address("127.0.0.1"), 0));
        const boost::asio::ip::udp::endpoint to(boost::asio::ip::make_address("127.0.0.1"),
                                                a.transport.localPort());
        const std::size_t cap = JudpTransport::kMaxLearnedAddresses, extra = 50;
        const auto datagrams0 = a.counters.get("rx.datagrams");
        for (std::size_t i = 0; i < cap + extra; ++i) {
            JudpHeader h;
            h.destination = a.self;
            h.source = JausId{std::uint16_t(1000 + i), 1, 1};
            raw.send_to(
                boost::asio::buffer(encodeDatagram(h, encode(ReportStatus{ManagementState::Ready, 0}))), to);
            if (i % 64 ==
                63) // let the receiver keep up (the socket buffer is large, but the machine is shared)
                QVERIFY(runUntil(io, [&] { return a.counters.get("rx.datagrams") - datagrams0 == i + 1; }));
        }
        QVERIFY(runUntil(io, [&] { return a.counters.get("rx.datagrams") - datagrams0 == cap + extra; }));
        QCOMPARE(a.transport.learnedAddresses(), cap);
        // The vehicle holds one entry, so cap - 1 invented IDs were learned and the rest not.
        QCOMPARE(a.counters.get("rx.limited.learned_address"), std::uint64_t(extra + 1));
        QCOMPARE(a.transport.endpointOf(vehicle.self), vehicleAt); // the real vehicle is still known
    }

    void staticTableAvoidsTheBroadcast() {
        boost::asio::io_context io;
        const std::uint16_t mc = findFreeUdpPort();
        Node a(io, jaustest::loopback(mc), JausId{126, 1, 1});
        a.transport.open();
        auto s = jaustest::loopback(mc);
        s.staticEndpoints.push_back({JausId{126, 255, 255}, "127.0.0.1", a.transport.localPort(), false});
        Node b(io, s, JausId{200, 1, 1});
        b.transport.open();
        b.transport.send(b.self, JausId{126, 3, 1}, encodeEmpty(msg::QueryStatus), {});
        QVERIFY(runUntil(io, [&] { return a.got.size() == 1; }));
        QCOMPARE(b.counters.get("tx.unknown_destination"), std::uint64_t(0));
    }

    void largeMessagesAreFragmentedAndReassembled() {
        boost::asio::io_context io;
        const std::uint16_t mc = findFreeUdpPort();
        Node a(io, jaustest::loopback(mc), JausId{126, 1, 1});
        Node b(io, jaustest::loopback(mc), JausId{200, 1, 1});
        a.transport.open();
        b.transport.open();
        b.transport.send(b.self, a.self, encodeEmpty(msg::QueryHeartbeatPulse), {});
        QVERIFY(runUntil(io, [&] { return a.got.size() == 1; }));
        ReportServices big;
        for (int n = 0; n < 40; ++n) {
            NodeServices node{std::uint8_t(n + 1), {}};
            for (int c = 0; c < 5; ++c)
                node.components.push_back(
                    {std::uint8_t(c + 1),
                     0,
                     {{"urn:jaus:jss:core:Liveness", 1, 1}, {"urn:jaus:jss:core:Events", 1, 1}}});
            big.nodes.push_back(node);
        }
        const Bytes payload = encode(big);
        QVERIFY(payload.size() > 2 * kMaxFragmentPayload);
        a.transport.send(a.self, b.self, payload, {});
        // (b also hears its own first message looped back by multicast: the stack filters src == self.)
        auto isServices = [](const Rx& r) { return peekMessageId(r.payload) == msg::ReportServices; };
        QVERIFY(runUntil(io, [&] { return std::any_of(b.got.begin(), b.got.end(), isServices); }));
        QCOMPARE(std::find_if(b.got.begin(), b.got.end(), isServices)->payload, payload);
        QVERIFY(a.counters.get("tx.datagrams") >= 3);
    }

    void jtcpClientAndServer() {
        boost::asio::io_context io;
        const std::uint16_t mc = findFreeUdpPort();
        auto sa = jaustest::loopback(mc);
        sa.jtcpServer = true;
        sa.jtcpPort = 0;
        Node a(io, sa, JausId{126, 1, 1});
        a.transport.open();
        QVERIFY(a.transport.localTcpPort() != 0);
        auto sb = jaustest::loopback(mc);
        sb.staticEndpoints.push_back({JausId{126, 255, 255}, "127.0.0.1", a.transport.localTcpPort(), true});
        Node b(io, sb, JausId{200, 1, 1});
        b.transport.open();
        b.transport.send(b.self, a.self, encodeU8(msg::RequestControl, 205), {});
        b.transport.send(b.self, a.self, encodeEmpty(msg::QueryStatus), {});
        QVERIFY(runUntil(io, [&] { return a.got.size() == 2; }));
        QCOMPARE(a.counters.get("rx.jtcp.messages"), std::uint64_t(2));
        QCOMPARE(a.counters.get("rx.datagrams"), std::uint64_t(0));
        QCOMPARE(peekMessageId(a.got[0].payload), msg::RequestControl);
        // The server answers over the connection it learned.
        a.transport.send(a.self, b.self, encodeU8(msg::ConfirmControl, 0), {});
        QVERIFY(runUntil(io, [&] { return b.got.size() == 1; }));
        QCOMPARE(b.counters.get("rx.jtcp.messages"), std::uint64_t(1));
        QVERIFY(a.transport.endpointOf(b.self).rfind("tcp:", 0) == 0);
    }
};

QTEST_GUILESS_MAIN(TestJausTransport)
#include "test_jaus_transport.moc"
