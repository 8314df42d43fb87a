// Event, alarm and link texts translated like the rest. The stacks and toText() give stable
// English keys (logs, recordings, CSV, headless JSON); what the operator reads comes from DisplayText in the
// language of the loaded translator. This test loads the console's own .qm files (embedded in ocu_app).
#include "app/ConsoleApp.h"
#include "models/AlarmModel.h"
#include "models/DisplayText.h"
#include "models/FleetModel.h"
#ifdef OCU_TEST_WITH_JAUS
#include "models/jaus/JausSubsystemModel.h"
#endif
#include "widgets/EventLogWidget.h"
#include "widgets/FleetListWidget.h"

#include <QApplication>
#include <QBuffer>
#include <QTableView>
#include <QTest>
#include <QTranslator>

using namespace ocu;

namespace {

// Every English display text of every enum value, as DisplayText gives it without a translator.
QStringList allDisplaySources() {
    QStringList s;
    for (auto v :
         {EventSeverity::Info, EventSeverity::Warning, EventSeverity::Alarm, EventSeverity::Critical})
        s << DisplayText::severity(v);
    for (auto v : {EventKind::LinkLoss, EventKind::Timeout, EventKind::HealthFault, EventKind::Diagnostic,
                   EventKind::Discrepancy, EventKind::ControlLost, EventKind::TextMessage, EventKind::Audit,
                   EventKind::Info})
        s << DisplayText::kind(v);
    for (auto v : {AlarmPriority::Auto, AlarmPriority::Low, AlarmPriority::Medium, AlarmPriority::High,
                   AlarmPriority::Urgent})
        s << DisplayText::priority(v);
    for (auto v : {LinkState::Unknown, LinkState::Up, LinkState::Degraded, LinkState::Down})
        s << DisplayText::link(v);
    for (auto v : {StopState::Unknown, StopState::None, StopState::Stopped})
        s << DisplayText::stop(v);
    for (auto v : {HealthLevel::Unknown, HealthLevel::Ok, HealthLevel::Warning, HealthLevel::Fault})
        s << DisplayText::health(v);
    for (auto v : {ModeCategory::Unknown, ModeCategory::Manual, ModeCategory::Autonomous,
                   ModeCategory::Remote, ModeCategory::Idle, ModeCategory::Transition, ModeCategory::Stopped,
                   ModeCategory::Fault, ModeCategory::Shutdown})
        s << DisplayText::mode(v);
    for (auto v : {ControlState::None, ControlState::Monitoring, ControlState::ControlledByMe,
                   ControlState::ControlledByOther, ControlState::Denied})
        s << DisplayText::control(v);
    for (auto v : {StatusCategory::Ok, StatusCategory::Warning, StatusCategory::FaultOrStopped,
                   StatusCategory::Stale, StatusCategory::Autonomous})
        s << DisplayText::status(v);
    s.removeDuplicates();
    return s;
}

MachineState degradedTruck() {
    MachineState m;
    m.id = QStringLiteral("iso23725:t1");
    m.protocol = Protocol::Iso23725;
    m.name = QStringLiteral("HT1");
    m.link = LinkState::Degraded;
    m.health = HealthLevel::Fault;
    m.mode = ModeCategory::Autonomous;
    m.lastDataMs = 1000;
    return m;
}

} // namespace

class TestTranslatedTexts : public QObject {
    Q_OBJECT
private slots:
    void englishWithoutTranslator();
    void everyDisplayTextTranslated_data();
    void everyDisplayTextTranslated();
    void germanInPanels();
};

void TestTranslatedTexts::englishWithoutTranslator() {
    AlarmModel alarms;
    alarms.add(makeEvent(EventSeverity::Warning, EventKind::LinkLoss, {}, QStringLiteral("link x lost")));
    QCOMPARE(alarms.data(alarms.index(0, AlarmModel::ColSeverity)).toString(), QStringLiteral("WARNING"));
    QCOMPARE(alarms.data(alarms.index(0, AlarmModel::ColKind)).toString(), QStringLiteral("link loss"));
    QCOMPARE(alarms.data(alarms.index(0, AlarmModel::ColPriority)).toString(), QStringLiteral("low"));
    QCOMPARE(DisplayText::link(LinkState::Degraded), QStringLiteral("degraded"));
}

