#include "AuditCatalogue.h"

#include "Limits.h"
#include "MomentMath.h"
#include "RayTracer.h"
#include "RenderError.h"
#include "SceneLibrary.h"
#include "SceneSupply.h"
#include "SettingsError.h"
#include "SettingsKeys.h"
#include "ShadowReference.h"
#include "ShadowTechnique.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace shadowlab {

namespace {

const QSize kSize(192, 108);

using AuditRun = std::function<AuditOutcome(HeadlessRenderer&)>;

Settings seedWith(const QStringList& assignments)
{
    Settings s = presetSettings(QStringLiteral("seed"));
    for (const QString& a : assignments)
        applyAssignment(s, a);
    return s;
}

QString percent(double share) { return QStringLiteral("%1 %").arg(100.0 * share, 0, 'f', 2); }

struct Measurement {
    bool finite = true;
    int counted = 0;        // light-facing pixels inside the light volume
    int wrong = 0;
    double weightedWrong = 0.0; // |V - V_ref| weighted by N.L: the error in direct light as seen
    double weight = 0.0;
    VisibilityBuffer buffer;
    double error() const { return counted ? double(wrong) / counted : 0.0; }
    double lightError() const { return weight > 0.0 ? weightedWrong / weight : 0.0; }
};

// Renders the measuring variant and compares every light-facing pixel in the light's volume
// with the hard ray-traced reference (one shadow ray per pixel, Embree).
Measurement measure(HeadlessRenderer& headless, const Settings& settings)
{
    Renderer& r = headless.renderer();
    Measurement m;
    supplyScene(r, settings);
    m.buffer = r.renderVisibility(settings, kSize);
    const LightFrame& light = r.lightFrame();
    m.finite = isFinite(light.view) && isFinite(light.shadowMatrix) && isFinite(light.depthShadowMatrix);
    const glm::dvec3 origin = m.buffer.cameraPosition;
    ReferenceOptions options;
    options.area = false;
    const ReferenceVisibility reference = traceReference(RayTracer(*r.scene(), origin), m.buffer, light, options);
    for (int i = 0; i < m.buffer.pixelCount(); ++i) {
        const float v = m.buffer.visibility(i);
        if (!std::isfinite(v) || v < 0.0f || v > 1.0f) {
            m.finite = false;
            continue;
        }
        if (m.buffer.mask(i) != VisibilityBuffer::FacingLight)
            continue;
        const glm::dvec3 world = m.buffer.worldPosition(i);
        const glm::dvec4 s = light.shadowMatrix * glm::dvec4(world, 1.0);
        const glm::dvec3 c = glm::dvec3(s) / s.w;
        // Outside a manual volume is lit by design; a fitted volume leaves out only what no
        // caster can shadow, so every pixel counts there.
        if (settings.light.fit == LightFit::Manual && (s.w <= 0.0 || c.x < 0.0 || c.x > 1.0 || c.y < 0.0 || c.y > 1.0 || c.z > 1.0))
            continue;
        const glm::dvec3 toLight = light.perspective ? light.position - world : -light.direction;
        const double difference = std::abs(double(v) - double(reference.hard[std::size_t(i)]));
        const double nDotL = std::max(0.0, glm::dot(m.buffer.normal(i), glm::normalize(toLight)));
        ++m.counted;
        m.wrong += difference > 0.5;
        m.weightedWrong += nDotL * difference;
        m.weight += nDotL;
    }
    return m;
}

enum class Judge {
    Pixels,     // share of misclassified light-facing pixels <= the limit
    Light,      // N.L-weighted error <= the limit: what a viewer sees of the direct light
    FiniteOnly, // error reported, not judged
};

// Rendered, finite, and within `limit` of the ray-cast reference.
AuditRun accurate(Settings settings, double limit, Judge judge = Judge::Pixels)
{
    return [settings, limit, judge](HeadlessRenderer& h) {
        const Measurement m = measure(h, settings);
        AuditOutcome o;
        o.finite = m.finite;
        o.error = m.error();
        const double judged = judge == Judge::Light ? m.lightError() : m.error();
        o.pass = m.finite && m.counted > 0 && (judge == Judge::FiniteOnly || judged <= limit);
        o.happened = QStringLiteral("%1, %2 of %3 lit-side pixels wrong (N.L-weighted %4), texel %5")
                         .arg(m.finite ? QStringLiteral("finite") : QStringLiteral("NOT FINITE"))
                         .arg(m.wrong)
                         .arg(m.counted)
                         .arg(percent(m.lightError()))
                         .arg(h.renderer().lastFrame().texelWorldSize, 0, 'g', 3);
        return o;
    };
}

// Refused before anything is drawn, with a message naming `key`.
AuditRun refused(Settings settings, QString key)
{
    return [settings, key](HeadlessRenderer& h) {
        AuditOutcome o;
        try {
            h.renderFrame(settings, kSize);
            o.happened = QStringLiteral("rendered without complaint");
        } catch (const SettingsError& e) {
            o.pass = e.key() == key;
            o.happened = QString::fromStdString(e.what());
        }
        return o;
    };
}

Scene withOffset(Scene scene, const glm::dvec3& offset)
{
    for (SceneObject& o : scene.objects)
        o.model = glm::translate(glm::dmat4(1.0), offset) * o.model;
    return scene;
}

Settings offsetSettings(Settings s, const glm::dvec3& offset)
{
    s.light.position += offset;
    s.light.target += offset;
    s.camera.position += offset;
    s.camera.target += offset;
    return s;
}

// Ground plane at y = -0.5 with one cube: the simplest contact and size cases.
Scene groundAndCube(const QString& name, const glm::dmat4& cube)
{
    Scene s;
    s.name = name;
    s.meshes.push_back(meshes::plane(25.0f, 25.0f));
    s.objects.push_back({QStringLiteral("ground"), 0, glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, -0.5, 0.0)), TextureKind::Checker, true});
    s.meshes.push_back(meshes::cube());
    s.objects.push_back({QStringLiteral("cube"), 1, cube, TextureKind::Wood, true});
    return s;
}

