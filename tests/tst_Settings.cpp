// Settings without GL: every key parses, prints and round-trips; every bad value is refused
// with a message that names the key and the allowed range, and leaves the settings unchanged.
#include "SceneLibrary.h"
#include "SettingRelevance.h"
#include "SettingsError.h"
#include "SettingsKeys.h"
#include "ShadowTechnique.h"

#include <QJsonDocument>
#include <QTemporaryDir>
#include <QtTest>

using namespace shadowlab;

class TestSettings : public QObject {
    Q_OBJECT

private Q_SLOTS:
    // A field the current settings do not read says so, and what would make it count; the
    // same field counts again once that is set.
    // Objects switched off by name or index: trimmed, each once, an index a whole number.
    void objectSwitchesParse()
    {
        Settings s;
        applySetting(s, "objects.no_cast", " high cube , #2,high cube,, ");
        QCOMPARE(s.objects.noCast, (QStringList{"high cube", "#2"}));
        QCOMPARE(settingValue(s, "objects.no_cast"), QStringLiteral("high cube,#2"));
        applySetting(s, "objects.no_receive", "");
        QVERIFY(s.objects.noReceive.isEmpty());
        for (const char* bad : {"#-1", "#x", "#"}) {
            try {
                applySetting(s, "objects.no_receive", bad);
                QFAIL(bad);
            } catch (const SettingsError& e) {
                QVERIFY2(QString::fromUtf8(e.what()).contains("whole number from 0"), e.what());
            }
        }
        // A new scene brings its own objects: the switches of the last one do not follow it.
        Settings moved = movedToScene(s, presetSettings("torus"));
        QVERIFY(moved.objects.noCast.isEmpty());
    }

