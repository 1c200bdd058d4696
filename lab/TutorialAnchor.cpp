#include "TutorialAnchor.h"

#include "RenderError.h"
#include "ReportSweep.h"
#include "SettingsKeys.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <QElapsedTimer>

#include <array>
#include <cmath>
#include <vector>

namespace shadowlab {

namespace {

constexpr int kMapSide = 1024;

const char* const kDepthVertex = R"(#version 330 core
layout(location = 0) in vec3 aPos;
uniform mat4 lightSpaceMatrix;
uniform mat4 model;
void main() { gl_Position = lightSpaceMatrix * model * vec4(aPos, 1.0); }
)";

const char* const kDepthFragment = R"(#version 330 core
void main() {}
)";

// The tutorial's lit pass, step for step: the same reads, the same maths per pixel.
const char* const kLitVertex = R"(#version 330 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexCoords;
out vec3 fragPos;
out vec3 normal;
out vec2 texCoords;
out vec4 fragPosLightSpace;
uniform mat4 projection, view, model, lightSpaceMatrix;
void main()
{
    fragPos = vec3(model * vec4(aPos, 1.0));
    normal = transpose(inverse(mat3(model))) * aNormal;
    texCoords = aTexCoords;
    fragPosLightSpace = lightSpaceMatrix * vec4(fragPos, 1.0);
    gl_Position = projection * view * model * vec4(aPos, 1.0);
}
)";

const char* const kLitFragment = R"(#version 330 core
out vec4 fragColour;
in vec3 fragPos;
in vec3 normal;
in vec2 texCoords;
in vec4 fragPosLightSpace;
uniform sampler2D diffuseTexture;
uniform sampler2D shadowMap;
uniform vec3 lightPos;
uniform vec3 viewPos;

float shadowOf(vec4 lightSpace)
{
    vec3 p = lightSpace.xyz / lightSpace.w * 0.5 + 0.5;
    vec3 n = normalize(normal);
    vec3 toLight = normalize(lightPos - fragPos);
    float bias = max(0.05 * (1.0 - dot(n, toLight)), 0.005);
    float shadow = 0.0;
    vec2 texel = 1.0 / textureSize(shadowMap, 0);
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y)
            shadow += p.z - bias > texture(shadowMap, p.xy + vec2(x, y) * texel).r ? 1.0 : 0.0;
    shadow /= 9.0;
    if (p.z > 1.0)
        shadow = 0.0;
    return shadow;
}

void main()
{
    vec3 colour = texture(diffuseTexture, texCoords).rgb;
    vec3 n = normalize(normal);
    vec3 lightColour = vec3(0.3);
    vec3 ambient = 0.3 * colour;
    vec3 toLight = normalize(lightPos - fragPos);
    vec3 diffuse = max(dot(toLight, n), 0.0) * lightColour;
    vec3 toEye = normalize(viewPos - fragPos);
    vec3 halfway = normalize(toLight + toEye);
    vec3 specular = pow(max(dot(n, halfway), 0.0), 64.0) * lightColour;
    float shadow = shadowOf(fragPosLightSpace);
    fragColour = vec4((ambient + (1.0 - shadow) * (diffuse + specular)) * colour, 1.0);
}
)";

std::unique_ptr<QOpenGLShaderProgram> buildProgram(const char* vertex, const char* fragment, const char* name)
{
    auto program = std::make_unique<QOpenGLShaderProgram>();
    if (!program->addShaderFromSourceCode(QOpenGLShader::Vertex, vertex) || !program->addShaderFromSourceCode(QOpenGLShader::Fragment, fragment)
        || !program->link())
        throw RenderError(QStringLiteral("the tutorial anchor's %1 program does not build: %2").arg(QLatin1String(name), program->log()));
    return program;
}

// Position, normal and uv of each vertex, as the tutorial's arrays hold them.
using Vertex8 = std::array<float, 8>;

std::vector<Vertex8> planeVertices()
{
    return {{25, -0.5f, 25, 0, 1, 0, 25, 0},  {-25, -0.5f, 25, 0, 1, 0, 0, 0},   {-25, -0.5f, -25, 0, 1, 0, 0, 25},
            {25, -0.5f, 25, 0, 1, 0, 25, 0},  {-25, -0.5f, -25, 0, 1, 0, 0, 25}, {25, -0.5f, -25, 0, 1, 0, 25, 25}};
}