// Runs `body` with `scene` in place of the preset.
AuditRun onScene(Scene scene, AuditRun body)
{
    return [scene, body](HeadlessRenderer& h) {
        h.renderer().setScene(scene);
        return body(h);
    };
}

AuditOutcome contactShadow(HeadlessRenderer& h)
{
    // Cube [-0.5, 0.5]^3 resting on the ground, light from -x: its shadow must start at the
    // face x = 0.5 (ground from one texel beyond it dark) and the ground before x = -0.5 lit.
    const Settings s = seedWith({QStringLiteral("light.position=-4,4,0"), QStringLiteral("light.target=0,-0.5,0"),
                                 QStringLiteral("camera.position=0,4,1.5"), QStringLiteral("camera.target=0,-0.5,0")});
    const Measurement m = measure(h, s);
    const double texel = h.renderer().lastFrame().texelWorldSize;
    int darkBeyond = 0, beyond = 0, litBefore = 0, before = 0;
    for (int i = 0; i < m.buffer.pixelCount(); ++i) {
        const glm::dvec3 p = m.buffer.worldPosition(i);
        if (m.buffer.mask(i) != VisibilityBuffer::FacingLight || std::abs(p.y + 0.5) > 1e-3 || std::abs(p.z) > 0.4)
            continue;
        if (p.x > 0.5 + texel && p.x < 0.6) {
            ++beyond;
            darkBeyond += m.buffer.visibility(i) < 0.5f;
        } else if (p.x < -0.5 - texel && p.x > -0.7) {
            ++before;
            litBefore += m.buffer.visibility(i) > 0.5f;
        }
    }
    AuditOutcome o;
    o.finite = m.finite;
    o.error = m.error();
    o.pass = m.finite && beyond > 0 && darkBeyond == beyond && before > 0 && litBefore == before;
    o.happened = QStringLiteral("%1/%2 ground pixels from 1 texel to 0.1 past the contact dark, %3/%4 before the cube lit")
                     .arg(darkBeyond).arg(beyond).arg(litBefore).arg(before);
    return o;
}