    void ignoredSettingsSayWhy()
    {
        Settings s;     // hw-bilinear, a directional light, one map, no virtual map, no contact shadows
        QVERIFY(ignoredBecause(s, "filter.kernel").contains("pcf"));
        QVERIFY(ignoredBecause(s, "bias.receiver_plane").contains("one lookup"));
        QVERIFY(ignoredBecause(s, "shadow.virtual_pool").contains("shadow.virtual"));
        QVERIFY(ignoredBecause(s, "shadow.split").contains("shadow.cascades"));
        QVERIFY(ignoredBecause(s, "contact.steps").contains("contact.enabled"));
        QVERIFY(ignoredBecause(s, "moments.blur").contains("moment"));
        QVERIFY(ignoredBecause(s, "light.warp_scale").contains("lispsm"));
        for (const char* key : {"map.size", "bias.slope", "filter.mode", "shadow.cascades", "shadow.virtual", "light.position", "shadow.enabled"})
            QVERIFY2(ignoredBecause(s, key).isEmpty(), key);
        applySetting(s, "filter.mode", "pcf64");
        QVERIFY(ignoredBecause(s, "bias.receiver_plane").isEmpty());    // its 64 taps lie on the plane
        applySetting(s, "filter.mode", "pcf");
        QVERIFY(ignoredBecause(s, "filter.kernel").isEmpty());
        applySetting(s, "shadow.virtual", "true");
        QVERIFY(ignoredBecause(s, "shadow.virtual_pool").isEmpty());
        QVERIFY(ignoredBecause(s, "shadow.cascades").contains("replaces cascades"));
        QVERIFY(ignoredBecause(s, "map.slices").contains("virtual"));
        applySetting(s, "shadow.virtual", "false");
        applySetting(s, "filter.mode", "dpcf");
        QVERIFY(ignoredBecause(s, "filter.early_out").isEmpty());       // dpcf skips its taps outside penumbrae too
        applySetting(s, "filter.mode", "pcf");
        applySetting(s, "shadow.cascades", "3");
        QVERIFY(ignoredBecause(s, "map.slices").contains("cascades"));
        applySetting(s, "shadow.split", "uniform");
        QVERIFY(ignoredBecause(s, "shadow.split").isEmpty());
        QVERIFY(ignoredBecause(s, "shadow.split_lambda").contains("practical"));
        applySetting(s, "filter.mode", "msm");
        QVERIFY(ignoredBecause(s, "moments.blur").isEmpty());
        QVERIFY(ignoredBecause(s, "bias.cull_front").contains("filter.moment_bias"));
        QVERIFY(ignoredBecause(s, "bias.skip_floors").isEmpty());                  // four moments: floors only around the casters
        QVERIFY(ignoredBecause(s, "moments.blur_at").isEmpty());
        applySetting(s, "moments.anisotropy", "4");
        QVERIFY(ignoredBecause(s, "bias.skip_floors").contains("no coverage"));     // ... or, read anywhere, in the whole map
        applySetting(s, "moments.anisotropy", "1");
        applySetting(s, "filter.mode", "msm-hausdorff");
        QVERIFY(ignoredBecause(s, "bias.skip_floors").contains("far plane"));
        applySetting(s, "filter.mode", "msm");
        applySetting(s, "filter.mode", "vsm");
        QVERIFY(ignoredBecause(s, "bias.skip_floors").isEmpty());                  // coverage: floors stay out
        applySetting(s, "moments.mipmaps", "true");
        QVERIFY(ignoredBecause(s, "moments.blur_at").contains("moments.mipmaps"));
        applySetting(s, "moments.mipmaps", "false");
        applySetting(s, "moments.blur", "0");
        QVERIFY(ignoredBecause(s, "moments.blur_at").contains("blurs nothing"));
        applySetting(s, "light.type", "point");
        QVERIFY(ignoredBecause(s, "shadow.cascades").contains("six cube faces"));
        QVERIFY(!ignoredBecause(s, "shadow.virtual_pool").isEmpty());
        applySetting(s, "shadow.enabled", "false");
        for (const SettingKey& key : settingKeys()) {
            const bool shadowKey = key.key.startsWith("map.") || key.key.startsWith("bias.") || key.key.startsWith("filter.");
            QVERIFY2(!shadowKey || ignoredBecause(s, key.key).contains("shadow.enabled"), qPrintable(key.key));
        }
        QVERIFY(ignoredBecause(s, "camera.fov").isEmpty());
    }

    // The table is the dock's only source: every key names its label and group, and its slider
    // lies inside its range.
    void everyKeyCarriesItsPresentation()
    {
        for (const SettingKey& key : settingKeys()) {
            const SettingPresentation& p = key.presentation;
            QVERIFY2(!p.label.isEmpty(), qPrintable(key.key));
            QVERIFY2(settingGroups().contains(p.group), qPrintable(key.key + ": group '" + p.group + "'"));
            if (key.type == u"number" || key.type == u"integer") {
                QVERIFY2(p.sliderLow < p.sliderHigh, qPrintable(key.key));
                QVERIFY2(p.sliderLow >= key.minimum && p.sliderHigh <= key.maximum, qPrintable(key.key));
                QVERIFY2(!p.logarithmic || p.sliderLow > 0.0, qPrintable(key.key));
            }
            if (key.type == u"integer")
                QVERIFY2(p.decimals == 0, qPrintable(key.key));
        }
        // Every group holds a key.
        for (const QString& group : settingGroups()) {
            QVERIFY2(std::any_of(settingKeys().begin(), settingKeys().end(), [&](const SettingKey& k) { return k.presentation.group == group; }),
                     qPrintable(group));
        }
    }

    void defaultsAreValidForEveryPreset()
    {
        for (const QString& scene : sceneNames()) {
            const Settings s = presetSettings(scene);
            QCOMPARE(s.scene, scene);
            QVERIFY2(validate(s).empty(), qPrintable(scene));
        }
    }

