// Every case of `shadowlab audit` as a test row: the same catalogue, the same verdicts.
#include "Application.h"
#include "AuditCatalogue.h"

#include <QtTest>

using namespace shadowlab;

class TestAudit : public QObject {
    Q_OBJECT

public:
    static void initMain() { configureApplication(); }

private:
    std::unique_ptr<HeadlessRenderer> m_headless;

private Q_SLOTS:
    void initTestCase()
    {
        m_headless = std::make_unique<HeadlessRenderer>();
        qInfo("renderer: %s", qPrintable(m_headless->renderer().rendererString()));
    }
    void cleanupTestCase() { m_headless.reset(); }

    void catalogueCoversTheIssue() { QVERIFY(auditCatalogue().size() >= 20); }

    void auditCase_data()
    {
        QTest::addColumn<int>("index");
        for (std::size_t i = 0; i < auditCatalogue().size(); ++i)
            QTest::newRow(qPrintable(auditCatalogue()[i].name)) << int(i);
    }

    void auditCase()
    {
        QFETCH(int, index);
        const AuditCase& c = auditCatalogue().at(std::size_t(index));
        const AuditOutcome o = runAuditCase(c, *m_headless);
        qInfo("%s", qPrintable(o.happened));
        QVERIFY2(o.finite, qPrintable(o.happened));
        QVERIFY2(o.pass, qPrintable(QStringLiteral("expected: %1; happened: %2").arg(c.expected, o.happened)));
    }
};

#include "HeadlessTestMain.h"
SHADOWLAB_TEST_MAIN(TestAudit)
#include "tst_Audit.moc"
