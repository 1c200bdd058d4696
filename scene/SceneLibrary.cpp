#include "SceneLibrary.h"

#include "ProceduralTexture.h"
#include "SceneFileError.h"
#include "SceneLoader.h"
#include "SceneShapes.h"
#include "SettingsKeys.h"
#include "SettingsError.h"

#include <QFile>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

namespace shadowlab {

namespace {

void addGround(Scene& scene, double y)
{
    scene.groundHeight = y;
    scene.meshes.push_back(meshes::plane(25.0f, 25.0f));
    scene.objects.push_back({QStringLiteral("ground"), int(scene.meshes.size() - 1),
                             glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, y, 0.0)), TextureKind::Checker, true});
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

// `count` vehicles driving the city's streets: boxes the size of cars, vans and buses, each up
// and down one street (a path there and back, its own speed and start), in the lane of its
// direction. They are the city's moving casters: their shadows cross the streets and the
// buildings' walls.
void addVehicles(Scene& s, int count)
{
    if (count <= 0)
        return;
    s.meshes.push_back(meshes::cube());
    const int box = int(s.meshes.size() - 1);
    const std::uint32_t seed = 777u;
    const double span = kCitySide * 0.5 - kCityStreet;
    for (int n = 0; n < count; ++n) {
        const auto u = [&](std::uint32_t k) { return presetRandom(seed, std::uint32_t(8 * n) + k); };
        const bool alongX = u(0) < 0.5;
        // The streets run between blocks: kCityBlocks + 1 lines at the pitch.
        const int street = std::min(int(u(1) * (kCityBlocks + 1)), kCityBlocks);
        const double across = -kCitySide * 0.5 + street * kCityPitch + (u(2) < 0.5 ? -1.0 : 1.0) * kCityStreet * 0.25;
        const double length = u(3) < 0.15 ? 12.0 : (u(3) < 0.4 ? 6.0 : 4.5);
        const double height = length > 10.0 ? 3.2 : (length > 5.0 ? 2.4 : 1.5);
        const glm::dvec3 half(length * 0.5, height * 0.5, 1.0);
        const double speed = 8.0 + 8.0 * u(4);                      // m/s
        const double period = 2.0 * 2.0 * span / speed;             // there and back
        const auto at = [&](double along) {
            return alongX ? glm::dvec3(along, half.y, across) : glm::dvec3(across, half.y, along);
        };
        Motion motion;
        motion.kind = Motion::Kind::Path;
        const glm::dquat heading = glm::angleAxis(alongX ? 0.0 : glm::half_pi<double>(), glm::dvec3(0.0, 1.0, 0.0));
        motion.keys = {{0.0, at(-span), heading}, {period * 0.5, at(span), heading}, {period, at(-span), heading}};
        motion.period = period;
        motion.start = period * u(5);
        motion.post = glm::scale(glm::dmat4(1.0), half);
        SceneObject vehicle{QStringLiteral("vehicle %1").arg(n + 1), box, motion.at(0.0), TextureKind::Flat, true, true,
                            glm::vec3(float(0.3 + 0.6 * u(6)), float(0.3 + 0.4 * u(7)), float(0.35 + 0.5 * u(2)))};
        vehicle.motion = motion;
        s.objects.push_back(std::move(vehicle));
    }
}

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
    addVehicles(s, cityVehicleCount(name));
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

// A preset's file (SceneNames.h): its shapes or generator, and its settings.
QJsonObject presetFile(const QString& name)
{
    const QString path = QStringLiteral("%1/%2.json").arg(QLatin1String(kScenePresetFolder), name);
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw SceneFileError(path, QStringLiteral("the built-in scene's file is missing from this build"));
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(file.readAll(), &error);
    if (error.error != QJsonParseError::NoError || !doc.isObject())
        throw SceneFileError(path, QStringLiteral("is not a JSON object: %1").arg(error.errorString()));
    return doc.object();
}

// What a preset file holds besides settings keys.
const QStringList kPresetFields{QStringLiteral("order"), QStringLiteral("about"), QStringLiteral("shapes"), QStringLiteral("generator")};

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
    return isPresetName(name) ? buildPresetScene(name) : *loadSceneFile(name);
}

Scene buildPresetScene(const QString& name)
{
    if (const int buildings = cityBuildingCount(name); buildings > 0)
        return cityScene(name, buildings);
    if (!isPresetName(name))
        throw SettingsError(QStringLiteral("scene"), QStringLiteral("'%1' is not a preset").arg(name));
    const QJsonObject preset = presetFile(name);
    const QString generator = preset.value(QStringLiteral("generator")).toString();
    if (generator == u"foliage")
        return foliageScene();
    if (!generator.isEmpty())
        throw SceneFileError(QStringLiteral("%1/%2.json").arg(QLatin1String(kScenePresetFolder), name),
                             QStringLiteral("names the generator '%1', which this build does not have").arg(generator));
    Scene s;
    s.name = name;
    appendShapes(s, preset.value(QStringLiteral("shapes")).toArray(), QStringLiteral("%1/%2.json").arg(QLatin1String(kScenePresetFolder), name));
    return s;
}

