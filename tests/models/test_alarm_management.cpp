// Alarm management in AlarmModel (EEMUA 191 / ISA-18.2): a repeat of an active alarm updates it
// (one row, occurrence count) instead of flooding; stable keys; acknowledgement by key with who and when;
// priorities; shelving that expires by itself (fake clock); the alarm rate per 10 minutes and the flood flag.
#include "models/AlarmModel.h"

#include <QSignalSpy>
#include <QtTest>

using namespace ocu;

namespace {

constexpr qint64 kStart = 1'800'000'000'000; // 2027-01-15, any fixed instant
constexpr qint64 kMinute = 60'000;

FleetEvent alarm(const QString& machine, const QString& text, EventKind kind = EventKind::Timeout,
                 EventSeverity sev = EventSeverity::Warning) {
    FleetEvent e = makeEvent(sev, kind, machine, text, QStringLiteral("test"));
    e.timeMs = 0; // stamped by the model's clock
    return e;
}

struct Fixture {
    std::shared_ptr<ManualModelClock> clock = std::make_shared<ManualModelClock>(kStart);
    AlarmModel model;
    Fixture() { model.setClock(clock); }
};

} // namespace

class TestAlarmManagement : public QObject {
    Q_OBJECT
private slots:
    void keysAreStableAndDistinguishCause() {
        const FleetEvent a = alarm(QStringLiteral("HT01"), QStringLiteral("no data from HT01"));
        const FleetEvent b = alarm(QStringLiteral("HT01"), QStringLiteral("other text, same cause"));
        QCOMPARE(alarmKey(a), QStringLiteral("timeout|HT01|test"));
        QCOMPARE(alarmKey(a), alarmKey(b)); // the text is not part of a cause with an identity of its own
        FleetEvent grouped = alarm({}, QStringLiteral("3 machines ..."), EventKind::Discrepancy);
        grouped.cause = QStringLiteral("fleet.not_in_fms");
        grouped.group = QStringLiteral("ahs-north");
        QCOMPARE(alarmKey(grouped), QStringLiteral("fleet.not_in_fms|ahs-north|test"));
        QVERIFY(alarmKey(alarm(QStringLiteral("HT02"), {})) != alarmKey(a));
    }

    void priorityFollowsSeverityUnlessSet() {
        QCOMPARE(effectivePriority(alarm({}, {}, EventKind::Timeout, EventSeverity::Warning)),
                 AlarmPriority::Low);
        QCOMPARE(effectivePriority(alarm({}, {}, EventKind::LinkLoss, EventSeverity::Alarm)),
                 AlarmPriority::High);
        QCOMPARE(effectivePriority(alarm({}, {}, EventKind::LinkLoss, EventSeverity::Critical)),
                 AlarmPriority::Urgent);
        FleetEvent e = alarm({}, {});
        e.priority = AlarmPriority::Medium;
        QCOMPARE(effectivePriority(e), AlarmPriority::Medium);
        Fixture f;
        f.model.add(e);
        QCOMPARE(f.model.data(f.model.index(0, AlarmModel::ColPriority)).toString(),
                 QStringLiteral("medium"));
        QCOMPARE(f.model.data(f.model.index(0, 0), AlarmModel::PriorityRole).toInt(),
                 int(AlarmPriority::Medium));
    }

