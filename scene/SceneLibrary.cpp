#include "SceneLibrary.h"

#include "ProceduralTexture.h"
#include "SceneLoader.h"
#include "SettingsError.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace shadowlab {

namespace {

glm::dmat4 placement(glm::dvec3 position, double scale, double angleDegrees = 0.0, glm::dvec3 axis = {0, 1, 0})
{
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), position);
    if (angleDegrees != 0.0)
        m = glm::rotate(m, glm::radians(angleDegrees), glm::normalize(axis));
    return glm::scale(m, glm::dvec3(scale));
}

void addGround(Scene& scene, double y)
{
    scene.groundHeight = y;
    scene.meshes.push_back(meshes::plane(25.0f, 25.0f));
    scene.objects.push_back({QStringLiteral("ground"), int(scene.meshes.size() - 1),
                             glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, y, 0.0)), TextureKind::Checker, true});
}

Scene seedScene()
{
    // The classic tutorial scene: three wooden cubes over a large plane.
    Scene s;
    s.name = QStringLiteral("seed");
    addGround(s, -0.5);
    s.meshes.push_back(meshes::cube());
    const int cube = int(s.meshes.size() - 1);
    s.objects.push_back({QStringLiteral("high cube"), cube, placement({0.0, 1.5, 0.0}, 0.5), TextureKind::Wood, true});
    s.objects.push_back({QStringLiteral("resting cube"), cube, placement({2.0, 0.0, 1.0}, 0.5), TextureKind::Wood, true});
    s.objects.push_back({QStringLiteral("tilted cube"), cube, placement({-1.0, 0.0, 2.0}, 0.25, 60.0, {1.0, 0.0, 1.0}),
                         TextureKind::Wood, true});
    return s;
}

Scene torusScene()
{
    Scene s;
    s.name = QStringLiteral("torus");
    addGround(s, -0.5);
    s.meshes.push_back(meshes::torus(1.0f, 0.35f, 64, 24));
    s.objects.push_back({QStringLiteral("torus"), int(s.meshes.size() - 1), placement({-0.6, 0.75, 0.0}, 1.0, 70.0, {1.0, 0.0, 0.2}),
                         TextureKind::Wood, true});
    s.meshes.push_back(meshes::pyramid());
    s.objects.push_back({QStringLiteral("pyramid"), int(s.meshes.size() - 1), placement({1.8, 0.1, 0.6}, 0.6, 20.0),
                         TextureKind::Wood, true});
    return s;
}

Scene cubesScene()
{
    Scene s;
    s.name = QStringLiteral("cubes");
    addGround(s, -0.5);
    s.meshes.push_back(meshes::cube());
    const int cube = int(s.meshes.size() - 1);
    // Fixed placements (x, y, z, half-size, angle) so the preset is the same on every run.
    const double table[10][5] = {{-3.0, 0.5, -2.0, 0.6, 15.0}, {-1.2, 1.8, -1.0, 0.4, 40.0}, {0.6, 0.2, -2.6, 0.5, 70.0},
                                 {2.4, 1.2, -1.6, 0.45, 110.0}, {3.4, 0.0, 0.4, 0.5, 25.0},  {1.2, 2.6, 0.6, 0.35, 55.0},
                                 {-0.4, 0.3, 1.2, 0.55, 80.0},  {-2.6, 1.4, 1.6, 0.4, 135.0}, {0.8, 0.9, 2.8, 0.3, 160.0},
                                 {-3.6, 0.1, 3.2, 0.45, 5.0}};
    for (int i = 0; i < 10; ++i) {
        const auto& t = table[i];
        s.objects.push_back({QStringLiteral("cube %1").arg(i + 1), cube,
                             placement({t[0], t[1], t[2]}, t[3], t[4], {0.3 * (i % 3), 1.0, 0.2 * (i % 2)}), TextureKind::Wood, true});
    }
    return s;
}