Scene degenerateTriangleScene()
{
    Scene s = buildScene(QStringLiteral("seed"));
    Mesh& cube = s.meshes.at(std::size_t(s.objects.at(1).mesh));
    // Three collinear vertices with zero normals: zero area, no direction.
    const auto base = std::uint32_t(cube.vertices.size());
    cube.vertices.push_back({{0.0f, 1.2f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f}});
    cube.vertices.push_back({{0.5f, 1.2f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f}});
    cube.vertices.push_back({{1.0f, 1.2f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f}});
    cube.indices.insert(cube.indices.end(), {base, base + 1, base + 2, base, base, base});
    return s;
}

// The catalogue as it is built: each group below appends its cases, in the order the audit
// prints them.
struct CaseList {
    std::vector<AuditCase> cases;
    void add(const QString& name, const QString& expected, AuditRun run) { cases.push_back({name, expected, std::move(run)}); }
};

// The light straight above, straight below and grazing the ground plane.
void addLightPlacements(CaseList& c)
{
    c.add("light straight above", "finite orthonormal frame (up vector parallel); error <= 2 %",
          accurate(seedWith({"light.position=0,6,0", "light.far=10"}), 0.02));
    c.add("light straight below", "finite frame; the ground shadows what faces the light; error <= 2 %",
          accurate(seedWith({"light.position=0,-6,0", "light.far=10"}), 0.02));
    c.add("light grazing the plane (N.L = 1e-3)",
          "bounded bias, finite; the plane (direct light 1e-3) may go dark, the N.L-weighted error <= 2 %",
          accurate(seedWith({"light.position=10,-0.49,0", "light.target=0,-0.5,0", "light.near=0.5", "light.far=30"}), 0.02, Judge::Light));
    c.add("N.L = 0 exactly", "the plane counts as facing away (unlit), the rest finite; error <= 5 %",
          accurate(seedWith({"light.position=10,-0.5,0", "light.target=0,-0.5,0", "light.near=0.5", "light.far=30"}), 0.05));
}

// A perspective light's depth over eight decades: warned of in depth24, exact with reversed Z.
void addDepthPrecision(CaseList& c)
{
    const QStringList wideRange{"light.projection=perspective", "light.fit=manual", "light.near=0.001", "light.far=100000",
                                "bias.slope=0", "bias.min=0", "bias.normal=1.5"};
    c.add("perspective near/far 1e-3/1e5, depth24", "renders with a precision warning naming light.near; finite",
          [s = seedWith(wideRange)](HeadlessRenderer& h) {
              AuditOutcome o = accurate(s, 1.0)(h);
              const auto issues = validate(s);
              const bool warned = !issues.empty() && issues.front().severity == SettingsIssue::Severity::Warning
                                  && issues.front().key == u"light.near";
              o.pass = o.pass && warned;
              o.happened += warned ? QStringLiteral("; warned") : QStringLiteral("; NO WARNING");
              return o;
          });
    c.add("perspective near/far 1e-3/1e5, depth32f + reversed Z", "no warning, reversed depth in use; error <= 3 %",
          [s = seedWith(wideRange + QStringList{"map.format=depth32f"})](HeadlessRenderer& h) {
              AuditOutcome o = accurate(s, 0.03)(h);
              const bool reversed = h.renderer().lastFrame().reversedDepth;
              o.pass = o.pass && validate(s).empty() && (reversed || !h.renderer().supportsReversedDepth());
              o.happened += reversed ? QStringLiteral("; reversed Z") : QStringLiteral("; conventional Z (no clip control)");
              return o;
          });
}