    void everyKeyRoundTrips()
    {
        const Settings defaults;
        for (const SettingKey& k : settingKeys()) {
            Settings s;
            applySetting(s, k.key, settingValue(defaults, k.key));
            QVERIFY2(s == defaults, qPrintable(k.key));
            QVERIFY2(!k.help.isEmpty() && !k.range.isEmpty(), qPrintable(k.key));
        }
    }

    void requiredKeysExist()
    {
        const QStringList required{"light.position", "light.target", "light.projection", "light.extent", "light.fov",
                                   "light.near", "light.far", "map.size", "map.format", "bias.slope", "bias.min",
                                   "bias.cull_front", "bias.polygon_factor", "bias.polygon_units", "filter.mode",
                                   "filter.kernel", "shadow.enabled", "shading.model", "camera.position",
                                   "camera.target", "camera.fov", "scene", "light.fit", "light.stabilize", "bias.normal"};
        for (const QString& key : required)
            QVERIFY2(findSettingKey(key) != nullptr, qPrintable(key));
    }

    void goodValuesApply()
    {
        Settings s;
        applyAssignment(s, "light.position=1, 2.5 ,-3");
        QVERIFY(s.light.position == glm::dvec3(1.0, 2.5, -3.0));
        applyAssignment(s, "filter.mode=pcf-dither4");
        QVERIFY(s.filter.mode == FilterMode::PcfDither4);
        applyAssignment(s, "map.format=depth32f");
        QVERIFY(s.map.format == DepthFormat::Depth32F);
        applyAssignment(s, "bias.cull_front=on");
        QVERIFY(s.bias.cullFront);
        applyAssignment(s, "light.projection=perspective");
        QVERIFY(s.light.projection == LightProjection::Perspective);
        applyAssignment(s, "filter.mode=pcss");
        QVERIFY(s.filter.mode == FilterMode::Pcss);
        applyAssignment(s, "filter.taps=8");
        QCOMPARE(s.filter.taps, 8);
        applyAssignment(s, "filter.taps=64");
        QCOMPARE(s.filter.taps, 64);
        applyAssignment(s, "filter.radius=0.5");
        QCOMPARE(s.filter.radius, 0.5);
        applyAssignment(s, "filter.radius=32");
        QCOMPARE(s.filter.radius, 32.0);
        applyAssignment(s, "bias.receiver_plane=true");
        QVERIFY(s.bias.receiverPlane);
        applyAssignment(s, "filter.early_out=false");
        QVERIFY(!s.filter.earlyOut);
    }

