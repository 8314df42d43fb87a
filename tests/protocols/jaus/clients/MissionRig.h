#pragma once
// MissionClient with the services it works with (events, drive, access control, management) on a
// ClientRig, and a vehicle offering the waypoint list drivers, played by hand: upload, confirmations,
// read-back and start helpers (test_mission_client, test_mission_file_upload).
#include <QtTest>

#include "protocols/jaus/MessagesMission.h"
#include "protocols/jaus/clients/AccessControlClient.h"
#include "protocols/jaus/clients/DriveClient.h"
#include "protocols/jaus/clients/EventsClient.h"
#include "protocols/jaus/clients/ManagementClient.h"
#include "protocols/jaus/clients/MissionClient.h"
#include "tests/protocols/jaus/clients/ClientRig.h"

namespace ocu::jaus::test {

inline const std::string kLwld = "urn:jaus:jss:mobility:LocalWaypointListDriver";
inline const std::string kGwld = "urn:jaus:jss:mobility:GlobalWaypointListDriver";

struct MissionRig : ClientRig {
    EventsClient events{ctx};
    DriveClient drive{ctx};
    AccessControlClient access{ctx, drive};
    ManagementClient management{ctx, events, drive};
    MissionClient mission{ctx, events, access};
    MissionRig() {
        for (ClientService* c :
             std::initializer_list<ClientService*>{&events, &drive, &access, &management, &mission})
            c->registerMessages(table);
        access.setOtherControl([this](RemoteSubsystem& r, const JausId& src, std::uint16_t id, ByteSpan p) {
            return mission.handleControlMessage(r, src, id, p);
        });
        management.setOtherStatus([this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
            return mission.handleStatus(r, src, p);
        });
    }
    // A vehicle whose list drivers sit on `driver` (the drive component ss.3.1 by default), posed at
    // 48.1 N 11.5 E = local (12.5, -3.25), both yaws 0.5, controlled by us when `controlled`.
    RemoteSubsystem& missionVehicle(JausId driver = ClientRig::mobility(), bool controlled = true) {
        RemoteSubsystem& r = vehicle();
        std::vector<ComponentInfo> comps{ComponentInfo{1, {{"urn:jaus:jss:mobility:PrimitiveDriver", 1, 0}}}};
        if (driver.component == 1)
            comps[0].services.insert(comps[0].services.end(), {{kLwld, 1, 0}, {kGwld, 1, 1}});
        else
            comps.push_back(ComponentInfo{driver.component, {{kLwld, 1, 0}}});
        r.snap.services = {NodeInfo{3, comps}};
        GlobalPose g;
        g.lat = 48.1;
        g.lon = 11.5;
        g.yaw = 0.5;
        LocalPose l;
        l.x = 12.5;
        l.y = -3.25;
        l.yaw = 0.5;
        r.snap.globalPose = g;
        r.snap.localPose = l;
        r.snap.management = ManagementState::Standby;
        mission.onServicesKnown(r);
        if (controlled) {
            access.requestControl(r.id());
            deliver(r, encodeU8(msg::ConfirmControl, 0));
        }
        return r;
    }
    void run(RemoteSubsystem& r, double seconds) {
        runFor(seconds, [&](TimePoint now) {
            access.tick(r, now);
            mission.tick(r, now);
        });
    }
    static std::vector<MissionPoint> route(int n) {
        std::vector<MissionPoint> pts;
        for (int i = 0; i < n; ++i)
            pts.push_back(MissionPoint{48.1 + 0.0001 * (i + 1), 11.5, 0, 1.0});
        return pts;
    }
    // Confirms the last SetElement/DeleteElement by its RequestID.
    void confirmLast(RemoteSubsystem& r, std::uint16_t id, JausId from = ClientRig::mobility()) {
        const Sent* s = out.last(id);
        QVERIFY(s);
        deliver(r, encodeU8(msg::ConfirmElementRequest, s->payload[2]), from);
    }
    // Plays a ListManager that holds exactly what it was sent: answers the read-back.
    void answerReadBack(RemoteSubsystem& r, const std::vector<ListElement>& held,
                        JausId from = ClientRig::mobility(), bool withFormat = true) {
        QVERIFY(out.last(msg::QueryElementCount));
        deliver(r, encodeU16(msg::ReportElementCount, std::uint16_t(held.size())), from);
        ReportElementList list;
        for (auto it = held.rbegin(); it != held.rend(); ++it)
            list.uids.push_back(it->uid); // any order: compared as a set
        deliver(r, encode(list), from);
        for (std::size_t i = 0; i < held.size(); ++i) {
            Bytes e = encode(held[i]);
            if (!withFormat)
                e.erase(e.begin() + 8); // JAUS++ leaves the format byte out
            deliver(r, e, from);
        }
    }
    std::vector<ListElement> uploaded() const {
        std::vector<ListElement> all;
        for (const Sent& s : out.sent)
            if (s.id() == msg::SetElement) {
                const auto set = decodeSetElement(s.payload);
                all.insert(all.end(), set->elements.begin(), set->elements.end());
            }
        // The vehicle patches the links of appended parts (jaus-autonomy.md §2.3).
        for (std::size_t i = 0; i < all.size(); ++i)
            all[i].next = i + 1 < all.size() ? all[i + 1].uid : 0;
        return all;
    }
    void uploadAndVerify(RemoteSubsystem& r, int n, std::optional<bool> global = false,
                         JausId from = ClientRig::mobility()) {
        QVERIFY(mission.upload(r.id(), route(n), global));
        confirmLast(r, msg::DeleteElement, from);
        while (mission.step(r.id()) == MissionClient::Step::Sending)
            confirmLast(r, msg::SetElement, from);
        answerReadBack(r, uploaded(), from);
        QCOMPARE(r.snap.mission.phase, MissionPhase::Uploaded);
    }
    void startRunning(RemoteSubsystem& r, JausId from = ClientRig::mobility()) {
        QVERIFY(mission.start(r.id(), 0));
        deliver(r, encode(ReportStatus{ManagementState::Ready, 0}), from);
        run(r, 0.02);
        QVERIFY(out.last(msg::ExecuteList));
        deliver(r, encodeU16(msg::ReportActiveElement, 1), from);
        QCOMPARE(r.snap.mission.phase, MissionPhase::Running);
    }
};

} // namespace ocu::jaus::test