// A cube from -1 to 1, two triangles a face, each face's normal and a 0..1 uv square.
std::vector<Vertex8> cubeVertices()
{
    std::vector<Vertex8> v;
    for (int axis = 0; axis < 3; ++axis) {
        for (float side : {-1.0f, 1.0f}) {
            const int a = (axis + 1) % 3, b = (axis + 2) % 3;
            const auto corner = [&](float s, float t) {
                Vertex8 out{};
                out[std::size_t(axis)] = side;
                out[std::size_t(a)] = s;
                out[std::size_t(b)] = t;
                out[std::size_t(3 + axis)] = side;
                out[6] = s * 0.5f + 0.5f;
                out[7] = t * 0.5f + 0.5f;
                return out;
            };
            // Counter-clockwise seen from outside.
            const bool flip = side < 0.0f;
            const Vertex8 p0 = corner(-1, -1), p1 = flip ? corner(-1, 1) : corner(1, -1), p2 = corner(1, 1), p3 = flip ? corner(1, -1) : corner(-1, 1);
            v.insert(v.end(), {p0, p1, p2, p2, p3, p0});
        }
    }
    return v;
}

void uploadVertices(GlFunctions* gl, GLuint array, GLuint buffer, const std::vector<Vertex8>& vertices)
{
    gl->glBindVertexArray(array);
    gl->glBindBuffer(GL_ARRAY_BUFFER, buffer);
    gl->glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex8)), vertices.data(), GL_STATIC_DRAW);
    for (GLuint i = 0; i < 3; ++i) {
        gl->glEnableVertexAttribArray(i);
        const GLint components = i == 2 ? 2 : 3;
        gl->glVertexAttribPointer(i, components, GL_FLOAT, GL_FALSE, sizeof(Vertex8), reinterpret_cast<const void*>(std::size_t(3 * i) * sizeof(float)));
    }
    gl->glBindVertexArray(0);
}

glm::mat4 lightSpace()
{
    return glm::ortho(-10.0f, 10.0f, -10.0f, 10.0f, 1.0f, 7.5f) * glm::lookAt(glm::vec3(-2.0f, 4.0f, -1.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
}

} // namespace

Settings tutorialSettings(Settings s)
{
    s.bias = BiasSettings{};            // what the tutorial does not set, as the defaults
    for (const QString& assignment : tutorialAssignments())
        applyAssignment(s, assignment);
    return s;
}

TutorialAnchor::TutorialAnchor(GlFunctions* gl, QSize size) : m_gl(gl), m_size(size)
{
    m_depthProgram = buildProgram(kDepthVertex, kDepthFragment, "depth");
    m_litProgram = buildProgram(kLitVertex, kLitFragment, "lit");
    buildGeometry();
    buildTextures();
}

void TutorialAnchor::buildGeometry()
{
    m_planeArray = makeVertexArray(m_gl);
    m_cubeArray = makeVertexArray(m_gl);
    m_planeVertices = makeBuffer(m_gl);
    m_cubeVertices = makeBuffer(m_gl);
    uploadVertices(m_gl, m_planeArray.id(), m_planeVertices.id(), planeVertices());
    uploadVertices(m_gl, m_cubeArray.id(), m_cubeVertices.id(), cubeVertices());
}

void TutorialAnchor::buildTextures()
{
    // A wood-like 512 x 512 texture with mipmaps, repeated, trilinear, as the tutorial loads its PNG.
    constexpr int side = 512;
    std::vector<unsigned char> texels(std::size_t(side * side * 3));
    for (int y = 0; y < side; ++y) {
        for (int x = 0; x < side; ++x) {
            const double grain = 0.5 + 0.5 * std::sin(0.11 * x + 3.0 * std::sin(0.013 * y));
            unsigned char* t = &texels[std::size_t((y * side + x) * 3)];
            t[0] = static_cast<unsigned char>(120 + 80 * grain);
            t[1] = static_cast<unsigned char>(70 + 50 * grain);
            t[2] = static_cast<unsigned char>(30 + 20 * grain);
        }
    }
    m_wood = makeTexture(m_gl);
    m_gl->glBindTexture(GL_TEXTURE_2D, m_wood.id());
    m_gl->glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, side, side, 0, GL_RGB, GL_UNSIGNED_BYTE, texels.data());
    m_gl->glGenerateMipmap(GL_TEXTURE_2D);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);

    m_depthMap = makeTexture(m_gl);
    m_gl->glBindTexture(GL_TEXTURE_2D, m_depthMap.id());
    m_gl->glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, kMapSide, kMapSide, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    m_gl->glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    m_depthFramebuffer = makeFramebuffer(m_gl);
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, m_depthFramebuffer.id());
    m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m_depthMap.id(), 0);
    m_gl->glDrawBuffer(GL_NONE);
    m_gl->glReadBuffer(GL_NONE);

    // The window: colour, and depth with stencil, as a default framebuffer has them.
    m_windowColour = makeTexture(m_gl);
    m_gl->glBindTexture(GL_TEXTURE_2D, m_windowColour.id());
    m_gl->glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, m_size.width(), m_size.height(), 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    m_windowDepth = makeTexture(m_gl);
    m_gl->glBindTexture(GL_TEXTURE_2D, m_windowDepth.id());
    m_gl->glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, m_size.width(), m_size.height(), 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, nullptr);
    m_window = makeFramebuffer(m_gl);
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, m_window.id());
    m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_windowColour.id(), 0);
    m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, m_windowDepth.id(), 0);
    if (m_gl->glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw RenderError(QStringLiteral("the tutorial anchor's %1x%2 target is not complete").arg(m_size.width()).arg(m_size.height()));
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
}