    void badValuesAreRefused_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("value");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("NaN") << "bias.slope" << "nan" << "finite";
        QTest::newRow("infinity") << "light.extent" << "inf" << "finite";
        QTest::newRow("not a number") << "light.far" << "far" << "not a number";
        QTest::newRow("negative bias") << "bias.min" << "-0.1" << "[0, 100]";
        QTest::newRow("fov 180") << "light.fov" << "180" << "(0, 180)";
        QTest::newRow("fov 0") << "light.fov" << "0" << "(0, 180)";
        QTest::newRow("even kernel") << "filter.kernel" << "4" << "is even; it must be odd";
        QTest::newRow("kernel 11") << "filter.kernel" << "11" << "[1, 9]";
        QTest::newRow("map too small") << "map.size" << "8" << "[16, 16384]";
        QTest::newRow("map huge") << "map.size" << "100000" << "[16, 16384]";
        QTest::newRow("unknown filter") << "filter.mode" << "shadow-volumes" << "hard | pcf";
        QTest::newRow("unknown scene") << "scene" << "sponza" << "seed";
        QTest::newRow("unknown fit") << "light.fit" << "auto" << "manual | scene";
        QTest::newRow("normal offset 9") << "bias.normal" << "9" << "[0, 8]";
        QTest::newRow("vector of two") << "light.position" << "1,2" << "x,y,z";
        QTest::newRow("vector with NaN") << "camera.position" << "1,nan,2" << "finite";
        QTest::newRow("not a bool") << "shadow.enabled" << "maybe" << "true | false";
        QTest::newRow("unknown key") << "bias.sloppy" << "1" << "unknown setting (did you mean 'bias.slope'?)";
        QTest::newRow("7 Poisson taps") << "filter.taps" << "7" << "[8, 64]";
        QTest::newRow("65 Poisson taps") << "filter.taps" << "65" << "[8, 64]";
        QTest::newRow("fractional taps") << "filter.taps" << "12.5" << "whole number";
        QTest::newRow("Poisson radius 0.25") << "filter.radius" << "0.25" << "[0.5, 32]";
        QTest::newRow("Poisson radius 33") << "filter.radius" << "33" << "[0.5, 32]";
        QTest::newRow("radius NaN") << "filter.radius" << "nan" << "finite";
        QTest::newRow("receiver plane not a bool") << "bias.receiver_plane" << "sometimes" << "true | false";
        QTest::newRow("early out not a bool") << "filter.early_out" << "2" << "true | false";
    }

    void badValuesAreRefused()
    {
        QFETCH(QString, key);
        QFETCH(QString, value);
        QFETCH(QString, mentions);
        Settings s;
        const Settings before = s;
        try {
            applySetting(s, key, value);
            QFAIL("expected a SettingsError");
        } catch (const SettingsError& e) {
            QCOMPARE(e.key(), key);
            const QString message = QString::fromStdString(e.what());
            QVERIFY2(message.startsWith(key), qPrintable(message));
            QVERIFY2(message.contains(mentions), qPrintable(message));
            // Only a key that is no setting says so: each front end then says where the keys are.
            QCOMPARE(e.isUnknownKey(), key == u"bias.sloppy");
        }
        QVERIFY(s == before);
    }

    void crossFieldRulesNameTheKey_data()
    {
        QTest::addColumn<QStringList>("assignments");
        QTest::addColumn<QString>("key");
        QTest::newRow("near = far") << QStringList{"light.near=5", "light.far=5"} << "light.far";
        QTest::newRow("near > far") << QStringList{"light.near=9", "light.far=5"} << "light.far";
        QTest::newRow("perspective near 0") << QStringList{"light.projection=perspective", "light.near=0"} << "light.near";
        QTest::newRow("light at target") << QStringList{"light.position=1,2,3", "light.target=1,2,3"} << "light.position";
        QTest::newRow("camera at target") << QStringList{"camera.position=0,1,0", "camera.target=0,1,0"} << "camera.position";
        QTest::newRow("depth bias over half the range") << QStringList{"bias.space=depth", "bias.min=0.6"} << "bias.min";
    }

    void crossFieldRulesNameTheKey()
    {
        QFETCH(QStringList, assignments);
        QFETCH(QString, key);
        Settings s;
        for (const QString& a : assignments)
            applyAssignment(s, a);
        const auto issues = validate(s);
        QVERIFY(!issues.empty());
        QVERIFY(issues.front().severity == SettingsIssue::Severity::Error);
        QCOMPARE(issues.front().key, key);
        QVERIFY_THROWS_EXCEPTION(SettingsError, ensureValid(s));
    }

    void riskyButValidValuesWarn()
    {
        Settings s;
        applyAssignment(s, "light.fit=manual");   // a fitted light picks its own near and far
        applyAssignment(s, "light.projection=perspective");
        applyAssignment(s, "light.near=0.001");
        applyAssignment(s, "light.far=100000");
        const auto issues = validate(s);
        QCOMPARE(issues.size(), std::size_t(1));
        QVERIFY(issues.front().severity == SettingsIssue::Severity::Warning);
        ensureValid(s); // warnings do not throw
        applyAssignment(s, "map.format=depth32f");
        QVERIFY(validate(s).empty());
    }

    // pcf-optimized has weights for 3, 5 and 7 texels: another filter.kernel is used as the
    // nearest of those, said in a warning and in the configuration's label.
    void pcfOptimizedSaysWhichKernelItUses()
    {
        for (const auto& [kernel, used] : {std::pair{1, 3}, std::pair{3, 3}, std::pair{5, 5}, std::pair{7, 7}, std::pair{9, 7}}) {
            Settings s;
            applyAssignment(s, "filter.mode=pcf-optimized");
            applyAssignment(s, QString("filter.kernel=%1").arg(kernel));
            QCOMPARE(optimizedPcfKernel(s.filter), used);
            QCOMPARE(filterLabel(s.filter), QString("pcf-optimized %1×%1").arg(used));
            const auto issues = validate(s);
            if (kernel == used) {
                QVERIFY(issues.empty());
                continue;
            }
            QCOMPARE(issues.size(), std::size_t(1));
            QVERIFY(issues.front().severity == SettingsIssue::Severity::Warning);
            QCOMPARE(issues.front().key, QString("filter.kernel"));
            QVERIFY2(issues.front().message.contains(QString("%1 is used").arg(used)), qPrintable(issues.front().message));
            ensureValid(s);
            applyAssignment(s, "filter.mode=pcf");     // pcf has every odd width
            QVERIFY(validate(s).empty());
        }
    }

    void structFieldsOutOfRangeAreCaught()
    {
        Settings s;
        s.bias.slope = std::nan("");
        s.filter.kernel = 2;
        const auto issues = validate(s);
        QCOMPARE(issues.size(), std::size_t(2));
        QCOMPARE(issues[0].key, QString("bias.slope"));
        QCOMPARE(issues[1].key, QString("filter.kernel"));
    }

    void jsonRoundTripsAndAcceptsNestedObjects()
    {
        Settings s = presetSettings("torus");
        applyAssignment(s, "filter.mode=pcf64");
        applyAssignment(s, "bias.slope=0.125");
        QVERIFY(settingsFromJson(settingsToJson(s), Settings{}) == s);

        const QJsonObject nested = QJsonDocument::fromJson(R"({"light": {"position": [1, 2, 3], "far": 20},
                                                              "filter": {"mode": "hard"}})").object();
        const Settings n = settingsFromJson(nested, Settings{});
        QVERIFY(n.light.position == glm::dvec3(1.0, 2.0, 3.0));
        QCOMPARE(n.light.farPlane, 20.0);
        QVERIFY(n.filter.mode == FilterMode::Hard);
    }

    void settingsFilesReportTheirProblems()
    {
        QTemporaryDir dir;
        const QString good = dir.filePath("good.json");
        Settings s;
        applyAssignment(s, "map.size=512");
        saveSettingsFile(good, s);
        QCOMPARE(loadSettingsFile(good, Settings{}).map.size, 512);

        const QString malformed = dir.filePath("malformed.json");
        QFile f(malformed);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("{\"map.size\": 512,");
        f.close();
        try {
            loadSettingsFile(malformed, Settings{});
            QFAIL("expected a SettingsError");
        } catch (const SettingsError& e) {
            QVERIFY(QString(e.what()).contains("malformed.json"));
            QVERIFY(QString(e.what()).contains("not valid JSON"));
        }
        try {
            loadSettingsFile(dir.filePath("missing.json"), Settings{});
            QFAIL("expected a SettingsError");
        } catch (const SettingsError& e) {
            QVERIFY(QString(e.what()).contains("missing.json"));
        }
        QFile bad(dir.filePath("bad.json"));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write(R"({"filter.kernel": 6})");
        bad.close();
        try {
            loadSettingsFile(bad.fileName(), Settings{});
            QFAIL("expected a SettingsError");
        } catch (const SettingsError& e) {
            QCOMPARE(e.key(), QString("filter.kernel"));
            QVERIFY(QString(e.what()).contains("bad.json"));
            QVERIFY2(QString(e.what()).count("filter.kernel") == 1, e.what());     // the file, then the key once
        }
    }

    // The technique table is what filter.mode offers, in FilterMode order; every parameter a
    // technique reads is a key; every sweep variation is valid and selects its technique.
    void techniqueTableDrivesTheKeys()
    {
        const SettingKey* mode = findSettingKey("filter.mode");
        QVERIFY(mode);
        QCOMPARE(mode->choices.size(), qsizetype(shadowTechniques().size()));
        for (std::size_t i = 0; i < shadowTechniques().size(); ++i) {
            const ShadowTechnique& t = shadowTechniques()[i];
            QCOMPARE(int(t.mode), int(i));
            QCOMPARE(mode->choices[qsizetype(i)], t.key);
            QCOMPARE(toString(t.mode), t.key);
            QVERIFY2(mode->help.contains(t.key), qPrintable(t.key));
            QCOMPARE(t.shaderFile, QStringLiteral("shadow/%1.glsl").arg(t.key));
            QVERIFY(!t.samplers.empty());
            QVERIFY(!t.label.isEmpty() && !t.help.isEmpty());
            for (const QString& parameter : t.parameters)
                QVERIFY2(findSettingKey(parameter), qPrintable(parameter));
            QVERIFY2(!t.sweep.empty(), qPrintable(t.key));
            for (const TechniqueVariation& v : t.sweep) {
                Settings s;
                for (const QString& assignment : v.assignments)
                    applyAssignment(s, assignment);
                ensureValid(s);
                QCOMPARE(int(s.filter.mode), int(t.mode));
            }
        }
        for (const TechniqueParameter& p : techniqueParameters()) {
            const SettingKey* key = findSettingKey(p.key);
            QVERIFY2(key, qPrintable(p.key));
            QCOMPARE(key->minimum, p.minimum);
            QCOMPARE(key->maximum, p.maximum);
        }
        Settings pcf;
        applyAssignment(pcf, "filter.mode=pcf");
        applyAssignment(pcf, "filter.kernel=5");
        QCOMPARE(filterLabel(pcf.filter), QStringLiteral("pcf 5×5"));
        QVERIFY(usesParameter(pcf.filter, "filter.kernel"));
        applyAssignment(pcf, "filter.mode=hard");
        QVERIFY(!usesParameter(pcf.filter, "filter.kernel"));
    }

    // PCSS's light is the area reference's disk: light.radius in world units for a perspective
    // light, its angular radius seen from the target for a directional one.
    void pcssLightSizeIsTheReferencesDisk_data()
    {
        QTest::addColumn<QString>("projection");
        QTest::addColumn<double>("radius");
        QTest::addColumn<double>("expected");
        // The default light: position (-2, 4, -1), target the origin, sqrt(21) apart.
        QTest::newRow("ortho 0.25") << "ortho" << 0.25 << 0.25 / std::sqrt(21.0);
        QTest::newRow("ortho 1") << "ortho" << 1.0 << 1.0 / std::sqrt(21.0);
        QTest::newRow("perspective 0.25") << "perspective" << 0.25 << 0.25;
        QTest::newRow("perspective 0") << "perspective" << 0.0 << 0.0;
    }

    void pcssLightSizeIsTheReferencesDisk()
    {
        QFETCH(QString, projection);
        QFETCH(double, radius);
        QFETCH(double, expected);
        Settings s;
        applyAssignment(s, "filter.mode=pcss");
        applyAssignment(s, "light.projection=" + projection);
        applyAssignment(s, QString("light.radius=%1").arg(radius));
        const TechniqueShaderValues values = shadowTechnique(FilterMode::Pcss).shaderValues(s);
        QVERIFY(std::abs(values.lightSize - expected) < 1e-6);
        QCOMPARE(values.poissonRadius, 0.0f);
        QVERIFY(usesParameter(s.filter, "filter.taps"));
        QVERIFY(!usesParameter(s.filter, "filter.radius"));
        QCOMPARE(filterLabel(s.filter), QStringLiteral("pcss 16"));
    }
};

QTEST_APPLESS_MAIN(TestSettings)
#include "tst_Settings.moc"