// Light types and cascades at their extremes.
void addLightTypes(CaseList& c)
{
    c.add("point light inside a caster", "every receiver it could light is behind the cube's walls; finite; error <= 1 %",
          accurate(seedWith({"light.type=point", "light.position=0.05,1.5,-0.03", "light.target=0,0,0"}), 0.01));
    c.add("spot light inside a caster", "unlit everywhere; finite; error <= 1 %",
          accurate(seedWith({"light.type=spot", "light.fov=120", "light.position=0.05,1.5,-0.03", "light.target=0,0,0"}), 0.01));
    c.add("point light on a receiver", "the ground it rests on is lit edge-on (N.L = 0); finite",
          accurate(seedWith({"light.type=point", "light.position=0.8,-0.5,0.4", "light.target=0,-1,0"}), 1.0, Judge::FiniteOnly));
    c.add("point light on a cube-face seam", "a direction exactly between two faces picks one; error <= 2 %",
          accurate(seedWith({"light.type=point", "light.position=0,2.5,0", "light.target=0,0,0"}), 0.02));
    c.add("cascade splits at shadow distance 1e5", "four finite slices up to the camera's far plane; error <= 2 %",
          accurate(seedWith({"shadow.cascades=4", "shadow.distance=100000", "shadow.split=logarithmic"}), 0.02));
    c.add("evsm4 on cascades at shadow distance 1e5", "one moments tile per cascade, blurred within it; finite; error <= 2 %",
          accurate(seedWith({"filter.mode=evsm4", "shadow.cascades=4", "shadow.distance=100000", "shadow.split=logarithmic"}), 0.02));
    c.add("msm on a point light on a cube-face seam", "a moments tile per face; finite; error <= 2 %",
          accurate(seedWith({"filter.mode=msm", "light.type=point", "light.position=0,2.5,0", "light.target=0,0,0"}), 0.02));
}

// Settings no frame can be drawn with, refused with the key to change; beside them, ortho
// near = 0, which is valid.
void addRefusedSettings(CaseList& c)
{
    c.add("moment mipmaps over several views", "refused, naming moments.mipmaps",
          refused(seedWith({"filter.mode=vsm", "moments.mipmaps=true", "shadow.cascades=3"}), "moments.mipmaps"));
    c.add("cascades on a spot light", "refused, naming shadow.cascades",
          refused(seedWith({"light.type=spot", "shadow.cascades=4"}), "shadow.cascades"));
    c.add("perspective near = 0", "refused, naming light.near", refused(seedWith({"light.projection=perspective", "light.near=0"}), "light.near"));
    c.add("ortho near = 0", "valid for a directional light: renders; error <= 2 %", accurate(seedWith({"light.near=0"}), 0.02));
    c.add("near = far", "refused, naming light.far", refused(seedWith({"light.near=5", "light.far=5"}), "light.far"));
    c.add("near > far", "refused, naming light.far", refused(seedWith({"light.near=9", "light.far=5"}), "light.far"));
    c.add("light at its target", "refused, naming light.position", refused(seedWith({"light.position=0,0,0"}), "light.position"));
    c.add("fov 180", "refused, naming light.fov", [](HeadlessRenderer& h) {
        Settings s = seedWith({"light.projection=perspective"});
        s.light.fov = 180.0;
        return refused(s, "light.fov")(h);
    });
    c.add("NaN in a setting", "refused, naming the key (struct field and --set alike)", [](HeadlessRenderer& h) {
        Settings s = presetSettings(QStringLiteral("seed"));
        s.light.extent = std::nan("");
        AuditOutcome o = refused(s, "light.extent")(h);
        try {
            applySetting(s, QStringLiteral("bias.slope"), QStringLiteral("nan"));
            o.pass = false;
        } catch (const SettingsError& e) {
            o.pass = o.pass && e.key() == u"bias.slope";
        }
        return o;
    });
    c.add("PCF kernel 4 (even)", "refused, naming filter.kernel", [](HeadlessRenderer& h) {
        Settings s = seedWith({"filter.mode=pcf"});
        s.filter.kernel = 4;
        return refused(s, "filter.kernel")(h);
    });
}

