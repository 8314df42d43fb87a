#pragma once
// Test support: JAUS UDP settings on loopback only (DEVELOPERS.md: bind 127.0.0.1, an ephemeral unicast
// port, the multicast group sent on 127.0.0.1 with TTL 0), for the console and the tests' own peers.
#include "protocols/jaus/JausConfig.h"
#include "protocols/jaus/JausTypes.h"

#include <cstdint>

namespace jaustest {

inline ocu::jaus::TransportSettings loopback(std::uint16_t multicastPort) {
    ocu::jaus::TransportSettings t;
    t.bindAddress = "127.0.0.1";
    t.port = 0;
    t.multicastGroup = "239.255.0.1";
    t.multicastPort = multicastPort;
    t.multicastTtl = 0;
    t.interfaceAddress = "127.0.0.1";
    return t;
}

// A console's listener for tests that read the stack's state through snapshot() only.
struct QuietListener : ocu::jaus::JausListener {
    void onSubsystemChanged(const ocu::jaus::SubsystemSnapshot&) override {}
    void onEvent(const ocu::jaus::JausEvent&) override {}
};

} // namespace jaustest
