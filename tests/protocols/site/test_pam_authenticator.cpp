// Password checks through PAM against a throwaway service folder.
#include "protocols/site/PamAuthenticator.h"
#include "tests/support/ThrowawayPam.h"

#include <QtTest>

using namespace ocu;

class TestPamAuthenticator : public QObject {
    Q_OBJECT
private slots:
    void rightAndWrongPasswords() {
        testing::ThrowawayPam pam({{QStringLiteral("alice"), QStringLiteral("s3cret")},
                                   {QStringLiteral("bob"), QStringLiteral("hunter 2")}});
        const PamAuthenticator auth("ocu", pam.confDir().toStdString());
        QCOMPARE(auth.authenticate("alice", "s3cret"), std::string());
        QCOMPARE(auth.authenticate("bob", "hunter 2"), std::string());
        QCOMPARE(auth.authenticate("alice", "wrong"), std::string("wrong user name or password"));
        QCOMPARE(auth.authenticate("alice", "hunter 2"), std::string("wrong user name or password"));
        QCOMPARE(auth.authenticate("mallory", "s3cret"), std::string("wrong user name or password"));
        QVERIFY(!auth.authenticate("alice", "").empty());
        QVERIFY(!auth.authenticate("", "s3cret").empty());
    }
    // A service that does not exist in the folder is refused, never accepted.
    void unknownService() {
        testing::ThrowawayPam pam(
            std::map<QString, QString>{{QStringLiteral("alice"), QStringLiteral("s3cret")}});
        const PamAuthenticator auth("ocu-nonexistent", pam.confDir().toStdString());
        QVERIFY(!auth.authenticate("alice", "s3cret").empty());
    }
};

QTEST_GUILESS_MAIN(TestPamAuthenticator)
#include "test_pam_authenticator.moc"