// The shadow map from too small to the driver's largest.
void addMapSizes(CaseList& c)
{
    c.add("map size 8", "refused, naming map.size", [](HeadlessRenderer& h) {
        Settings s = presetSettings(QStringLiteral("seed"));
        s.map.size = 8;
        return refused(s, "map.size")(h);
    });
    c.add("map size above the driver maximum", "refused, naming map.size and the driver's limit", [](HeadlessRenderer& h) {
        Settings s = presetSettings(QStringLiteral("seed"));
        s.map.size = std::min(h.renderer().maxTextureSize() * 2, kMaxImageSide);
        if (s.map.size <= h.renderer().maxTextureSize())
            return AuditOutcome{true, true, std::nullopt, QStringLiteral("the driver allows every size the key allows")};
        return refused(s, "map.size")(h);
    });
    c.add("map size 16", "blocky but finite (error reported, not judged: 16 texels cannot resolve the scene)",
          accurate(seedWith({"map.size=16"}), 0.0, Judge::FiniteOnly));
    c.add("map size at the driver maximum", "allocates and renders, or fails with a clear message; finite", [](HeadlessRenderer& h) {
        const int size = std::min(h.renderer().maxTextureSize(), kMaxImageSide);
        Settings s = seedWith({QStringLiteral("map.size=%1").arg(size)});
        try {
            AuditOutcome o = accurate(s, 0.02)(h);
            o.happened = QStringLiteral("%1 x %1: ").arg(size) + o.happened;
            return o;
        } catch (const RenderError& e) {
            return AuditOutcome{true, true, std::nullopt, QStringLiteral("%1 x %1 refused: %2").arg(size).arg(QString::fromStdString(e.what()))};
        }
    });
}

// Every filter of the technique table, in each variation a sweep tries.
void addFilters(CaseList& c)
{
    for (const ShadowTechnique& technique : shadowTechniques()) {
        for (const TechniqueVariation& variation : technique.sweep)
            c.add(QStringLiteral("filter %1 on seed").arg(variation.label), QStringLiteral("renders; finite; error <= 1 %"),
                  accurate(seedWith(variation.assignments), 0.01));
    }
    c.add("PCF kernel 1 equals hard", "identical images", [](HeadlessRenderer& h) {
        const QImage hard = h.renderScene(seedWith({"filter.mode=hard"}), kSize);
        const QImage pcf = h.renderScene(seedWith({"filter.mode=pcf", "filter.kernel=1"}), kSize);
        const bool same = hard == pcf;
        return AuditOutcome{same, true, std::nullopt, same ? QStringLiteral("identical") : QStringLiteral("images differ")};
    });
}

// Viewports of one pixel and of none.
void addViewports(CaseList& c)
{
    c.add("1 x 1 viewport", "one finite pixel", [](HeadlessRenderer& h) {
        const QImage image = h.renderScene(presetSettings(QStringLiteral("seed")), QSize(1, 1));
        const bool ok = image.size() == QSize(1, 1) && isFinite(h.renderer().cameraFrame().viewProjection);
        return AuditOutcome{ok, ok, std::nullopt, QStringLiteral("%1 x %2 image").arg(image.width()).arg(image.height())};
    });
    c.add("0 x 0 viewport", "nothing drawn, no error", [](HeadlessRenderer& h) {
        h.makeCurrent();
        const int passes = h.renderer().shadowPassCount();
        h.renderer().render(presetSettings(QStringLiteral("seed")), RenderTarget{0, QSize(0, 0)});
        const bool ok = h.renderer().shadowPassCount() == passes;
        return AuditOutcome{ok, true, std::nullopt, ok ? QStringLiteral("returned without drawing") : QStringLiteral("drew")};
    });
}