Scene occluderScene()
{
    // The simplest shadow there is: a thin square board above a plane, turned 30 degrees so its
    // edges cross the shadow map's texel grid. Under a light straight above, its shadow is
    // exactly the board's square (half-size 1) on the plane.
    Scene s;
    s.name = QStringLiteral("occluder");
    addGround(s, 0.0);
    s.meshes.push_back(meshes::cube());
    glm::dmat4 board = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 1.0, 0.0));
    board = glm::rotate(board, glm::radians(30.0), glm::dvec3(0.0, 1.0, 0.0));
    board = glm::scale(board, glm::dvec3(1.0, 0.02, 1.0));
    s.objects.push_back({QStringLiteral("board"), int(s.meshes.size() - 1), board, TextureKind::Wood, true});
    return s;
}

// A reproducible hash to [0, 1) (PCG output permutation): the same city and shrubs on every platform,
// which std::uniform_real_distribution does not promise.
double presetRandom(std::uint32_t seed, std::uint32_t i)
{
    const std::uint32_t state = (seed * 2654435761u ^ i) * 747796405u + 2891336453u;
    const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return double(((word >> 22u) ^ word) >> 8) / 16777216.0;
}

// The city's street grid: square blocks with streets between them, over kCitySide² metres.
constexpr double kCitySide = 1200.0;        // metres: 1.44 km²
constexpr int kCityBlocks = 12;             // per side
constexpr double kCityStreet = 20.0;        // street width, metres
constexpr double kCityPitch = kCitySide / kCityBlocks;

Scene cityScene(const QString& name, int buildings)
{
    // Buildings of varied footprint and height on the lots of a street grid; the same count
    // always gives the same city. Heights: mostly low, a few towers (a long-tailed mix), so
    // shadows range from a few metres to a few hundred.
    Scene s;
    s.name = name;
    s.groundHeight = 0.0;
    s.meshes.push_back(meshes::plane(float(kCitySide * 0.5 + 60.0), float(kCitySide * 0.5 + 60.0) / 4.0f));
    s.objects.push_back({QStringLiteral("ground"), 0, glm::dmat4(1.0), TextureKind::Checker, true});
    s.meshes.push_back(meshes::cube());
    const int cube = 1;
    const int blocks = kCityBlocks * kCityBlocks;
    const int lotsPerSide = std::max(1, int(std::ceil(std::sqrt(double(buildings) / blocks))));
    const double blockSide = kCityPitch - kCityStreet;
    const double lot = blockSide / lotsPerSide;
    const std::uint32_t seed = 12345u;
    // Lots in an order that spreads any count over the whole grid: block by block in a
    // scrambled order, so 500 buildings cover the city as sparsely as 8,000 cover it densely.
    const int lots = blocks * lotsPerSide * lotsPerSide;
    std::vector<std::pair<double, int>> order;
    order.reserve(std::size_t(lots));
    for (int i = 0; i < lots; ++i)
        order.emplace_back(presetRandom(seed + 7u, std::uint32_t(i)), i);
    std::sort(order.begin(), order.end());
    s.objects.reserve(std::size_t(buildings) + 1);
    for (int n = 0; n < std::min(buildings, lots); ++n) {
        const int i = order[std::size_t(n)].second;
        const int block = i / (lotsPerSide * lotsPerSide);
        const int inBlock = i % (lotsPerSide * lotsPerSide);
        const double blockX = -kCitySide * 0.5 + (block % kCityBlocks) * kCityPitch + kCityStreet * 0.5;
        const double blockZ = -kCitySide * 0.5 + (block / kCityBlocks) * kCityPitch + kCityStreet * 0.5;
        const double r1 = presetRandom(seed, std::uint32_t(4 * i)), r2 = presetRandom(seed, std::uint32_t(4 * i + 1));
        const double r3 = presetRandom(seed, std::uint32_t(4 * i + 2)), r4 = presetRandom(seed, std::uint32_t(4 * i + 3));
        const double width = lot * (0.55 + 0.4 * r1), depth = lot * (0.55 + 0.4 * r2);
        const double height = 4.0 + 8.0 * r3 + (r4 > 0.9 ? 150.0 * (r4 - 0.9) / 0.1 * r3 : 22.0 * r4 * r4);
        const double x = blockX + (inBlock % lotsPerSide + 0.5) * lot + (r3 - 0.5) * (lot - width) * 0.8;
        const double z = blockZ + (inBlock / lotsPerSide + 0.5) * lot + (r1 - 0.5) * (lot - depth) * 0.8;
        glm::dmat4 model = glm::translate(glm::dmat4(1.0), glm::dvec3(x, height * 0.5, z));
        model = glm::scale(model, glm::dvec3(width * 0.5, height * 0.5, depth * 0.5));
        s.objects.push_back({QStringLiteral("building %1").arg(n + 1), cube, model, TextureKind::Wood, true, true,
                             glm::vec3(float(0.55 + 0.35 * r2), float(0.55 + 0.3 * r1), float(0.6 + 0.3 * r4))});
    }
    return s;
}

