// The numbers C++ and the shaders share (core/ShaderConstants.h): every program's source starts
// with each of them under its C++ name, at exactly the value C++ has, and no shader file writes
// one as a literal of its own. No GL context: sources are read from the resources.
#include "ShaderConstants.h"
#include "ShaderProgram.h"
#include "ShadowViews.h"
#include "VirtualPages.h"

#include <QDirIterator>
#include <QFile>
#include <QRegularExpression>
#include <QTest>

#include <algorithm>
#include <cstdlib>
#include <utility>
#include <vector>

using namespace shadowlab;

namespace {

// Each constant as GLSL reads it: the shaders wrote these values as these literals before.
const std::vector<std::pair<QByteArray, QByteArray>> kDefines = {
    {"kVirtualPageTexels", "#define kVirtualPageTexels 128"},
    {"kVirtualPageBorder", "#define kVirtualPageBorder 4"},
    {"kVirtualSlotTexels", "#define kVirtualSlotTexels 136"},
    {"kVirtualLevelPages", "#define kVirtualLevelPages 128"},
    {"kMaxVirtualLevels", "#define kMaxVirtualLevels 16"},
    {"kMaxShadowViews", "#define kMaxShadowViews 6"},
    {"kPcf64Side", "#define kPcf64Side 8"},
    {"kPcf64TapReach", "#define kPcf64TapReach 3.5"},
    {"kPcssBlockerTaps", "#define kPcssBlockerTaps 16"},
    {"kMaxBlurWeights", "#define kMaxBlurWeights 16"},
    {"kMaxDepthRangeLevels", "#define kMaxDepthRangeLevels 16"},
    {"kNoCasterDepth", "#define kNoCasterDepth 1e+30"},
    {"kOwnFacetCosine", "#define kOwnFacetCosine 0.001"},
    {"kViewTints", "#define kViewTints vec3[6](vec3(1.0, 0.25, 0.25), vec3(0.25, 1.0, 0.25), vec3(0.3, 0.45, 1.0), "
                   "vec3(1.0, 0.9, 0.2), vec3(1.0, 0.3, 1.0), vec3(0.2, 1.0, 1.0))"},
    {"kDensityBlue", "#define kDensityBlue vec3(0.15, 0.35, 0.95)"},
    {"kDensityGreen", "#define kDensityGreen vec3(0.1, 0.8, 0.25)"},
    {"kDensityYellow", "#define kDensityYellow vec3(0.95, 0.85, 0.1)"},
    {"kDensityRed", "#define kDensityRed vec3(0.95, 0.15, 0.1)"},
    {"kOutsideMapColour", "#define kOutsideMapColour vec3(0.15, 0.16, 0.2)"},
};

const ShaderConstant* constantNamed(const QByteArray& name)
{
    const auto all = shaderConstants();
    const auto it = std::find_if(all.begin(), all.end(), [&](const ShaderConstant& c) { return name == c.name; });
    return it == all.end() ? nullptr : &*it;
}

// Every shader file of the resources with its comments left out (they may quote values).
std::vector<std::pair<QString, QString>> shaderCode()
{
    static const QRegularExpression comment(QStringLiteral(R"(//[^\n]*|/\*.*?\*/)"), QRegularExpression::DotMatchesEverythingOption);
    std::vector<std::pair<QString, QString>> files;
    QDirIterator it(QStringLiteral(":/shaders"), QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        QFile file(it.next());
        if (file.open(QIODevice::ReadOnly))
            files.emplace_back(file.fileName(), QString::fromUtf8(file.readAll()).remove(comment));
    }
    return files;
}

// A number as GLSL spells one: "128", "128u", "3.5", ".5", "1e30", "1e+30" (no sign: that is
// an operator). Not part of a name (vec3) or of a longer number.
const QString kNumber = QStringLiteral(R"((?<![\w.])(\d+\.?\d*(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?)[uUfF]?(?![\w.]))");

} // namespace

class tst_ShaderConstants : public QObject {
    Q_OBJECT

private slots:
    void defined_data()
    {
        QTest::addColumn<QByteArray>("name");
        QTest::addColumn<QByteArray>("define");
        for (const auto& [name, define] : kDefines)
            QTest::newRow(name.constData()) << name << define;
    }

    // The constant is defined as above, in front of every program's source.
    void defined()
    {
        QFETCH(QByteArray, name);
        QFETCH(QByteArray, define);
        const ShaderConstant* constant = constantNamed(name);
        QVERIFY2(constant, name.constData());
        QCOMPARE(glslDefine(*constant), define);
        for (const QString& file : {QStringLiteral("fullscreen.vert"), QStringLiteral("momentsblur.frag"), QStringLiteral("virtual_reduce.vert")}) {
            const QByteArray source = loadShaderSource(file, {});
            QVERIFY2(source.startsWith("#version 330 core\n"), qPrintable(file));
            QVERIFY2(source.contains('\n' + define + '\n'), qPrintable(file));
        }
    }