// Scenes far from the origin, empty, touching, and smaller than a texel.
void addSceneExtremes(CaseList& c)
{
    for (const double offset : {1e5, 1e6}) {
        const glm::dvec3 shift(offset, 0.5 * offset, -offset);
        const QByteArray name = QByteArray("scene and camera offset by ") + (offset == 1e5 ? "1e5" : "1e6");
        c.add(QString::fromLatin1(name), QStringLiteral("as accurate as at the origin: error <= 2 %"),
              onScene(withOffset(buildScene(QStringLiteral("seed")), shift),
                      accurate(offsetSettings(presetSettings(QStringLiteral("seed")), shift), 0.02)));
    }
    c.add("empty scene", "no shadow pass, no draws, background only", onScene([] { Scene s; s.name = QStringLiteral("empty"); return s; }(), [](HeadlessRenderer& h) {
        const int passes = h.renderer().shadowPassCount();
        h.renderFrame(presetSettings(QStringLiteral("seed")), kSize);
        const FrameStats& f = h.renderer().lastFrame();
        const bool ok = h.renderer().shadowPassCount() == passes && f.shadowDraws == 0 && f.litDraws == 0;
        return AuditOutcome{ok, true, std::nullopt, QStringLiteral("%1 shadow draws, %2 lit draws").arg(f.shadowDraws).arg(f.litDraws)};
    }));
    c.add("caster touching its receiver", "shadow starts within one texel of the contact; no leak before it",
          onScene(groundAndCube(QStringLiteral("contact"), glm::scale(glm::dmat4(1.0), glm::dvec3(0.5))), contactShadow));
    c.add("sub-texel occluder", "at most a speck, nothing spurious elsewhere; error <= 1 %",
          onScene(groundAndCube(QStringLiteral("speck"), glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 1.0, 0.0)), glm::dvec3(1e-3))),
                  accurate(presetSettings(QStringLiteral("seed")), 0.01)));
}

// The moment techniques' own extremes, in both moments formats: depth squeezed into a sliver
// of a huge range (the moments lose their precision), a caster touching its receiver (where
// filtered moments leak by design) and an occluder smaller than a texel. Each must stay finite.
void addMomentExtremes(CaseList& c)
{
    for (const ShadowTechnique& technique : shadowTechniques()) {
        if (!isMomentTechnique(technique.mode))
            continue;
        for (const char* bits : {"32", "16"}) {
            const QStringList mode{QStringLiteral("filter.mode=") + technique.key, QStringLiteral("moments.format=%1").arg(QLatin1String(bits))};
            const QString name = QStringLiteral("%1 %2-bit").arg(technique.key, QLatin1String(bits));
            c.add(name + QStringLiteral(": huge depth range (manual ortho volume, near -1e6, far 1e6)"), QStringLiteral("finite; error reported"),
                  accurate(seedWith(mode + QStringList{"light.fit=manual", "light.near=-1e6", "light.far=1e6"}), 0.0, Judge::FiniteOnly));
            c.add(name + QStringLiteral(": perspective light, far/near 1e7"), QStringLiteral("finite; error reported"),
                  accurate(seedWith(mode + QStringList{"light.projection=perspective", "light.fit=manual", "light.near=0.001", "light.far=1e4"}),
                           0.0, Judge::FiniteOnly));
            c.add(name + QStringLiteral(": caster touching its receiver"), QStringLiteral("finite; error reported (filtered moments leak at contacts)"),
                  onScene(groundAndCube(QStringLiteral("contact"), glm::scale(glm::dmat4(1.0), glm::dvec3(0.5))),
                          accurate(seedWith(mode + QStringList{"light.position=-4,4,0", "light.target=0,-0.5,0", "camera.position=0,4,1.5",
                                                               "camera.target=0,-0.5,0"}),
                                   0.0, Judge::FiniteOnly)));
            c.add(name + QStringLiteral(": sub-texel occluder"), QStringLiteral("finite; error <= 1 %"),
                  onScene(groundAndCube(QStringLiteral("speck"), glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 1.0, 0.0)), glm::dvec3(1e-3))),
                          accurate(seedWith(mode), 0.01)));
        }
    }
}