Scene bleedingScene()
{
    // The classic failure of variance shadow maps: thin boards stacked at different heights
    // over a ground, each partly over the shadow of the one above. Where a receiver sees two
    // occluders at different depths within one filter footprint, Chebyshev's bound lets light
    // through inside a shadow the ray tracer says is solid.
    Scene s;
    s.name = QStringLiteral("bleeding");
    addGround(s, 0.0);
    s.meshes.push_back(meshes::cube());
    const int cube = int(s.meshes.size() - 1);
    auto board = [&](const char* name, glm::dvec3 centre, double halfX, double halfZ, double angle, double halfY = 0.03) {
        glm::dmat4 m = glm::translate(glm::dmat4(1.0), centre);
        m = glm::rotate(m, glm::radians(angle), glm::dvec3(0.0, 1.0, 0.0));
        m = glm::scale(m, glm::dvec3(halfX, halfY, halfZ));
        s.objects.push_back({QString::fromLatin1(name), cube, m, TextureKind::Wood, true});
    };
    // Light bleeds most where the lower occluder is close to the receiver and the upper one
    // far above it: the low board straddles the high board's edge a hand's width over the ground.
    board("high board", {0.0, 3.0, 0.0}, 1.6, 1.6, 15.0);
    board("middle board", {-0.3, 1.6, -0.6}, 1.0, 0.5, -20.0);
    board("low board", {1.45, 0.25, 0.55}, 0.45, 1.5, 15.0);
    board("low bar", {-0.9, 0.35, 0.7}, 0.2, 1.3, 40.0);
    // A block resting on the ground, under the high board: its contact shadow is where
    // exponential warps leak.
    board("resting block", {0.2, 0.2, 1.1}, 0.2, 0.2, 10.0, 0.2);
    return s;
}