void TestTranslatedTexts::everyDisplayTextTranslated_data() {
    QTest::addColumn<QString>("lang");
    QTest::newRow("de") << QStringLiteral("de");
    QTest::newRow("fr") << QStringLiteral("fr");
}

void TestTranslatedTexts::everyDisplayTextTranslated() {
    QFETCH(QString, lang);
    QTranslator t;
    QVERIFY(t.load(QStringLiteral(":/i18n/ocu_%1.qm").arg(lang)));
    QStringList missing;
    for (const QString& source : allDisplaySources())
        if (t.translate("ocu::DisplayText", source.toUtf8().constData()).isEmpty())
            missing << source;
    QVERIFY2(missing.isEmpty(), qPrintable(lang + QStringLiteral(": ") + missing.join(QStringLiteral(", "))));
}

void TestTranslatedTexts::germanInPanels() {
    auto* app = qobject_cast<QApplication*>(QCoreApplication::instance());
    QCOMPARE(installTranslator(*app, QStringLiteral("de")), QStringLiteral("de"));

    // Alarm panel / event log: severity, kind and priority in German; the stable key stays English.
    AlarmModel alarms;
    alarms.add(makeEvent(EventSeverity::Warning, EventKind::LinkLoss, {}, QStringLiteral("link x lost")));
    alarms.add(makeEvent(EventSeverity::Critical, EventKind::Discrepancy, QStringLiteral("iso23725:t1"),
                         QStringLiteral("not in the FMS fleet")));
    EventLogWidget log(&alarms);
    auto* view = log.findChild<QTableView*>();
    QVERIFY(view);
    QAbstractItemModel* shown = view->model();
    QCOMPARE(shown->rowCount(), 2);
    QCOMPARE(shown->index(0, AlarmModel::ColSeverity).data().toString(), QStringLiteral("WARNUNG"));
    QCOMPARE(shown->index(0, AlarmModel::ColKind).data().toString(), QStringLiteral("Verbindungsverlust"));
    QCOMPARE(shown->index(0, AlarmModel::ColPriority).data().toString(), QStringLiteral("niedrig"));
    QCOMPARE(shown->index(1, AlarmModel::ColSeverity).data().toString(), QStringLiteral("KRITISCH"));
    QCOMPARE(shown->index(1, AlarmModel::ColKind).data().toString(), QStringLiteral("Abweichung"));
    QCOMPARE(shown->index(1, AlarmModel::ColPriority).data().toString(), QStringLiteral("dringend"));
    QCOMPARE(alarms.headerData(AlarmModel::ColPriority, Qt::Horizontal).toString(),
             QStringLiteral("Priorität"));
    QBuffer csv;
    csv.open(QIODevice::ReadWrite);
    QVERIFY(alarms.exportCsv(&csv));
    const QByteArray text = csv.data();
    QVERIFY2(text.contains(",warning,link_loss,") && text.contains(",critical,discrepancy,"),
             text.constData());
    QCOMPARE(toText(EventSeverity::Warning), QStringLiteral("warning")); // headless JSON and logs

    // Fleet list: the link state word, the health and mode texts, and the details pane.
    FleetModel fleet;
    fleet.setClock(std::make_shared<ManualModelClock>(1500));
    fleet.upsert({degradedTruck()});
    QCOMPARE(fleet.rowCount(), 1);
    QVERIFY2(
        fleet.index(0, FleetModel::ColLink).data().toString().startsWith(QStringLiteral("beeinträchtigt")),
        qPrintable(fleet.index(0, FleetModel::ColLink).data().toString()));
    QCOMPARE(fleet.index(0, FleetModel::ColHealth).data().toString(), QStringLiteral("Fehler"));
    QCOMPARE(fleet.index(0, FleetModel::ColMode).data().toString(), QStringLiteral("autonom"));
    const QString details = FleetListWidget::describeMachine(degradedTruck());
    QVERIFY2(details.contains(QStringLiteral("beeinträchtigt")) &&
                 !details.contains(QStringLiteral("degraded")),
             qPrintable(details));

#ifdef OCU_TEST_WITH_JAUS
    // JAUS panel: the link column and the details use the translated word, not the stack's.
    QCOMPARE(JausSubsystemModel::linkText(JausLink::Down), QStringLiteral("ausgefallen"));
#endif
}

QTEST_MAIN(TestTranslatedTexts)
#include "test_translated_texts.moc"
