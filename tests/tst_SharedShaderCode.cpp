// What C++ and the shaders declare once.
// - GLSL that C++ runs too (shaders/shared/, core/SharedShaderCode.h): each function, run on the
//   GPU over a grid of inputs and here on the same inputs, gives the same answer. Integers (a
//   view, a level, a page) exactly; colours and depths to within float rounding. The inputs are
//   exact in float on both sides (small integers and binary fractions), so a difference is the
//   functions'.
// - The uniform blocks (renderer/UniformBlocks.h): in the programs that read them, the driver
//   lays every member out where the C++ struct has it, and the block reads from its binding.
#include "HeadlessRenderer.h"
#include "HeadlessTestMain.h"
#include "LitPass.h"
#include "RenderError.h"
#include "SettingsKeys.h"
#include "ShaderProgram.h"
#include "SharedShaderCode.h"
#include "UniformBlocks.h"

#include <QFile>
#include <QOpenGLFramebufferObject>
#include <QOpenGLShaderProgram>
#include <QTest>

#include <glm/vec4.hpp>

#include <cmath>
#include <vector>

using namespace shadowlab;

namespace {

constexpr int kSide = 64;   // a grid of kSide² inputs, one per pixel

// Which function a row runs. The GLSL below and inputsAt()/expected() follow the same order.
enum class Function { DensityRamp, SliceDepth, CubeFace, Cascade, VirtualLevels, VirtualWindow, VirtualRequest };

// One pixel's inputs, from its integer coordinates only.
struct Inputs {
    int x, y;
    float t;        // (x + kSide * y) / kSide², in [0, 1)
};

const char* kFragment = R"glsl(
uniform int uFunction;
out vec4 result;

void main()
{
    int x = int(gl_FragCoord.x), y = int(gl_FragCoord.y);
    float t = float(x + 64 * y) / 4096.0f;
    if (uFunction == 0) {
        result = vec4(densityRamp(t * 64.0f), 0.0f);
    } else if (uFunction == 1) {
        result = vec4(sliceDepthOf(t, vec3(0.25f, 0.5f, 0.8f)), 0.0f, 0.0f, 0.0f);
    } else if (uFunction == 2) {
        result = vec4(float(cubeFace(vec3(float(x - 32), float(y - 32), float((x * y) % 17 - 8)))), 0.0f, 0.0f, 0.0f);
    } else if (uFunction == 3) {
        result = vec4(float(cascadeIndex(t * 48.0f, vec4(5.0f, 10.0f, 20.0f, 40.0f), 1 + y % 4)), 0.0f, 0.0f, 0.0f);
    } else if (uFunction == 4) {
        result = vec4(float(virtualDensityLevel(t * 300.0f, y % 3, 8)), float(virtualFallbackLevel(x % 8, y % 10 - 1)),
                      float(virtualDensityLevel(float(1 << (x % 12)), y % 3, 12)), 0.0f);
    } else if (uFunction == 5) {
        vec2 q = virtualLevelPosition(x % 4, vec2(float(x) * 3.5f, float(y) * 9.25f - 200.0f), vec2(-10.5f, 3.25f));
        result = vec4(q, virtualWindowHolds(q) ? 1.0f : 0.0f, 0.0f);
    } else {
        uint request = virtualPackRequest(x % 16, ivec2((x * 2) % 128, (y * 3) % 128));
        ivec3 back = virtualUnpackRequest(request);
        result = vec4(float(request), vec3(back));
    }
}
)glsl";

glm::vec4 expected(Function f, const Inputs& in)
{
    const int x = in.x, y = in.y;
    const float t = in.t;
    switch (f) {
    case Function::DensityRamp:
        return {glsl::densityRamp(t * 64.0f), 0.0f};
    case Function::SliceDepth:
        return {glsl::sliceDepthOf(t, glm::vec3(0.25f, 0.5f, 0.8f)), 0.0f, 0.0f, 0.0f};
    case Function::CubeFace:
        return {float(glsl::cubeFace(glm::vec3(float(x - 32), float(y - 32), float((x * y) % 17 - 8)))), 0.0f, 0.0f, 0.0f};
    case Function::Cascade:
        return {float(glsl::cascadeIndex(t * 48.0f, glm::vec4(5.0f, 10.0f, 20.0f, 40.0f), 1 + y % 4)), 0.0f, 0.0f, 0.0f};
    case Function::VirtualLevels:
        // The third at exact powers of two, where floor(log2) rounds either way if log2 is not exact.
        return {float(glsl::virtualDensityLevel(t * 300.0f, y % 3, 8)), float(glsl::virtualFallbackLevel(x % 8, y % 10 - 1)),
                float(glsl::virtualDensityLevel(float(1 << (x % 12)), y % 3, 12)), 0.0f};
    case Function::VirtualWindow: {
        const glm::vec2 q = glsl::virtualLevelPosition(x % 4, glm::vec2(float(x) * 3.5f, float(y) * 9.25f - 200.0f), glm::vec2(-10.5f, 3.25f));
        return {q, glsl::virtualWindowHolds(q) ? 1.0f : 0.0f, 0.0f};
    }
    case Function::VirtualRequest: {
        const glm::uint request = glsl::virtualPackRequest(x % 16, glm::ivec2((x * 2) % 128, (y * 3) % 128));
        return {float(request), glm::vec3(glsl::virtualUnpackRequest(request))};
    }
    }
    return {};
}