Scene foliageScene()
{
    // Cut-out casters (alpha-masked cards, as glTF's alphaMode MASK): a trellis fence and three
    // shrubs of leaf cards on wooden stems. Drawn as solid quads, each card's shadow is a
    // rectangle; through their masks, lattice and leaves.
    Scene s;
    s.name = QStringLiteral("foliage");
    addGround(s, 0.0);
    s.images.push_back(makeLeafTexture(1));
    s.images.push_back(makeLeafTexture(2));
    s.images.push_back(makeTrellisTexture());
    const auto cutout = [&](const QString& name, int mesh, const glm::dmat4& model, int image) {
        SceneObject object{name, mesh, model, TextureKind::Image, true};
        object.image = image;
        object.alphaCutoff = 0.5f;
        s.objects.push_back(object);
    };
    // The fence: 5 x 1.6 m, one texture tile per metre.
    s.meshes.push_back(meshes::card({5.0f, 1.6f}));
    glm::dmat4 fence = glm::translate(glm::dmat4(1.0), glm::dvec3(-0.3, 0.8, -1.6));
    fence = glm::rotate(fence, glm::radians(8.0), glm::dvec3(0.0, 1.0, 0.0));
    cutout(QStringLiteral("trellis"), int(s.meshes.size() - 1), glm::scale(fence, glm::dvec3(2.5, 0.8, 1.0)), 2);
    s.meshes.push_back(meshes::card());
    const int card = int(s.meshes.size() - 1);
    s.meshes.push_back(meshes::cube());
    const int cube = int(s.meshes.size() - 1);
    const glm::dvec3 shrubs[3] = {{-1.9, 0.0, 0.6}, {0.5, 0.0, 1.2}, {2.3, 0.0, -0.2}};
    for (int k = 0; k < 3; ++k) {
        const double height = 0.9 + 0.25 * k;
        s.objects.push_back({QStringLiteral("stem %1").arg(k + 1), cube,
                             glm::scale(glm::translate(glm::dmat4(1.0), shrubs[k] + glm::dvec3(0.0, height * 0.5, 0.0)),
                                        glm::dvec3(0.04, height * 0.5, 0.04)),
                             TextureKind::Wood, true});
        for (int i = 0; i < 16; ++i) {
            const auto n = std::uint32_t(k * 16 + i);
            const double yaw = 360.0 * presetRandom(11, n), pitch = -50.0 + 100.0 * presetRandom(12, n);
            const double radius = 0.15 + 0.3 * presetRandom(13, n), around = 6.2831853 * presetRandom(14, n);
            const glm::dvec3 at = shrubs[k] + glm::dvec3(radius * std::cos(around), height * (0.55 + 0.5 * presetRandom(15, n)), radius * std::sin(around));
            glm::dmat4 m = glm::translate(glm::dmat4(1.0), at);
            m = glm::rotate(m, glm::radians(yaw), glm::dvec3(0.0, 1.0, 0.0));
            m = glm::rotate(m, glm::radians(pitch), glm::dvec3(1.0, 0.0, 0.0));
            cutout(QStringLiteral("leaves %1.%2").arg(k + 1).arg(i + 1), card, glm::scale(m, glm::dvec3(0.3)), int(n % 2));
        }
    }
    return s;
}

} // namespace

