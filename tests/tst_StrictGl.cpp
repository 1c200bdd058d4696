// ShadowLab declares OpenGL 3.3 core. llvmpipe, where the suite runs, offers 4.5 and so would
// hide a later feature used by mistake; Mesa's softpipe is another rasteriser that offers exactly
// 3.3 core. The presets, a point light, cascades, a virtual map and moment techniques render on
// both, and their shadow terms (shading.shadow_only) agree but for a few pixels along shadow edges,
// where the two rasterisers' rounding and texture filtering differ.
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <cstdlib>

namespace {

struct Rendered {
    QImage image;
    QString renderer;   // the "headless platform: ..." line
    QString error;
};

Rendered render(const QString& driver, const QStringList& settings, const QString& out)
{
    QProcess process;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("GALLIUM_DRIVER"), driver);
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("headless"));
    process.setProcessEnvironment(env);
    QStringList arguments{QStringLiteral("render"), QStringLiteral("--size"), QStringLiteral("160x90"), QStringLiteral("--out"), out,
                          QStringLiteral("--set"), QStringLiteral("shading.shadow_only=true")};
    for (const QString& s : settings)
        arguments << QStringLiteral("--set=") + s;
    process.start(QStringLiteral(SHADOWLAB_BINARY), arguments);
    Rendered r;
    if (!process.waitForFinished(240000) || process.exitStatus() != QProcess::NormalExit || process.exitCode() != 0) {
        r.error = QString::fromUtf8(process.readAllStandardError());
        return r;
    }
    const QString log = QString::fromUtf8(process.readAllStandardOutput() + process.readAllStandardError());
    for (const QString& line : log.split(QLatin1Char('\n'))) {
        if (line.startsWith(QStringLiteral("headless platform:")))
            r.renderer = line;
    }
    r.image = QImage(out).convertToFormat(QImage::Format_RGB32);
    return r;
}

} // namespace

class TestStrictGl : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void agreesWithLlvmpipe_data()
    {
        QTest::addColumn<QStringList>("settings");
        QTest::addColumn<int>("channelTolerance");      // filtered shadows: the filtering differs
        for (const char* preset : {"seed", "torus", "cubes", "occluder", "bleeding", "foliage", "city"})
            QTest::newRow(preset) << QStringList{QStringLiteral("scene=") + QString::fromLatin1(preset), QStringLiteral("map.size=512"),
                                                 QStringLiteral("filter.mode=hard")} << 8;
        QTest::newRow("point light") << QStringList{"scene=seed", "light.type=point", "map.size=256", "filter.mode=hard"} << 8;
        QTest::newRow("4 cascades") << QStringList{"scene=seed", "shadow.cascades=4", "map.size=256", "filter.mode=pcf"} << 8;
        QTest::newRow("virtual map") << QStringList{"scene=city", "shadow.virtual=true", "filter.mode=hard"} << 8;
        QTest::newRow("vsm") << QStringList{"scene=seed", "filter.mode=vsm", "map.size=512"} << 40;
        QTest::newRow("msm, point light") << QStringList{"scene=torus", "filter.mode=msm", "light.type=point", "map.size=256"} << 40;
        QTest::newRow("hw-bilinear, spot") << QStringList{"scene=cubes", "light.type=spot", "map.size=512"} << 40;
    }

    void agreesWithLlvmpipe()
    {
        QFETCH(QStringList, settings);
        QFETCH(int, channelTolerance);
        QTemporaryDir dir;
        const Rendered strict = render(QStringLiteral("softpipe"), settings, dir.filePath(QStringLiteral("softpipe.png")));
        QVERIFY2(strict.error.isEmpty(), qPrintable(QStringLiteral("softpipe: ") + strict.error));
        QVERIFY2(strict.renderer.contains(QStringLiteral("softpipe")) && strict.renderer.contains(QStringLiteral("OpenGL 3.3")),
                 qPrintable(strict.renderer));
        const Rendered usual = render(QStringLiteral("llvmpipe"), settings, dir.filePath(QStringLiteral("llvmpipe.png")));
        QVERIFY2(usual.error.isEmpty(), qPrintable(QStringLiteral("llvmpipe: ") + usual.error));
        QCOMPARE(strict.image.size(), usual.image.size());
        // A pixel differs where a channel differs by more than the tolerance; shadowed pixels
        // (dark in the shadow-only view) show there is a shadow to compare.
        int differing = 0, shadowed = 0;
        for (int y = 0; y < usual.image.height(); ++y) {
            for (int x = 0; x < usual.image.width(); ++x) {
                const QRgb a = strict.image.pixel(x, y), b = usual.image.pixel(x, y);
                const int d = std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)), std::abs(qBlue(a) - qBlue(b))});
                differing += d > channelTolerance;
                shadowed += qGray(b) < 60;
            }
        }
        const int pixels = usual.image.width() * usual.image.height();
        const QString numbers = QStringLiteral("%1 of %2 pixels differ by more than %3 (%4 %), %5 shadowed; %6")
                                    .arg(differing).arg(pixels).arg(channelTolerance).arg(100.0 * differing / pixels, 0, 'f', 2).arg(shadowed).arg(strict.renderer);
        QVERIFY2(shadowed > pixels / 100, qPrintable(numbers));
        QVERIFY2(differing <= pixels / 200, qPrintable(numbers));
        qInfo().noquote() << numbers;
    }
};

QTEST_GUILESS_MAIN(TestStrictGl)
#include "tst_StrictGl.moc"
