#pragma once
// The foreign vehicle's Enhanced Access Control 1.1 (urn:jaus:jss:iop:EnhancedAccessControl, written from
// jaus-autonomy.md §8: the FK-CORE EnhancedAccessControl_V1 rules and FKIE's server as the note describes
// them; its own decoding, nothing from protocols/ or sim/). The vehicle only queues, relays and times out;
// the holder decides:
//  * RequestHandoff from a console while nobody holds the vehicle: DENIED (ID 255), the console is to send
//    RequestControl instead; from the holder itself: GRANTED; below the default authority:
//    INSUFFICIENT_AUTHORITY; otherwise queued (or updated) and answered QUEUED with its queue ID, and the
//    whole queue goes to the holder as RequestReleaseControl.
//  * A request not re-asserted within the request timeout is dropped (DENIED); one the holder does not
//    answer within the decision timeout is answered TIMEOUT; RemoveHandoffRequest is answered DENIED. Each
//    change of the queue goes to the holder again (an empty queue too).
//  * ConfirmReleaseControl from the holder: GRANTED sends RejectControl(CONTROL_RELEASED) to the holder,
//    leaves the vehicle uncontrolled and answers the requester GRANTED (it must then send RequestControl);
//    DENIED answers DENIED; WAIT keeps the request queued, restarts its decision time and answers the
//    requester QUEUED (or FKIE's private code 7, by option).
// Dialect options: answers late, a policy that denies every request without asking the holder.
#include "tests/protocols/jaus/foreign/ForeignBytes.h"

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace foreign {

struct HandoffOptions {
    std::uint8_t requestTimeoutS = 5;   // ReportEnhancedTimeout (AEP-4818 §6.3: 5 s)
    std::uint8_t decisionTimeoutS = 60; // ReportHandoffTimeout (60 s)
    std::uint8_t defaultAuthority = 0;  // requests below it: INSUFFICIENT_AUTHORITY
    int answerDelayMs = 0;              // every answer of the service this much later (a busy stack)
    bool denyAll = false;        // a vehicle policy: every request DENIED (ID 255), the holder not asked
    std::uint8_t waitAnswer = 4; // what the requester hears after the holder's WAIT: 4 QUEUED, 7 FKIE
};

class EnhancedAccessControl {
public:
    using Clock = std::chrono::steady_clock;
    // Sends a payload (message ID + body) to a JAUS ID (u32) from the service's component.
    using Send = std::function<void(std::uint32_t to, const Buf& payload)>;
    // controller / controllerAuthority: the vehicle's access control.
    EnhancedAccessControl(HandoffOptions options, std::uint32_t& controller,
                          std::uint8_t& controllerAuthority, Send send)
        : m_opt(options), m_controller(controller), m_authority(controllerAuthority),
          m_send(std::move(send)) {}

    // A message to the service's component: true when it is the service's.
    bool handle(std::uint16_t mid, std::uint32_t src, const std::uint8_t* body, std::size_t len);
    // Timeouts and late answers (called every 50 ms).
    void tick(Clock::time_point now);
    // Requests in the queue; handoffs granted so far.
    std::size_t queued() const { return m_queue.size(); }
    int granted() const { return m_granted; }

private:
    struct Entry {
        std::uint8_t id = 0;
        std::uint32_t requester = 0;
        std::uint8_t authority = 0;
        std::string explanation;
        Clock::time_point asserted{}, asked{};
    };
    void answer(std::uint32_t to, std::uint8_t id, std::uint8_t code);
    void post(std::uint32_t to, Buf payload);
    void forwardQueue(); // RequestReleaseControl with the whole queue to the holder
    void onRequest(std::uint32_t src, const std::uint8_t* body, std::size_t len);
    void onRemove(std::uint32_t src, const std::uint8_t* body, std::size_t len);
    void onConfirmRelease(std::uint32_t src, const std::uint8_t* body, std::size_t len);

    HandoffOptions m_opt;
    std::uint32_t& m_controller;
    std::uint8_t& m_authority;
    Send m_send;
    std::vector<Entry> m_queue;
    struct Late {
        Clock::time_point due;
        std::uint32_t to;
        Buf payload;
    };
    std::vector<Late> m_late;
    std::uint8_t m_nextId = 1;
    int m_granted = 0;
};

} // namespace foreign