Settings presetSettings(const QString& name)
{
    if (!isPresetName(name))
        return sceneFileSettings(name);
    // The global defaults under the preset file's keys; every city:N shares the city's.
    QJsonObject keys = presetFile(cityBuildingCount(name) > 0 ? QStringLiteral("city") : name);
    for (const QString& field : kPresetFields)
        keys.remove(field);
    Settings s;
    s.scene = name;
    s = settingsFromJson(keys, s);
    s.scene = name;
    return s;
}

double sceneScale(const QString& name)
{
    if (isPresetName(name))
        return 1.0;
    const Bounds models = loadSceneFile(name)->modelBounds();
    return sceneLengthScale(std::max(glm::length(models.max - models.min) * 0.5, 1e-6));
}

QStringList objectTokens(const Scene& scene)
{
    // Counted once: a city has thousands of objects.
    QHash<QString, int> uses;
    for (const SceneObject& o : scene.objects)
        ++uses[o.name];
    QStringList tokens;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const QString& name = scene.objects[i].name;
        const bool own = !name.isEmpty() && !name.contains(u',') && !name.startsWith(u'#') && uses.value(name) == 1;
        tokens << (own ? name.trimmed() : QStringLiteral("#%1").arg(i));
    }
    return tokens;
}

void applyObjectSwitches(Scene& scene, const ObjectSwitches& switches)
{
    if (switches.noCast.isEmpty() && switches.noReceive.isEmpty())
        return;
    const QStringList tokens = objectTokens(scene);
    const auto apply = [&](const QStringList& names, const char* key, bool SceneObject::*flag) {
        for (const QString& name : names) {
            qsizetype i = tokens.indexOf(name);
            bool index = false;
            if (i < 0 && name.startsWith(u'#')) {
                i = name.mid(1).toLongLong(&index);     // any object by its index, named or not
                if (!index || i >= qsizetype(scene.objects.size()))
                    i = -1;
            }
            if (i < 0) {
                const QStringList shown = tokens.mid(0, 12);
                throw SettingsError(QString::fromLatin1(key), QStringLiteral("'%1' is no object of this scene; its objects are %2%3")
                                                                  .arg(displayText(name), shown.join(QStringLiteral(", ")),
                                                                       tokens.size() > shown.size() ? QStringLiteral(", …") : QString()));
            }
            scene.objects[std::size_t(i)].*flag = false;
        }
    };
    apply(switches.noCast, "objects.no_cast", &SceneObject::castsShadow);
    apply(switches.noReceive, "objects.no_receive", &SceneObject::receivesShadow);
}

CameraSettings presetCamera(const QString& name, double aspect)
{
    CameraSettings camera = presetSettings(name).camera;
    if (isPresetName(name) || !std::isfinite(aspect) || aspect <= 0.0)
        return camera;
    const Bounds models = loadSceneFile(name)->modelBounds();
    const double radius = glm::length(models.max - models.min) * 0.5;
    const glm::dvec3 toCamera = camera.position - models.center();
    const double distance = glm::length(toCamera);
    // A camera the file sets itself (looking elsewhere than the models' centre) is its author's.
    if (!(radius > 0.0) || !(distance > 0.0) || glm::length(camera.target - models.center()) > 1e-9 * (1.0 + radius))
        return camera;
    // The narrower half angle: the vertical field of view's, or the horizontal one of a tall view.
    const double halfHeight = glm::radians(camera.fov * 0.5);
    const double halfAngle = std::min(halfHeight, std::atan(std::tan(halfHeight) * aspect));
    const double needed = radius / std::sin(halfAngle) * 1.1;   // a tenth of margin round the sphere
    if (needed > distance)
        camera.position = models.center() + toCamera * (needed / distance);
    return camera;
}

Settings movedToScene(const Settings& side, const Settings& scene)
{
    Settings moved = side;
    moved.scene = scene.scene;
    moved.light = scene.light;
    moved.camera = scene.camera;
    moved.objects = scene.objects;
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

bool sceneMoves(const QString& name)
{
    if (cityBuildingCount(name) > 0)
        return cityVehicleCount(name) > 0;
    try {
        if (isPresetName(name)) {
            // Asked at every measurement (the reference's key): a preset is built once for it.
            static std::mutex mutex;
            static std::map<QString, bool> moving;
            std::lock_guard lock(mutex);
            const auto known = moving.find(name);
            return known != moving.end() ? known->second : moving.emplace(name, buildScene(name).moves()).first->second;
        }
        return loadSceneFile(name)->moves();
    } catch (const std::exception&) {
        return false;
    }
}

QString sceneIdentity(const QString& name)
{
    if (isPresetName(name))
        return name;
    return QStringLiteral("sha256:") + QString::fromLatin1(loadSceneFile(name)->identity);
}

} // namespace shadowlab