// Geometry that draws nothing: a zero-area triangle, a cut-out with nothing left.
void addDegenerateGeometry(CaseList& c)
{
    c.add("degenerate (zero-area) triangle in a mesh", "ignored: finite; error <= 2 %",
          onScene(degenerateTriangleScene(), accurate(presetSettings(QStringLiteral("seed")), 0.02)));
    c.add("cut-out with nothing left (base alpha 0)", "neither seen nor cast, in the map and the reference alike; finite; error <= 2 %",
          onScene([] {
              Scene s = groundAndCube(QStringLiteral("vanished cube"), glm::dmat4(1.0));
              s.objects[1].alphaCutoff = 0.5f;
              s.objects[1].baseAlpha = 0.0f;
              return s;
          }(), accurate(seedWith({QStringLiteral("light.position=-4,4,0"), QStringLiteral("light.target=0,-0.5,0")}), 0.02)));
}

// What fitting the light volume to the scene buys, and what a volume leaves out.
void addFitting(CaseList& c)
{
    c.add("fit = scene on seed", "smaller texels than the classic +-10 volume, error no worse (+0.5 %)", [](HeadlessRenderer& h) {
        const Measurement manual = measure(h, seedWith({"light.fit=manual"}));
        const double manualTexel = h.renderer().lastFrame().texelWorldSize;
        const Measurement fitted = measure(h, presetSettings(QStringLiteral("seed")));
        const double fittedTexel = h.renderer().lastFrame().texelWorldSize;
        AuditOutcome o;
        o.finite = manual.finite && fitted.finite;
        o.error = fitted.error();
        o.pass = o.finite && fittedTexel < manualTexel && fitted.error() <= manual.error() + 0.005;
        o.happened = QStringLiteral("texel %1 -> %2, error %3 -> %4")
                         .arg(manualTexel, 0, 'g', 3).arg(fittedTexel, 0, 'g', 3).arg(percent(manual.error()), percent(fitted.error()));
        return o;
    });
    c.add("casters outside the light volume", "not drawn in the depth pass", [](HeadlessRenderer& h) {
        const Settings s = [] {
            Settings cubes = presetSettings(QStringLiteral("cubes"));
            applyAssignment(cubes, QStringLiteral("light.fit=manual"));
            applyAssignment(cubes, QStringLiteral("light.extent=1.5"));
            return cubes;
        }();
        h.renderer().invalidateShadowMap();
        h.renderFrame(s, kSize);
        const int draws = h.renderer().lastFrame().shadowDraws;
        const int casters = int(h.renderer().scene()->objects.size());
        return AuditOutcome{draws < casters, true, std::nullopt, QStringLiteral("%1 of %2 casters drawn").arg(draws).arg(casters)};
    });
}

std::vector<AuditCase> makeCatalogue()
{
    CaseList c;
    addLightPlacements(c);
    addDepthPrecision(c);
    addLightTypes(c);
    addRefusedSettings(c);
    addMapSizes(c);
    addFilters(c);
    addViewports(c);
    addSceneExtremes(c);
    addMomentExtremes(c);
    addDegenerateGeometry(c);
    addFitting(c);
    return std::move(c.cases);
}

} // namespace

const std::vector<AuditCase>& auditCatalogue()
{
    static const std::vector<AuditCase> catalogue = makeCatalogue();
    return catalogue;
}

AuditOutcome runAuditCase(const AuditCase& c, HeadlessRenderer& headless)
{
    AuditOutcome outcome;
    try {
        outcome = c.run(headless);
    } catch (const std::exception& e) {
        outcome.pass = false;
        outcome.happened = QStringLiteral("unexpected error: %1").arg(QString::fromStdString(e.what()));
    }
    headless.renderer().setScene(std::nullopt);
    return outcome;
}

} // namespace shadowlab