void TutorialAnchor::drawScene(QOpenGLShaderProgram& program)
{
    const int model = program.uniformLocation("model");
    const auto draw = [&](const glm::mat4& m, const GlVertexArray& array, GLsizei count) {
        m_gl->glUniformMatrix4fv(model, 1, GL_FALSE, glm::value_ptr(m));
        m_gl->glBindVertexArray(array.id());
        m_gl->glDrawArrays(GL_TRIANGLES, 0, count);
    };
    draw(glm::mat4(1.0f), m_planeArray, 6);
    draw(glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.5f, 0.0f)), glm::vec3(0.5f)), m_cubeArray, 36);
    draw(glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(2.0f, 0.0f, 1.0f)), glm::vec3(0.5f)), m_cubeArray, 36);
    const glm::mat4 turned = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(-1.0f, 0.0f, 2.0f)), glm::radians(60.0f),
                                         glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f)));
    draw(glm::scale(turned, glm::vec3(0.25f)), m_cubeArray, 36);
    m_gl->glBindVertexArray(0);
}

double TutorialAnchor::timedFrame(const CameraFrame& camera)
{
    QElapsedTimer timer;
    timer.start();
    m_gl->glEnable(GL_DEPTH_TEST);
    m_gl->glDisable(GL_CULL_FACE);
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, m_window.id());
    m_gl->glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    m_gl->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    const glm::mat4 light = lightSpace();
    m_depthProgram->bind();
    m_gl->glUniformMatrix4fv(m_depthProgram->uniformLocation("lightSpaceMatrix"), 1, GL_FALSE, glm::value_ptr(light));
    m_gl->glViewport(0, 0, kMapSide, kMapSide);
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, m_depthFramebuffer.id());
    m_gl->glClear(GL_DEPTH_BUFFER_BIT);
    drawScene(*m_depthProgram);

    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, m_window.id());
    m_gl->glViewport(0, 0, m_size.width(), m_size.height());
    m_gl->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    m_gl->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    m_litProgram->bind();
    // Camera-relative positions are ShadowLab's; the tutorial's are world, as here.
    const glm::mat4 view(camera.view), projection(camera.projection);
    m_gl->glUniformMatrix4fv(m_litProgram->uniformLocation("projection"), 1, GL_FALSE, glm::value_ptr(projection));
    m_gl->glUniformMatrix4fv(m_litProgram->uniformLocation("view"), 1, GL_FALSE, glm::value_ptr(view));
    m_gl->glUniformMatrix4fv(m_litProgram->uniformLocation("lightSpaceMatrix"), 1, GL_FALSE, glm::value_ptr(light));
    m_litProgram->setUniformValue("viewPos", float(camera.position.x), float(camera.position.y), float(camera.position.z));
    m_litProgram->setUniformValue("lightPos", -2.0f, 4.0f, -1.0f);
    m_litProgram->setUniformValue("diffuseTexture", 0);
    m_litProgram->setUniformValue("shadowMap", 1);
    m_gl->glActiveTexture(GL_TEXTURE0);
    m_gl->glBindTexture(GL_TEXTURE_2D, m_wood.id());
    m_gl->glActiveTexture(GL_TEXTURE1);
    m_gl->glBindTexture(GL_TEXTURE_2D, m_depthMap.id());
    drawScene(*m_litProgram);
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    m_gl->glActiveTexture(GL_TEXTURE0);
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    m_gl->glFinish();
    return double(timer.nsecsElapsed()) / 1e6;
}

} // namespace shadowlab