    void repeatsOfAnActiveAlarmAreOneRow() {
        Fixture f;
        for (int i = 0; i < 1000; ++i)
            f.model.add(alarm(QStringLiteral("HT01"), QStringLiteral("no data from HT01")));
        f.model.add(alarm(QStringLiteral("HT02"), QStringLiteral("no data from HT02")));
        QCOMPARE(f.model.rowCount(), 2);
        QCOMPARE(f.model.occurrencesAt(0), 1000);
        QCOMPARE(f.model.occurrencesAt(1), 1);
        QCOMPARE(f.model.unacknowledgedCount(), 2);
        QCOMPARE(f.model.data(f.model.index(0, AlarmModel::ColCount)).toString(), QStringLiteral(" ×1000"));
        // Once acknowledged, the next occurrence is a new alarm (it must be seen again).
        f.model.acknowledge(0);
        f.model.add(alarm(QStringLiteral("HT01"), QStringLiteral("no data from HT01")));
        QCOMPARE(f.model.rowCount(), 3);
        QCOMPARE(f.model.unacknowledgedCount(), 2);
        // Info entries are a log, never merged.
        f.model.add(alarm({}, QStringLiteral("note"), EventKind::Info, EventSeverity::Info));
        f.model.add(alarm({}, QStringLiteral("note"), EventKind::Info, EventSeverity::Info));
        QCOMPARE(f.model.rowCount(), 5);
    }

    void acknowledgementCarriesKeyWhoAndWhen() {
        Fixture f;
        f.model.setOperatorName(QStringLiteral("dispatcher"));
        QSignalSpy acks(&f.model, &AlarmModel::alarmAcknowledged);
        f.model.add(alarm(QStringLiteral("HT01"), QStringLiteral("no data")));
        f.clock->advance(5000);
        f.model.acknowledge(0);
        QCOMPARE(acks.count(), 1);
        QCOMPARE(acks[0][0].toString(), QStringLiteral("timeout|HT01|test"));
        QCOMPARE(acks[0][1].toString(), QStringLiteral("dispatcher"));
        QCOMPARE(acks[0][2].toLongLong(), kStart + 5000);
        QCOMPARE(f.model.acknowledgedByAt(0), QStringLiteral("dispatcher"));
        // Acknowledging again does nothing; acknowledging by key from another console works on active ones.
        f.model.acknowledge(0);
        QCOMPARE(acks.count(), 1);
        f.model.add(alarm(QStringLiteral("HT02"), QStringLiteral("no data")));
        QVERIFY(!f.model.acknowledgeKey(QStringLiteral("timeout|HT09|test"), QStringLiteral("x"),
                                        f.clock->nowMs()));
        QVERIFY(f.model.acknowledgeKey(QStringLiteral("timeout|HT02|test"), QStringLiteral("site manager"),
                                       f.clock->nowMs()));
        QCOMPARE(f.model.unacknowledgedCount(), 0);
        QCOMPARE(f.model.acknowledgedByAt(1), QStringLiteral("site manager"));
        QCOMPARE(acks.count(), 2);
        // An acknowledgement made before an occurrence was raised does not cover it.
        f.model.add(alarm(QStringLiteral("HT03"), QStringLiteral("no data")));
        QVERIFY(!f.model.acknowledgeKey(QStringLiteral("timeout|HT03|test"), QStringLiteral("x"),
                                        f.clock->nowMs() - kMinute));
        QCOMPARE(f.model.unacknowledgedCount(), 1);
    }