std::vector<CameraSettings> cameraPath(const CameraSettings& start, int frames, double step)
{
    std::vector<CameraSettings> path;
    const glm::dvec3 forward = glm::normalize(start.target - start.position);
    // Sideways and a little forward: the view slides across the shadows as when walking.
    const glm::dvec3 side = glm::normalize(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 along = glm::length(side) > 0.0 ? glm::normalize(side + forward * 0.5) : glm::dvec3(1.0, 0.0, 0.0);
    for (int i = 0; i < std::max(frames, 1); ++i) {
        CameraSettings c = start;
        c.position += along * (step * i);
        c.target += along * (step * i);
        path.push_back(c);
    }
    return path;
}

Scene buildScene(const QString& name)
{
    if (const int buildings = cityBuildingCount(name); buildings > 0)
        return cityScene(name, buildings);
    if (!sceneNames().contains(name))
        return *loadSceneFile(name);
    if (name == u"seed")
        return seedScene();
    if (name == u"torus")
        return torusScene();
    if (name == u"cubes")
        return cubesScene();
    if (name == u"occluder")
        return occluderScene();
    if (name == u"bleeding")
        return bleedingScene();
    if (name == u"foliage")
        return foliageScene();
    throw SettingsError(QStringLiteral("scene"),
                        QStringLiteral("'%1' is not a scene; choose one of %2").arg(name, sceneNames().join(QStringLiteral(" | "))));
}

Settings presetSettings(const QString& name)
{
    if (!isPresetName(name))
        return sceneFileSettings(name);
    Settings s;
    s.scene = name;
    if (cityBuildingCount(name) > 0) {
        // An afternoon sun; a pedestrian on a street, looking down it toward the towers.
        s.light.position = {-400.0, 500.0, -250.0};
        s.light.target = {0.0, 0.0, 0.0};
        s.light.extent = 700.0;
        s.light.nearPlane = 1.0;
        s.light.farPlane = 1600.0;
        const double street = -kCitySide * 0.5 + 5.0 * kCityPitch + kCityStreet * 0.25;
        s.camera.position = {street, 1.7, 380.0};
        s.camera.target = {street + 25.0, 8.0, 280.0};
        s.camera.fov = 60.0;
        return s;
    }
    // The small scenes' lights and cameras; the seed's light is the global defaults.
    struct View {
        const char* name;
        std::optional<LightSettings> light;     // the defaults but position, target, extent, near, far
        glm::dvec3 cameraPosition, cameraTarget;
        double normalOffset = 0.0;              // bias.normal, texels
    };
    const auto light = [](glm::dvec3 position, double extent, double nearPlane, double farPlane) {
        LightSettings l;
        l.position = position;
        l.target = {0.0, 0.0, 0.0};
        l.extent = extent;
        l.nearPlane = nearPlane;
        l.farPlane = farPlane;
        return l;
    };
    const View views[] = {
        // The camera frames the three cubes and their shadows from above and to the side.
        {.name = "seed", .light = std::nullopt, .cameraPosition = {5.2, 4.6, 8.4}, .cameraTarget = {-0.2, 0.6, 0.2}},
        {.name = "torus", .light = light({-6.0, 1.6, 2.0}, 5.0, 1.0, 14.0), .cameraPosition = {0.5, 2.5, 6.5}, .cameraTarget = {0.0, 0.3, 0.0}},
        {.name = "cubes", .light = light({4.0, 9.0, 3.0}, 8.0, 2.0, 18.0), .cameraPosition = {0.0, 6.0, 11.0}, .cameraTarget = {0.0, 0.5, 0.0}},
        {.name = "occluder", .light = light({0.0, 6.0, 0.0}, 4.0, 1.0, 10.0), .cameraPosition = {0.0, 5.0, 4.5}, .cameraTarget = {0.0, 0.0, 0.0}},
        // Nearly overhead, so each board's shadow falls inside the one above's; the camera looks
        // down past the boards' edges at the ground they shadow.
        {.name = "bleeding", .light = light({-1.0, 8.0, -0.6}, 4.0, 1.0, 10.0), .cameraPosition = {4.6, 2.4, 5.4}, .cameraTarget = {0.2, 0.5, 0.2}},
        // A low sun behind the fence throws the lattice and the leaves toward the camera. The
        // cards have no thickness: their lit face meets its own depth in the map, which a texel
        // of normal offset clears at grazing light, where a depth bias would have to be huge.
        // (A thickness cures that, but with the slab's sides missing it lets light through a
        // sliver t * tan(angle) wide along every shadow edge.)
        {.name = "foliage", .light = light({-3.0, 6.0, -5.0}, 5.0, 1.0, 16.0), .cameraPosition = {1.2, 4.2, 6.8}, .cameraTarget = {0.0, 0.4, 0.2},
         .normalOffset = 1.0},
    };
    for (const View& view : views) {
        if (name != QLatin1String(view.name))
            continue;
        if (view.light)
            s.light = *view.light;
        s.camera.position = view.cameraPosition;
        s.camera.target = view.cameraTarget;
        s.bias.normal = view.normalOffset;
    }
    return s;
}

Settings movedToScene(const Settings& side, const Settings& scene)
{
    Settings moved = side;
    moved.scene = scene.scene;
    moved.light = scene.light;
    moved.camera = scene.camera;
    moved.reference = scene.reference;
    moved.shadow.distance = scene.shadow.distance;
    moved.bias.cullFront = scene.bias.cullFront;
    // A bias in texels or depth units means the same on any scene; one in world units does not.
    if (side.bias.space == BiasSpace::World && scene.bias.space == BiasSpace::World) {
        moved.bias.slope = scene.bias.slope;
        moved.bias.min = scene.bias.min;
    }
    return moved;
}

bool sceneHasCutouts(const QString& name)
{
    try {
        if (isPresetName(name))
            return buildScene(name).hasCutouts();
        return loadSceneFile(name)->hasCutouts();
    } catch (const std::exception&) {
        return false;   // the load's own error is said where the scene is built
    }
}

QString sceneIdentity(const QString& name)
{
    if (isPresetName(name))
        return name;
    return QStringLiteral("sha256:") + QString::fromLatin1(loadSceneFile(name)->identity);
}

} // namespace shadowlab