    // A constant added to the table gets a row above.
    void everyConstantHasARow()
    {
        QCOMPARE(shaderConstants().size(), kDefines.size());
    }

    // Only preprocessor lines, which may come before a shader's #extension lines (the
    // depth-range pass has one); a declaration there fails to compile.
    void preludeIsPreprocessorOnly()
    {
        const QList<QByteArray> lines = glslConstants().trimmed().split('\n');
        QCOMPARE(lines.size(), qsizetype(kDefines.size()));
        for (const QByteArray& line : lines)
            QVERIFY2(line.startsWith("#define "), line.constData());
    }

    void floatsReadBack_data()
    {
        QTest::addColumn<float>("value");
        for (const float v : {0.1f, 0.3f, 0.45f, 0.95f, 1.0f, 3.5f, 128.0f, 1.0f / 3.0f, 16777216.0f, 1e-7f, 1e30f, 0.0f})
            QTest::newRow(QByteArray::number(double(v), 'g', 9).constData()) << v;
    }

    // GLSL reads each float the table writes back as exactly that float, as a float literal.
    void floatsReadBack()
    {
        QFETCH(float, value);
        const QByteArray text = glslFloat(value);
        static const QRegularExpression floatLiteral(QStringLiteral(R"(^(\d+\.\d*([eE][+-]?\d+)?|\d+[eE][+-]?\d+)$)"));
        QVERIFY2(floatLiteral.match(QString::fromLatin1(text)).hasMatch(), text.constData());
        QCOMPARE(std::strtof(text.constData(), nullptr), value);
    }

    void noShaderWritesTheNumber_data()
    {
        QTest::addColumn<double>("value");
        // Those values a shader has no other use for; small counts such as 4, 6, 8 and 16 do
        // have others, and so does kNoCasterDepth's 1e30 (the depth-range reduction's neutral
        // value), so they are left out.
        QTest::newRow("kVirtualPageTexels") << double(kVirtualPageTexels);
        QTest::newRow("kVirtualLevelPages") << double(kVirtualLevelPages);
        QTest::newRow("kVirtualLevelPages - 1") << double(kVirtualLevelPages - 1);
        QTest::newRow("kVirtualLevelPages squared") << double(kVirtualLevelPages * kVirtualLevelPages);
        QTest::newRow("kVirtualSlotTexels") << double(kVirtualSlotTexels);
        QTest::newRow("kPcf64TapReach") << double(kPcf64TapReach);
    }

    // No shader file spells the number out where the constant's name belongs.
    void noShaderWritesTheNumber()
    {
        QFETCH(double, value);
        const std::vector<std::pair<QString, QString>> files = shaderCode();
        QVERIFY(files.size() > 20);
        const QRegularExpression number(kNumber);
        for (const auto& [file, code] : files) {
            for (auto it = number.globalMatch(code); it.hasNext();) {
                const QString literal = it.next().captured(1);
                QVERIFY2(float(literal.toDouble()) != float(value), qPrintable(QStringLiteral("%1 writes %2").arg(file, literal)));
            }
        }
    }

    void noShaderWritesTheColour_data()
    {
        QTest::addColumn<Rgb>("colour");
        for (const ShaderConstant& c : shaderConstants()) {
            if (const Rgb* rgb = std::get_if<Rgb>(&c.value))
                QTest::newRow(c.name) << *rgb;
            if (const auto* list = std::get_if<std::span<const Rgb>>(&c.value)) {
                for (std::size_t i = 0; i < list->size(); ++i)
                    QTest::addRow("%s[%d]", c.name, int(i)) << (*list)[i];
            }
        }
    }

    // No vec3 or vec4 whose first three components are the colour.
    void noShaderWritesTheColour()
    {
        QFETCH(Rgb, colour);
        const QRegularExpression vector(QStringLiteral(R"(vec[34]\(\s*%1\s*,\s*%1\s*,\s*%1\s*[,)])").arg(kNumber));
        for (const auto& [file, code] : shaderCode()) {
            for (auto it = vector.globalMatch(code); it.hasNext();) {
                const QRegularExpressionMatch m = it.next();
                const Rgb written{m.captured(1).toFloat(), m.captured(2).toFloat(), m.captured(3).toFloat()};
                QVERIFY2(written != colour, qPrintable(QStringLiteral("%1 writes %2").arg(file, m.captured(0))));
            }
        }
    }
};

QTEST_GUILESS_MAIN(tst_ShaderConstants)
#include "tst_ShaderConstants.moc"
