// The window's side of the operator: the status bar says who, File › Lock covers the picture below the safety
// toolbar while STOP ALL stays visible and keeps its key, the unlock and switch dialogs check passwords
// through a throwaway PAM service. With OCU_OPERATOR_SHOTS=<folder>: the lock screen and the sign-in
// dialog at 1366x768 as PNGs.
#include "app/LockScreen.h"
#include "app/MainWindow.h"
#include "app/OperatorUi.h"
#include "app/SiteLoader.h"
#include "app/SiteRuntime.h"
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/FleetModel.h"
#include "models/OperatorSession.h"
#include "models/testing/FakeFleetBridge.h"
#include "protocols/site/PamAuthenticator.h"
#include "tests/support/ThrowawayPam.h"
#include "widgets/SignInDialog.h"

#include <QAction>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QPainter>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QToolBar>
#include <QtTest>

#include <memory>

using namespace ocu;
using R = OperatorRole;

namespace {
struct Console {
    testing::ThrowawayPam pam{{{QStringLiteral("alice"), QStringLiteral("a-pass")},
                               {QStringLiteral("bob"), QStringLiteral("b-pass")}}};
    PamAuthenticator auth{"ocu", pam.confDir().toStdString()};
    FleetModel fleet;
    AlarmModel alarms;
    CommandGate gate{&alarms};
    MainWindow window;
    std::unique_ptr<OperatorSession> session;
    OperatorUi* ui = nullptr;
    Console() {
        session = std::make_unique<OperatorSession>(
            &gate, &fleet, &alarms,
            [this](const QString& u, const QString& p) {
                return QString::fromStdString(auth.authenticate(u.toStdString(), p.toStdString()));
            },
            [](const QString& user) {
                return OperatorIdentity{user, user == QLatin1String("alice") ? R::UgvOperator : R::Dispatcher,
                                        QStringLiteral("ocu-1")};
            });
        session->setOperator({QStringLiteral("alice"), R::UgvOperator, QStringLiteral("ocu-1")});
        ui = new OperatorUi(window, session.get());
        window.resize(1366, 768);
        window.show();
        (void)QTest::qWaitForWindowExposed(&window);
    }
    QAction* action(const char* name) { return window.findChild<QAction*>(QLatin1String(name)); }
};

void saveShot(const QImage& image, const QString& name) {
    const QString dir = qEnvironmentVariable("OCU_OPERATOR_SHOTS");
    if (!dir.isEmpty())
        QVERIFY(image.save(dir + QLatin1Char('/') + name));
}
} // namespace

class TestOperatorUi : public QObject {
    Q_OBJECT
private slots:
    void statusBarNamesOperatorAndRole() {
        Console c;
        auto* label = c.window.findChild<QLabel*>(QStringLiteral("status-operator"));
        QVERIFY(label);
        QCOMPARE(label->text(), QStringLiteral("alice · UGV operator"));
        QVERIFY(c.action("action-switch-operator"));
    }

    void lockKeepsStopAllAndUnlocksByPassword() {
        Console c;
        QSignalSpy stops(&c.window, &MainWindow::stopAllRequested);
        c.action("action-lock")->trigger();
        QVERIFY(c.session->isLocked());
        LockScreen* veil = c.ui->lockScreen();
        QTRY_VERIFY(veil->isVisible());
        // STOP ALL above the veil, visible; its key works on the locked console.
        auto* stopButton = c.window.findChild<QWidget*>(QStringLiteral("button-stop-all"));
        QVERIFY(stopButton && stopButton->isVisible());
        const QRect stopRect(stopButton->mapTo(&c.window, QPoint(0, 0)), stopButton->size());
        QVERIFY2(!veil->geometry().intersects(stopRect), "the veil covers STOP ALL");
        QVERIFY(veil->geometry().height() > c.window.height() / 2);
        QTest::keyClick(&c.window, Qt::Key_F12);
        QCOMPARE(stops.count(), 1);
        saveShot(c.window.grab().toImage(), QStringLiteral("lock-screen-1366x768.png"));

        std::unique_ptr<SignInDialog> unlock(c.ui->makeUnlockDialog());
        QCOMPARE(unlock->userField()->text(), QStringLiteral("alice"));
        QVERIFY(unlock->userField()->isReadOnly());
        unlock->passwordField()->setText(QStringLiteral("wrong"));
        unlock->submit();
        QVERIFY(c.session->isLocked());
        QCOMPARE(unlock->errorLabel()->text(), QStringLiteral("wrong user name or password"));
        QVERIFY(unlock->passwordField()->text().isEmpty());
        unlock->passwordField()->setText(QStringLiteral("a-pass"));
        unlock->submit();
        QVERIFY(!c.session->isLocked());
        QTRY_VERIFY(!veil->isVisible());
    }