    void shelvingExpiresByItself() {
        Fixture f;
        f.model.setOperatorName(QStringLiteral("dispatcher"));
        QSignalSpy shelved(&f.model, &AlarmModel::alarmShelved);
        QSignalSpy unshelved(&f.model, &AlarmModel::alarmUnshelved);
        f.model.add(alarm(QStringLiteral("HT01"), QStringLiteral("no data")));
        f.model.add(alarm(QStringLiteral("HT02"), QStringLiteral("no data")));
        const QString key = f.model.keyAt(0);
        f.model.shelve(key, 15 * kMinute);
        QCOMPARE(shelved.count(), 1);
        QCOMPARE(shelved[0][0].toString(), key);
        QCOMPARE(shelved[0][1].toString(), QStringLiteral("dispatcher"));
        QCOMPARE(shelved[0][3].toLongLong(), kStart + 15 * kMinute);
        QVERIFY(f.model.isShelved(0));
        QCOMPARE(f.model.unacknowledgedCount(), 1);
        // Hidden from the default view, shown on demand.
        AlarmFilterProxy proxy;
        proxy.setSourceModel(&f.model);
        QCOMPARE(proxy.rowCount(), 1);
        proxy.setShowShelved(true);
        QCOMPARE(proxy.rowCount(), 2);
        proxy.setShowShelved(false);
        // A repeat while shelved is not annunciated.
        f.model.add(alarm(QStringLiteral("HT01"), QStringLiteral("no data")));
        QCOMPARE(f.model.unacknowledgedCount(), 1);
        f.clock->advance(15 * kMinute - 1);
        f.model.expireShelving();
        QVERIFY(f.model.isShelved(0));
        QCOMPARE(unshelved.count(), 0);
        f.clock->advance(1);
        f.model.expireShelving();
        QVERIFY(!f.model.isShelved(0));
        QCOMPARE(unshelved.count(), 1);
        QCOMPARE(unshelved[0][0].toString(), key);
        QCOMPARE(unshelved[0][1].toString(), QStringLiteral("expiry"));
        QCOMPARE(unshelved[0][2].toLongLong(), kStart + 15 * kMinute);
        // Back, and still unacknowledged: it must be seen.
        QCOMPARE(f.model.unacknowledgedCount(), 2);
        QCOMPARE(proxy.rowCount(), 2);
        // Shelving from another console that already expired is ignored; unshelve by hand works.
        QVERIFY(!f.model.applyShelve(key, QStringLiteral("x"), f.clock->nowMs() - 2 * kMinute,
                                     f.clock->nowMs() - kMinute));
        QVERIFY(f.model.applyShelve(key, QStringLiteral("x"), f.clock->nowMs(), f.clock->nowMs() + kMinute));
        QVERIFY(f.model.unshelve(key));
        QCOMPARE(unshelved.count(), 2);
    }

    void shelvingExpiresOnTheTimer() {
        // The model's own 1 s timer ends shelvings (with the fake clock already past the end).
        Fixture f;
        f.model.add(alarm(QStringLiteral("HT01"), QStringLiteral("no data")));
        QSignalSpy unshelved(&f.model, &AlarmModel::alarmUnshelved);
        f.model.shelve(f.model.keyAt(0), kMinute);
        f.clock->advance(kMinute);
        QTRY_COMPARE_WITH_TIMEOUT(unshelved.count(), 1, 10000);
    }

    void alarmRateAndFlood() {
        Fixture f;
        QSignalSpy rate(&f.model, &AlarmModel::alarmRateChanged);
        for (int i = 0; i < 10; ++i) {
            f.model.add(alarm(QStringLiteral("HT%1").arg(i), QStringLiteral("no data")));
            f.clock->advance(30'000);
        }
        QCOMPARE(f.model.alarmRate(), 10);
        QVERIFY(!f.model.isFlood()); // 10 per 10 min is the limit, not a flood
        // Repeats of active alarms and info entries do not count.
        f.model.add(alarm(QStringLiteral("HT0"), QStringLiteral("no data")));
        f.model.add(alarm({}, QStringLiteral("note"), EventKind::Info, EventSeverity::Info));
        QCOMPARE(f.model.alarmRate(), 10);
        f.model.add(alarm(QStringLiteral("HT10"), QStringLiteral("no data")));
        QCOMPARE(f.model.alarmRate(), 11);
        QVERIFY(f.model.isFlood());
        QCOMPARE(rate.last()[0].toInt(), 11);
        QCOMPARE(rate.last()[1].toBool(), true);
        // The window slides: the first alarm (at kStart) leaves it 10 minutes later.
        f.clock->set(kStart + AlarmModel::kRateWindowMs);
        QCOMPARE(f.model.alarmRate(), 10);
        QVERIFY(!f.model.isFlood());
        f.clock->set(kStart + 2 * AlarmModel::kRateWindowMs);
        QCOMPARE(f.model.alarmRate(), 0);
        QTRY_COMPARE_WITH_TIMEOUT(rate.last()[0].toInt(), 0, 10000); // the timer tells the panel
    }
};

QTEST_GUILESS_MAIN(TestAlarmManagement)
#include "test_alarm_management.moc"
