#include "tests/protocols/jaus/foreign/ForeignWaypointList.h"

#include <algorithm>
#include <cmath>

namespace foreign {

namespace {

enum : std::uint16_t {
    SetElement = 0x041A,
    DeleteElement = 0x041B,
    ConfirmElementRequest = 0x041C,
    RejectElementRequest = 0x041D,
    QueryElement = 0x241A,
    QueryElementList = 0x241B,
    QueryElementCount = 0x241C,
    ReportElement = 0x441A,
    ReportElementList = 0x441B,
    ReportElementCount = 0x441C,
    ExecuteList = 0x041E,
    QueryActiveElement = 0x241E,
    ReportActiveElement = 0x441E,
    QueryTravelSpeed = 0x240A,
    ReportTravelSpeed = 0x440A,
    SetLocalWaypoint = 0x040D,
};

double unscale(std::uint32_t v, double lo, double hi, double maxRaw) {
    return lo + double(v) * (hi - lo) / maxRaw;
}
Buf withId(std::uint16_t id) {
    Buf b;
    put16(b, id);
    return b;
}

} // namespace

bool WaypointListDriver::handle(std::uint16_t mid, std::uint32_t src, const std::uint8_t* body,
                                std::size_t len, std::vector<Buf>& replies) {
    switch (mid) {
    case SetElement: {
        if (len < 2 || src != m_controller)
            return true;
        const std::uint8_t req = body[0], n = body[1];
        auto reject = [&](std::uint8_t code) {
            Buf b = withId(RejectElementRequest);
            put8(b, req);
            put8(b, code);
            replies.push_back(b);
        };
        if (m_opt.rejectSetElementCode)
            return reject(m_opt.rejectSetElementCode), true;
        auto list = m_list;
        std::size_t i = 2;
        std::vector<std::uint16_t> added;
        for (int k = 0; k < n; ++k) {
            // UID, Prev, Next, format u8, length u16, data (a whole SetLocalWaypoint message).
            if (i + 9 > len)
                return reject(7), true;
            const std::uint16_t uid = get16(body + i), prev = get16(body + i + 2), next = get16(body + i + 4);
            const std::size_t dlen = get16(body + i + 7);
            const std::uint8_t* d = body + i + 9;
            if (i + 9 + dlen > len || dlen < 11 || get16(d) != SetLocalWaypoint || uid == 0 || uid == 0xFFFF)
                return reject(7), true; // JAUS++ answers every failure with code 7
            Element e;
            e.prev = prev;
            e.next = next;
            const std::uint8_t pv = d[2];
            e.x = unscale(get32(d + 3), -100000, 100000, 4294967295.0);
            e.y = unscale(get32(d + 7), -100000, 100000, 4294967295.0);
            std::size_t at =
                11 + ((pv & 1) ? 4 : 0) + ((pv & 2) ? 2 : 0) + ((pv & 4) ? 2 : 0) + ((pv & 8) ? 2 : 0);
            if ((pv & 16) && at + 2 <= dlen)
                e.tolerance = std::max(0.25, unscale(get16(d + at), 0, 100, 65535.0));
            e.raw.assign(d, d + dlen);
            list[uid] = e;
            added.push_back(uid);
            i += 9 + dlen;
        }
        for (std::uint16_t uid : added) { // links patched, every reference must exist (no forward links)
            const Element& e = list[uid];
            if ((e.prev && !list.count(e.prev)) || (e.next && !list.count(e.next)))
                return reject(7), true;
            if (e.prev)
                list[e.prev].next = uid;
            if (e.next)
                list[e.next].prev = uid;
        }
        m_list = std::move(list);
        Buf b = withId(ConfirmElementRequest);
        put8(b, req);
        replies.push_back(b);
        return true;
    }
    case DeleteElement: {
        if (len < 2 || src != m_controller)
            return true;
        for (std::size_t i = 0; i < body[1] && 2 + 2 * i + 2 <= len; ++i) {
            const std::uint16_t uid = get16(body + 2 + 2 * i);
            if (uid == 0xFFFF) {
                m_list.clear();
                stop();
            } else if (m_list.erase(uid) == 0) {
                Buf b = withId(RejectElementRequest);
                put8(b, body[0]);
                put8(b, 1);
                replies.push_back(b);
                return true;
            }
        }
        Buf b = withId(ConfirmElementRequest);
        put8(b, body[0]);
        replies.push_back(b);
        return true;
    }
    case QueryElementCount: {
        Buf b = withId(ReportElementCount);
        put16(b, std::uint16_t(m_list.size()));
        replies.push_back(b);
        return true;
    }
    case QueryElementList: {
        Buf b = withId(ReportElementList);
        put16(b, std::uint16_t(m_list.size()));
        for (const auto& [uid, e] : m_list) // ascending UID order
            put16(b, uid);
        replies.push_back(b);
        return true;
    }
    case QueryElement: {
        if (len < 2)
            return true;
        auto it = m_list.find(get16(body));
        if (it == m_list.end())
            return true;               // QueryElement(0) unanswered too
        Buf b = withId(ReportElement); // no format byte (JAUS++)
        put16(b, it->first);
        put16(b, it->second.prev);
        put16(b, it->second.next);
        put16(b, std::uint16_t(it->second.raw.size()));
        b.insert(b.end(), it->second.raw.begin(), it->second.raw.end());
        replies.push_back(b);
        return true;
    }
    case ExecuteList: {
        if (len < 3 || src != m_controller || m_status != 1 || m_opt.ignoreExecuteList)
            return true;
        const double speed = std::min(m_opt.maxSpeed, get16(body + 1) * 327.67 / 65535.0);
        if (speed > 0)
            m_speed = speed;
        if ((body[0] & 1) && len >= 5) {
            const std::uint16_t uid = get16(body + 3);
            // Executing means taking the drive component: not while a console holds it. A driver on the drive
            // component itself drives for whoever controls that component.
            if (!m_list.count(uid) ||
                (!sharesDriveComponent() && m_driveController != 0 && m_driveController != m_self))
                return true;
            if (!sharesDriveComponent())
                m_driveController = m_self;
            m_active = uid;
        }
        return true;
    }
    case QueryActiveElement: {
        Buf b = withId(ReportActiveElement);
        put16(b, m_active);
        replies.push_back(b);
        return true;
    }
    case QueryTravelSpeed: {
        Buf b = withId(ReportTravelSpeed);
        put16(b, std::uint16_t(m_speed / 327.67 * 65535.0 + 0.5));
        replies.push_back(b);
        return true;
    }
    default:
        return false;
    }
}

void WaypointListDriver::stop() {
    m_active = 0;
    m_speed = 0;
    if (m_driveController == m_self)
        m_driveController = 0;
}

void WaypointListDriver::step(double dt, bool vehicleEmergency, double& x, double& y) {
    // An emergency of the vehicle ends the driver's own Ready (it follows its drive component).
    if (vehicleEmergency && m_status == 1)
        m_status = 2;
    // Leaving Ready resets the speed (JSIDL resetTravelSpeed): Resume alone does not move it again.
    if (m_status != 1 || m_controller == 0 || vehicleEmergency) {
        m_speed = 0;
        return;
    }
    if (!m_active || m_speed <= 0)
        return;
    auto it = m_list.find(m_active);
    if (it == m_list.end())
        return stop();
    const double dx = it->second.x - x, dy = it->second.y - y, d = std::hypot(dx, dy);
    if (d <= it->second.tolerance) {
        m_active = it->second.next;
        if (!m_active)
            stop(); // the end of the list: idle, the drive component handed back
        return;
    }
    const double s = std::min(d, m_speed * dt);
    x += dx / d * s;
    y += dy / d * s;
}

} // namespace foreign