    // Tab and Shift+Tab on a locked console go round the veil and the row above it (STOP ALL, workspaces)
    // only.
    void focusStaysOnTheVeilAndTheSafetyToolbar() {
        Console c;
        c.window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&c.window));
        QWidget* behind = nullptr;
        for (QWidget* w : c.window.findChildren<QWidget*>())
            if (w->isVisible() && w->focusPolicy() & Qt::TabFocus &&
                !w->objectName().contains(QLatin1String("stop")) &&
                !qobject_cast<QToolBar*>(w->parentWidget())) {
                behind = w;
                break;
            }
        QVERIFY(behind);
        c.action("action-lock")->trigger();
        LockScreen* veil = c.ui->lockScreen();
        QTRY_VERIFY(veil->isVisible());
        auto* toolbar = c.window.findChild<QToolBar*>(QStringLiteral("toolbar-safety"));
        QVERIFY(toolbar);
        const auto allowed = [&](QWidget* f) {
            return f && (veil->isAncestorOf(f) || f == veil || toolbar->isAncestorOf(f) || f == toolbar ||
                         f->mapTo(&c.window, QPoint(0, f->height())).y() <= veil->geometry().top());
        };
        QTRY_VERIFY(allowed(QApplication::focusWidget()));
        behind->setFocus(Qt::MouseFocusReason); // a click or a shortcut that would focus a panel
        QVERIFY2(allowed(QApplication::focusWidget()), qPrintable(QApplication::focusWidget()->objectName()));
        bool reachedStop = false;
        for (int i = 0; i < 40; ++i) {
            QTest::keyClick(QApplication::focusWidget(), i % 10 == 9 ? Qt::Key_Backtab : Qt::Key_Tab);
            QWidget* f = QApplication::focusWidget();
            QVERIFY2(allowed(f),
                     qPrintable(QStringLiteral("Tab reached %1 (%2) under the veil")
                                    .arg(f ? f->objectName() : QStringLiteral("nothing"),
                                         f ? QString::fromLatin1(f->metaObject()->className()) : QString())));
            reachedStop = reachedStop || f->objectName() == QLatin1String("button-stop-all");
        }
        QVERIFY2(reachedStop, "STOP ALL not reachable by Tab on the locked console");
        QVERIFY(c.session->unlock(QStringLiteral("a-pass")));
        QTRY_VERIFY(!veil->isVisible());
        behind->setFocus(Qt::MouseFocusReason);
        QCOMPARE(QApplication::focusWidget(), behind);
    }

    void switchOperatorDialog() {
        Console c;
        std::unique_ptr<SignInDialog> d(c.ui->makeSwitchDialog());
        d->resize(d->sizeHint());
        d->userField()->setText(QStringLiteral("bob"));
        d->passwordField()->setText(QStringLiteral("nope"));
        d->submit();
        QVERIFY(d->errorLabel()->isVisibleTo(d.get()));
        QCOMPARE(c.session->current().user, QStringLiteral("alice"));
        // The dialog over the window, as the person sees it after a wrong password.
        d->show();
        QVERIFY(QTest::qWaitForWindowExposed(d.get()));
        QImage shot = c.window.grab().toImage();
        {
            QPainter p(&shot);
            const QImage dialog = d->grab().toImage();
            const QPoint at((shot.width() - dialog.width()) / 2, (shot.height() - dialog.height()) / 3);
            p.drawImage(at, dialog);
            p.setPen(QPen(Qt::darkGray, 2)); // the window frame the offscreen platform does not draw
            p.drawRect(QRect(at, dialog.size()).adjusted(-1, -1, 0, 0));
        }
        saveShot(shot, QStringLiteral("sign-in-1366x768.png"));
        d->passwordField()->setText(QStringLiteral("b-pass"));
        d->submit();
        QCOMPARE(c.session->current().user, QStringLiteral("bob"));
        auto* label = c.window.findChild<QLabel*>(QStringLiteral("status-operator"));
        QCOMPARE(label->text(), QStringLiteral("bob · dispatcher"));
    }

    // The whole console on the built-in site with a roles section: the OS user's role in the status bar and
    // in STOP ALL's audit line from the locked console; the console's end is the person's sign-out.
    void builtInSite() {
        QTemporaryDir recordings;
        auto site = loadSite({});
        QVERIFY(site.ok() && recordings.isValid());
        SiteConfig cfg = std::move(site.value());
        cfg.record.dir = recordings.path().toStdString();
        cfg.fleet.auditLog = recordings.filePath(QStringLiteral("audit.jsonl")).toStdString();
        cfg.roles.configured = true;
        cfg.roles.users[currentOsUser().name] = R::Supervisor;
        SiteRuntime runtime(cfg);
        runtime.start();
        QCOMPARE(runtime.operatorIdentity().role, R::Supervisor);
        QCOMPARE(runtime.operatorIdentity().user, QString::fromStdString(currentOsUser().name));
        {
            MainWindow window;
            runtime.populate(window);
            window.resize(1366, 768);
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            auto* label = window.findChild<QLabel*>(QStringLiteral("status-operator"));
            QVERIFY(label && label->text().endsWith(QStringLiteral("· supervisor")));
            QTest::qWait(qEnvironmentVariableIsSet("OCU_OPERATOR_SHOTS") ? 6000 : 500); // machines on the map
            runtime.operatorSession()->lock();
            QCoreApplication::processEvents();
            saveShot(window.grab().toImage(), QStringLiteral("lock-screen-site-1366x768.png"));
            QTest::keyClick(&window, Qt::Key_F12);
            QFile audit(recordings.filePath(QStringLiteral("audit.jsonl")));
            const auto actions = [&audit] {
                QStringList out;
                if (audit.open(QIODevice::ReadOnly)) {
                    for (const QByteArray& l : audit.readAll().split('\n'))
                        if (!l.isEmpty())
                            out << QJsonDocument::fromJson(l)
                                       .object()
                                       .value(QStringLiteral("action"))
                                       .toString();
                    audit.close();
                }
                return out;
            };
            // The console's start and the lock are the person's too.
            QTRY_COMPARE_WITH_TIMEOUT(
                actions(),
                (QStringList{QStringLiteral("sign_in"), QStringLiteral("lock"), QStringLiteral("stop_all")}),
                5000);
            QVERIFY(audit.open(QIODevice::ReadOnly));
            const QJsonObject line = QJsonDocument::fromJson(audit.readAll().split('\n').at(2)).object();
            QCOMPARE(line.value(QStringLiteral("action")).toString(), QStringLiteral("stop_all"));
            QCOMPARE(line.value(QStringLiteral("role")).toString(), QStringLiteral("supervisor"));
            QCOMPARE(line.value(QStringLiteral("operator")).toString(), runtime.operatorIdentity().user);
        }
        runtime.stop();
        QFile audit(recordings.filePath(QStringLiteral("audit.jsonl")));
        QVERIFY(audit.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = audit.readAll().trimmed().split('\n');
        const QJsonObject last = QJsonDocument::fromJson(lines.last()).object();
        QCOMPARE(last.value(QStringLiteral("action")).toString(), QStringLiteral("sign_out"));
        QCOMPARE(last.value(QStringLiteral("operator")).toString(), runtime.operatorIdentity().user);
        QCOMPARE(last.value(QStringLiteral("role")).toString(), QStringLiteral("supervisor"));
    }
};

QTEST_MAIN(TestOperatorUi)
#include "test_operator_ui.moc"