QByteArray sharedSource()
{
    QByteArray source;
    for (const char* file : {"density_ramp.glsl", "depth_slice_decode.glsl", "view_choice.glsl", "virtual_levels.glsl"}) {
        QFile f(QStringLiteral(":/shaders/shared/") + QLatin1String(file));
        if (!f.open(QIODevice::ReadOnly))
            qFatal("missing shader resource %s", file);
        source += f.readAll() + '\n';
    }
    return source;
}

} // namespace

class TestSharedShaderCode : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        m_headless = std::make_unique<HeadlessRenderer>();
        m_headless->makeCurrent();
        // The prelude every program gets (the version and the shared constants), then the shared
        // files as they are, then the grid.
        const QByteArray prelude = loadShaderSource(QStringLiteral("fullscreen.vert"), {}).split('\n').first() + '\n' + glslConstants();
        m_program = std::make_unique<QOpenGLShaderProgram>();
        QVERIFY2(m_program->addShaderFromSourceCode(QOpenGLShader::Vertex, loadShaderSource(QStringLiteral("fullscreen.vert"), {})),
                 qPrintable(m_program->log()));
        QVERIFY2(m_program->addShaderFromSourceCode(QOpenGLShader::Fragment, prelude + sharedSource() + kFragment), qPrintable(m_program->log()));
        QVERIFY2(m_program->link(), qPrintable(m_program->log()));
    }

    void cleanupTestCase()
    {
        m_headless->makeCurrent();
        m_program.reset();
    }

    void gpuAndCpuAgree_data()
    {
        QTest::addColumn<int>("functionIndex");
        QTest::addColumn<float>("tolerance");   // 0: exactly
        QTest::newRow("densityRamp") << int(Function::DensityRamp) << 1e-5f;
        QTest::newRow("sliceDepthOf") << int(Function::SliceDepth) << 1e-6f;
        QTest::newRow("cubeFace") << int(Function::CubeFace) << 0.0f;
        QTest::newRow("cascadeIndex") << int(Function::Cascade) << 0.0f;
        QTest::newRow("virtualDensityLevel, virtualFallbackLevel") << int(Function::VirtualLevels) << 0.0f;
        QTest::newRow("virtualLevelPosition, virtualWindowHolds") << int(Function::VirtualWindow) << 0.0f;
        QTest::newRow("virtualPackRequest, virtualUnpackRequest") << int(Function::VirtualRequest) << 0.0f;
    }

    void gpuAndCpuAgree()
    {
        QFETCH(int, functionIndex);
        const auto function = Function(functionIndex);
        QFETCH(float, tolerance);
        m_headless->makeCurrent();
        GlFunctions* gl = m_headless->functions();
        QOpenGLFramebufferObjectFormat format;
        format.setInternalTextureFormat(GL_RGBA32F);
        QOpenGLFramebufferObject target(kSide, kSide, format);
        QVERIFY(target.bind());
        gl->glViewport(0, 0, kSide, kSide);
        gl->glDisable(GL_DEPTH_TEST);
        m_program->bind();
        m_program->setUniformValue("uUvOffset", 0.0f, 0.0f);
        m_program->setUniformValue("uUvScale", 1.0f, 1.0f);
        m_program->setUniformValue("uFunction", int(function));
        GLuint vertexArray = 0;
        gl->glGenVertexArrays(1, &vertexArray);
        gl->glBindVertexArray(vertexArray);
        gl->glDrawArrays(GL_TRIANGLES, 0, 3);
        gl->glBindVertexArray(0);
        gl->glDeleteVertexArrays(1, &vertexArray);
        std::vector<glm::vec4> gpu(std::size_t(kSide * kSide));
        gl->glReadPixels(0, 0, kSide, kSide, GL_RGBA, GL_FLOAT, gpu.data());
        target.release();

        int differing = 0;
        QString first;
        for (int y = 0; y < kSide; ++y) {
            for (int x = 0; x < kSide; ++x) {
                const Inputs in{x, y, float(x + kSide * y) / float(kSide * kSide)};
                const glm::vec4 cpu = expected(function, in), got = gpu[std::size_t(x + kSide * y)];
                for (int c = 0; c < 4; ++c) {
                    if (std::abs(cpu[c] - got[c]) > tolerance) {
                        if (differing++ == 0)
                            first = QStringLiteral("at (%1, %2), channel %3: GPU %4, C++ %5").arg(x).arg(y).arg(c).arg(double(got[c]), 0, 'g', 9).arg(double(cpu[c]), 0, 'g', 9);
                    }
                }
            }
        }
        QVERIFY2(differing == 0, qPrintable(QStringLiteral("%1 values differ; the first %2").arg(differing).arg(first)));
    }

    void uniformBlocksMatchTheDriver_data()
    {
        QTest::addColumn<QString>("fragment");
        QTest::addColumn<QStringList>("settings");  // the lit pass's variant for them; none: no defines
        QTest::addColumn<QStringList>("blocks");    // those the program must read
        const QString lit = QStringLiteral("lit.frag");
        const QStringList views{QStringLiteral("ShadowViewBlock"), QStringLiteral("LitFrameBlock")};
        QTest::newRow("cascades, pcss, early out, contact shadows")
            << lit << QStringList{"shadow.cascades=3", "filter.mode=pcss", "filter.early_out=true", "contact.enabled=true", "bias.space=texel"} << views;
        QTest::newRow("virtual map, poisson") << lit << QStringList{"shadow.virtual=true", "filter.mode=poisson"}
                                              << views + QStringList{QStringLiteral("VirtualMapBlock")};
        QTest::newRow("msm, point light") << lit << QStringList{"light.type=point", "filter.mode=msm"} << views;
        QTest::newRow("spot light, dpcf") << lit << QStringList{"light.type=spot", "filter.mode=dpcf"} << views;
        QTest::newRow("virtual map's requests") << QStringLiteral("virtual_request.frag") << QStringList() << QStringList{QStringLiteral("VirtualMapBlock")};
    }

    void uniformBlocksMatchTheDriver()
    {
        QFETCH(QString, fragment);
        QFETCH(QStringList, settings);
        QFETCH(QStringList, blocks);
        Settings s;
        for (const QString& assignment : settings)
            applyAssignment(s, assignment);
        const QStringList defines = settings.isEmpty() ? QStringList() : LitPass::variantDefines(planFrame(s, true, true));
        m_headless->makeCurrent();
        GlFunctions* gl = m_headless->functions();
        std::unique_ptr<ShaderProgram> made;
        try {
            made = std::make_unique<ShaderProgram>(gl, QStringLiteral("lit.vert"), fragment, defines);
        } catch (const RenderError& e) {
            QFAIL(e.what());
        }
        ShaderProgram& program = *made;
        for (const QString& name : blocks) {
            const UniformBlockDeclaration* block = uniformBlock(name);
            QVERIFY(block);
            const GLuint index = gl->glGetUniformBlockIndex(program.id(), block->name);
            QVERIFY2(index != GL_INVALID_INDEX, qPrintable(name + QStringLiteral(" is not read")));
            GLint size = 0, binding = -1;
            gl->glGetActiveUniformBlockiv(program.id(), index, GL_UNIFORM_BLOCK_DATA_SIZE, &size);
            gl->glGetActiveUniformBlockiv(program.id(), index, GL_UNIFORM_BLOCK_BINDING, &binding);
            QVERIFY2(size > 0 && std::size_t(size) <= block->size, qPrintable(QStringLiteral("%1: %2 bytes, C++ %3").arg(name).arg(size).arg(block->size)));
            QCOMPARE(binding, GLint(block->binding));
            for (const std140::Member& member : block->members) {
                GLuint memberIndex = GL_INVALID_INDEX;
                gl->glGetUniformIndices(program.id(), 1, &member.name, &memberIndex);
                QVERIFY2(memberIndex != GL_INVALID_INDEX, member.name);
                GLint offset = -1, stride = -1;
                gl->glGetActiveUniformsiv(program.id(), 1, &memberIndex, GL_UNIFORM_OFFSET, &offset);
                gl->glGetActiveUniformsiv(program.id(), 1, &memberIndex, GL_UNIFORM_ARRAY_STRIDE, &stride);
                QVERIFY2(offset == GLint(member.offset), qPrintable(QStringLiteral("%1: driver %2, C++ %3").arg(member.name).arg(offset).arg(member.offset)));
                QVERIFY2(stride == GLint(member.arrayStride), qPrintable(QStringLiteral("%1's stride: driver %2, C++ %3").arg(member.name).arg(stride).arg(member.arrayStride)));
            }
        }
    }

private:
    std::unique_ptr<HeadlessRenderer> m_headless;
    std::unique_ptr<QOpenGLShaderProgram> m_program;
};

SHADOWLAB_TEST_MAIN(TestSharedShaderCode)
#include "tst_SharedShaderCode.moc"
