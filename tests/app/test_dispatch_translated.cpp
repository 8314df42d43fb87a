// The dispatch and production panels in German. Loads the console's own German .qm (embedded in
// ocu_app) and builds the panels as the console does: every label, button and column header the operator
// reads is German (no English source text left), the cue of a truck asking for work, the panel's own
// mnemonics unique within the panel, and the shift report's texts.
#include "app/ConsoleApp.h"
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/DispatchModel.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/ProductionModel.h"
#include "models/testing/FakeDispatchSource.h"
#include "widgets/dispatch/DispatchPanel.h"
#include "widgets/production/ProductionView.h"

#include <QAbstractButton>
#include <QApplication>
#include <QHeaderView>
#include <QLabel>
#include <QSet>
#include <QTabWidget>
#include <QTableView>
#include <QTest>

using namespace ocu;

namespace {

// Every visible text of the widget's labels and buttons, and its tables' column headers.
QStringList shownTexts(QWidget* w) {
    QStringList out;
    for (auto* l : w->findChildren<QLabel*>())
        if (!l->text().isEmpty())
            out << l->text();
    for (auto* b : w->findChildren<QAbstractButton*>())
        if (!b->text().isEmpty())
            out << b->text();
    for (auto* tabs : w->findChildren<QTabWidget*>())
        for (int i = 0; i < tabs->count(); ++i)
            out << tabs->tabText(i);
    for (auto* t : w->findChildren<QTableView*>()) {
        QAbstractItemModel* m = t->model();
        for (int c = 0; m && c < m->columnCount(); ++c)
            out << m->headerData(c, Qt::Horizontal).toString();
    }
    return out;
}

// The English sources of the panels (as in the code): none of them may remain under the German translator.
const QStringList kEnglish = {
    QStringLiteral("Truc&ks"),
    QStringLiteral("Next needing work (F6)"),
    QStringLiteral("&Task"),
    QStringLiteral("&Destination"),
    QStringLiteral("Pick on &map"),
    QStringLiteral("&Assign"),
    QStringLiteral("Re-&assign"),
    QStringLiteral("&Reset"),
    QStringLiteral("&Queues"),
    QStringLiteral("A&uto dispatch"),
    QStringLiteral("Truck"),
    QStringLiteral("Custodian"),
    QStringLiteral("Mode"),
    QStringLiteral("Assignment"),
    QStringLiteral("Task"),
    QStringLiteral("Destination"),
    QStringLiteral("Production"),
    QStringLiteral("Payload"),
    QStringLiteral("In state"),
    QStringLiteral("Area"),
    QStringLiteral("Kind"),
    QStringLiteral("Coming"),
    QStringLiteral("At area"),
    QStringLiteral("no truck needs an assignment"),
    QStringLiteral("1 truck(s) need an assignment"),
    QStringLiteral("Plan (t/shift):"),
    QStringLiteral("Shift &report…"),
    QStringLiteral("New shift"),
    QStringLiteral("Loads"),
    QStringLiteral("Tonnes"),
    QStringLiteral("Cycles"),
    QStringLiteral("Queue"),
    QStringLiteral("Spot"),
    QStringLiteral("Load"),
    QStringLiteral("Haul"),
    QStringLiteral("Dump"),
    QStringLiteral("Return"),
    QStringLiteral("Trucks"),
    QStringLiteral("Shovels"),
    QStringLiteral("Dumps"),
};

QChar mnemonic(const QString& text) {
    for (int i = 0; i + 1 < text.size(); ++i)
        if (text[i] == QLatin1Char('&') && text[i + 1] != QLatin1Char('&'))
            return text[i + 1].toLower();
    return {};
}

} // namespace

class TestDispatchTranslated : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        auto* app = qobject_cast<QApplication*>(QCoreApplication::instance());
        QCOMPARE(installTranslator(*app, QStringLiteral("de")), QStringLiteral("de"));
    }

    void dispatchPanelInGerman() {
        AlarmModel alarms;
        CommandGate gate{&alarms};
        FleetModel fleet;
        FleetSelection selection{&fleet};
        FakeDispatchSource src;
        src.setAreas({{QStringLiteral("ahs"), 10, QStringLiteral("Shovel A"), QStringLiteral("Load")}});
        DispatchTruck t;
        t.id = QStringLiteral("iso23725:T1");
        t.link = QStringLiteral("ahs");
        t.name = QStringLiteral("T1");
        t.stateKnown = true;
        t.custodian = QStringLiteral("FMS");
        t.wayId = 1;
        t.needsAssignment = true;
        src.setTrucks({t});
        DispatchPanel panel(&src, &gate, &selection);
        panel.resize(1100, 400);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));

        const QStringList shown = shownTexts(&panel);
        for (const QString& e : kEnglish)
            QVERIFY2(!shown.contains(e), qPrintable(QStringLiteral("English left: ") + e));
        for (const QString& de :
             {QStringLiteral("&Lkw"), QStringLiteral("Auf&gabe"), QStringLiteral("&Ziel"),
              QStringLiteral("Auf der &Karte"), QStringLiteral("Zuwei&sen"), QStringLiteral("Zu&rücksetzen"),
              QStringLiteral("Nächster ohne Arbeit (F6)"), QStringLiteral("Disponent"),
              QStringLiteral("Auftrag"), QStringLiteral("Nutzlast"), QStringLiteral("Unterwegs"),
              QStringLiteral("1 Lkw braucht einen Auftrag")})
            QVERIFY2(shown.contains(de), qPrintable(de + QStringLiteral(" not in: ") + shown.join(u'|')));

        // The truck asking for work shows the German cue.
        auto* table = panel.findChild<QTableView*>(QStringLiteral("dispatch-table"));
        QVERIFY(table);
        bool cue = false;
        for (int c = 0; c < table->model()->columnCount(); ++c)
            cue = cue || table->model()->index(0, c).data().toString() == QStringLiteral("BRAUCHT AUFTRAG");
        QVERIFY(cue);

        // The panel's Alt keys stay unique in German (and clear of the German menus: Datei, Ansicht, Hilfe).
        QSet<QChar> keys{QLatin1Char('d'), QLatin1Char('a'), QLatin1Char('h')};
        for (const QString& s : shown) {
            const QChar k = mnemonic(s);
            if (k.isNull())
                continue;
            QVERIFY2(!keys.contains(k),
                     qPrintable(QStringLiteral("Alt+") + k + QStringLiteral(" twice: ") + s));
            keys.insert(k);
        }
        // The key list in the tooltip names the German keys.
        const QString help = DispatchPanel::shortcutHelp();
        QVERIFY2(help.contains(QStringLiteral("Alt+Z: Ziel")) && help.contains(QStringLiteral("Alt+K")),
                 qPrintable(help));
    }

    void productionViewInGerman() {
        ProductionModel model;
        ProductionView view(&model);
        view.resize(1100, 500);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        const QStringList shown = shownTexts(&view);
        for (const QString& e : kEnglish)
            QVERIFY2(!shown.contains(e), qPrintable(QStringLiteral("English left: ") + e));
        for (const QString& de :
             {QStringLiteral("Schicht&bericht…"), QStringLiteral("Neue Schicht"), QStringLiteral("Ladungen"),
              QStringLiteral("Tonnen"), QStringLiteral("Umläufe")})
            QVERIFY2(shown.contains(de), qPrintable(de + QStringLiteral(" not in: ") + shown.join(u'|')));
        QCOMPARE(QObject::tr("Shift report"), QStringLiteral("Schichtbericht"));
    }
};

QTEST_MAIN(TestDispatchTranslated)
#include "test_dispatch_translated.moc"
