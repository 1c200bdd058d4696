#include "SceneLoader.h"

#include "IsolatedImport.h"
#include "SceneFileError.h"
#include "SceneShapes.h"
#include "SettingsKeys.h"

#include <glm/gtc/matrix_transform.hpp>

#include <QCryptographicHash>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

namespace shadowlab {

namespace {

constexpr qint64 kMaxSceneFileBytes = 1 << 20;      // a scene file is a short list, not data
constexpr double kSeedObjectRadius = 2.5;           // the seed preset's objects, whose defaults the bias was tuned on

} // namespace

double sceneLengthScale(double modelRadius)
{
    return modelRadius / kSeedObjectRadius;
}

namespace {

struct Loaded {
    std::shared_ptr<const Scene> scene;     // what is drawn, with its ground (a model's is its last mesh and object)
    QJsonObject settings;                   // a scene file's keys of `shadowlab settings`
    bool closedCasters = false;             // every caster is a closed shape: front faces may be culled
};

// A model file's meshes alone, to place in a scene file: its scene without the ground that
// load() added. Made when a scene file asks, so opening a model alone copies nothing.
Scene withoutGround(const Scene& scene)
{
    Scene model = scene;
    model.meshes.pop_back();
    model.objects.pop_back();
    model.groundHeight.reset();
    return model;
}

bool isSceneFile(const QString& path)
{
    return QFileInfo(path).suffix().compare(QStringLiteral("json"), Qt::CaseInsensitive) == 0;
}

// The cache: path -> (size, modified, load). Shared by threads (tracing runs off the GUI thread).
// A file that was read and then saved in a form that cannot be read keeps its last good load,
// served while the file stays as it failed: only the first read of the bad file says why.
struct CacheEntry {
    qint64 size = -1;
    QDateTime modified;
    Loaded loaded;
    qint64 failedSize = -1;
    QDateTime failedModified;
};
std::mutex g_cacheMutex;
std::map<QString, CacheEntry> g_cache;

Loaded load(const QString& path, const ImportControl& control);

Loaded cached(const QString& path, const ImportControl& control)
{
    const QFileInfo info(path);
    if (!info.exists())
        throw SceneFileError(path, QStringLiteral("no such file; check the path"));
    const QString key = info.absoluteFilePath();
    {
        std::lock_guard lock(g_cacheMutex);
        const auto it = g_cache.find(key);
        const auto stampIs = [&](qint64 size, const QDateTime& modified) { return size == info.size() && modified == info.lastModified(); };
        if (it != g_cache.end() && (stampIs(it->second.size, it->second.modified) || stampIs(it->second.failedSize, it->second.failedModified)))
            return it->second.loaded;
    }
    Loaded loaded;
    try {
        loaded = load(key, control);
    } catch (const ImportCancelled&) {
        throw;
    } catch (const SceneFileError&) {
        std::lock_guard lock(g_cacheMutex);
        if (const auto it = g_cache.find(key); it != g_cache.end()) {
            it->second.failedSize = info.size();
            it->second.failedModified = info.lastModified();
        }
        throw;
    }
    std::lock_guard lock(g_cacheMutex);
    g_cache[key] = {info.size(), info.lastModified(), loaded, -1, {}};
    return loaded;
}

glm::dvec3 vectorOf(const QString& path, const QString& what, const QJsonValue& value, glm::dvec3 fallback)
{
    if (value.isUndefined())
        return fallback;
    if (value.isDouble())
        return glm::dvec3(value.toDouble());
    const QJsonArray a = value.toArray();
    if (a.size() != 3 || !a[0].isDouble() || !a[1].isDouble() || !a[2].isDouble())
        throw SceneFileError(path, QStringLiteral("%1 must be three numbers, e.g. [0, 1, 0]").arg(what));
    return {a[0].toDouble(), a[1].toDouble(), a[2].toDouble()};
}

void addGround(Scene& scene, double height)
{
    const Bounds b = scene.bounds();
    const double radius = std::max({b.max.x - b.min.x, b.max.z - b.min.z, 1e-3}) * 0.5;
    const double half = radius * 4.0;
    const glm::dvec3 centre = b.center();
    scene.groundHeight = height;
    scene.meshes.push_back(meshes::plane(float(half), 8.0f));
    SceneObject ground;
    ground.name = QStringLiteral("ground");
    ground.mesh = int(scene.meshes.size() - 1);
    ground.model = glm::translate(glm::dmat4(1.0), glm::dvec3(centre.x, height, centre.z));
    ground.texture = TextureKind::Checker;
    scene.objects.push_back(ground);
}

// Appends `part` to `scene` under `placement`.
void append(Scene& scene, const Scene& part, const glm::dmat4& placement, bool casts, bool receives)
{
    const int meshOffset = int(scene.meshes.size());
    const int imageOffset = int(scene.images.size());
    scene.meshes.insert(scene.meshes.end(), part.meshes.begin(), part.meshes.end());
    scene.images.insert(scene.images.end(), part.images.begin(), part.images.end());
    for (SceneObject object : part.objects) {
        object.mesh += meshOffset;
        if (object.image >= 0)
            object.image += imageOffset;
        object.model = placement * object.model;
        if (object.motion)
            object.motion->pre = placement * object.motion->pre;
        object.castsShadow = casts;
        object.receivesShadow = receives;
        scene.objects.push_back(std::move(object));
    }
    scene.warnings += part.warnings;
}

Loaded loadScene(const QString& path, const ImportControl& control)
{
    QFile file(path);
    if (QFileInfo(path).size() > kMaxSceneFileBytes)
        throw SceneFileError(path, QStringLiteral("is larger than %1 KiB; a scene file lists models, it does not hold them").arg(kMaxSceneFileBytes >> 10));
    if (!file.open(QIODevice::ReadOnly))
        throw SceneFileError(path, QStringLiteral("cannot be read: %1").arg(file.errorString()));
    const QByteArray bytes = file.readAll();
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &error);
    if (error.error != QJsonParseError::NoError)
        throw SceneFileError(path, QStringLiteral("is not valid JSON at offset %1: %2").arg(error.offset).arg(error.errorString()));
    QJsonObject object = doc.object();
    const QJsonArray models = object.take(QStringLiteral("models")).toArray();
    const QJsonValue shapes = object.take(QStringLiteral("shapes"));
    const QJsonValue ground = object.take(QStringLiteral("ground"));
    if (!shapes.isUndefined() && !shapes.isArray())
        throw SceneFileError(path, QStringLiteral("\"shapes\" must be a list, e.g. [{\"shape\": \"cube\"}]"));
    if (models.isEmpty() && shapes.toArray().isEmpty())
        throw SceneFileError(path, QStringLiteral("lists no models and no shapes; add \"models\": [{\"file\": \"model.glb\"}] "
                                                  "or \"shapes\": [{\"shape\": \"cube\"}]"));

    Loaded loaded;
    auto scene = std::make_shared<Scene>();
    scene->name = QFileInfo(path).absoluteFilePath();
    QCryptographicHash identity(QCryptographicHash::Sha256);
    identity.addData(bytes);
    for (qsizetype i = 0; i < models.size(); ++i) {
        const QJsonObject m = models[i].toObject();
        const QString where = QStringLiteral("models[%1]").arg(i);
        const QString name = m.value(QStringLiteral("file")).toString();
        if (name.isEmpty())
            throw SceneFileError(path, QStringLiteral("%1 has no \"file\"").arg(where));
        const QString modelPath = QFileInfo(QFileInfo(path).dir(), name).absoluteFilePath();
        if (isSceneFile(modelPath))
            throw SceneFileError(path, QStringLiteral("%1: a scene file cannot include another scene file").arg(where));
        const Scene part = withoutGround(*cached(modelPath, control).scene);
        const glm::dvec3 position = vectorOf(path, where + QStringLiteral(".position"), m.value(QStringLiteral("position")), glm::dvec3(0.0));
        const glm::dvec3 rotation = vectorOf(path, where + QStringLiteral(".rotation"), m.value(QStringLiteral("rotation")), glm::dvec3(0.0));
        const glm::dvec3 scale = vectorOf(path, where + QStringLiteral(".scale"), m.value(QStringLiteral("scale")), glm::dvec3(1.0));
        if (scale.x <= 0.0 || scale.y <= 0.0 || scale.z <= 0.0)
            throw SceneFileError(path, QStringLiteral("%1.scale must be positive").arg(where));
        glm::dmat4 placement = glm::translate(glm::dmat4(1.0), position);
        placement = glm::rotate(placement, glm::radians(rotation.z), glm::dvec3(0, 0, 1));
        placement = glm::rotate(placement, glm::radians(rotation.y), glm::dvec3(0, 1, 0));
        placement = glm::rotate(placement, glm::radians(rotation.x), glm::dvec3(1, 0, 0));
        placement = glm::scale(placement, scale);
        append(*scene, part, placement, m.value(QStringLiteral("casts")).toBool(true), m.value(QStringLiteral("receives")).toBool(true));
        identity.addData(part.identity);
    }
    loaded.closedCasters = appendShapes(*scene, shapes.toArray(), path) && models.isEmpty();
    // A "ground" shape is the ground; otherwise one is laid under what the file places.
    if (!scene->groundHeight && ground.isDouble())
        addGround(*scene, ground.toDouble());
    else if (!scene->groundHeight && (ground.isUndefined() || ground.toBool(false)))
        addGround(*scene, scene->bounds().min.y);
    scene->identity = identity.result().toHex();
    loaded.scene = std::move(scene);
    loaded.settings = object;
    return loaded;
}

Loaded load(const QString& path, const ImportControl& control)
{
    if (isSceneFile(path))
        return loadScene(path, control);
    auto scene = std::make_shared<Scene>(importModelIsolated(path, control));
    addGround(*scene, scene->bounds().min.y);
    return {std::move(scene), {}};
}

} // namespace

std::shared_ptr<const Scene> loadSceneFile(const QString& path, const ImportControl& control)
{
    return cached(path, control).scene;
}

std::shared_ptr<const Scene> loadedSceneFile(const QString& path)
{
    std::lock_guard lock(g_cacheMutex);
    const auto it = g_cache.find(QFileInfo(path).absoluteFilePath());
    return it == g_cache.end() ? nullptr : it->second.loaded.scene;
}

Settings sceneFileSettings(const QString& path)
{
    const Loaded loaded = cached(path, ImportControl{});
    const Scene& scene = *loaded.scene;
    // Frame what is not ground: the camera and light follow the models, not the big plane.
    const Bounds models = scene.modelBounds();
    const glm::dvec3 centre = models.center();
    const double radius = std::max(glm::length(models.max - models.min) * 0.5, 1e-6);

    Settings s;
    s.scene = scene.name;
    s.camera.fov = 45.0;
    // Far enough that the bounding sphere fits the height with a margin, and most of the width
    // of a narrow view (the window shares its width with the depth map and the dock).
    const double distance = radius / std::sin(glm::radians(s.camera.fov * 0.5)) * 1.3;
    s.camera.target = centre;
    s.camera.position = centre + glm::normalize(glm::dvec3(0.55, 0.55, 1.0)) * distance;
    // From above at about 55 degrees elevation, from the side opposite the camera's left, so the
    // shadow falls on the ground in view.
    s.light.target = centre;
    s.light.position = centre + glm::normalize(glm::dvec3(-0.6, 1.4, -0.4)) * radius * 3.0;
    // The hand-set volume (light.fit=manual) covers the ground in view, not just the model;
    // the default fit shrinks it to what casts onto what the camera sees.
    s.light.extent = radius * 4.0;
    s.light.nearPlane = radius * 0.5;
    s.light.farPlane = radius * 8.0;
    // World-space lengths tuned on the seed preset scale with the model.
    const double scale = sceneLengthScale(radius);
    s.bias.slope = std::min(s.bias.slope * scale, 100.0);
    s.bias.min = std::min(s.bias.min * scale, 100.0);
    s.reference.lightRadius = std::min(s.reference.lightRadius * scale, 100.0);
    // Cascades cover what is in view: the model and the ground round it, not the seed's 100 wu.
    s.shadow.distance = std::min(distance + radius * 2.0, 1e7);
    // Front-face culling in the shadow pass needs closed meshes; models are often open
    // (single-sided shells, thin legs) and would lose their shadows, so draw both sides. A file
    // of closed shapes only keeps it, and with it the defaults' freedom from acne.
    s.bias.cullFront = loaded.closedCasters;
    if (!loaded.settings.isEmpty()) {
        try {
            s = settingsFromJson(loaded.settings, s);
        } catch (const SettingsError& e) {
            throw SceneFileError(path, QString::fromUtf8(e.what()));
        }
        s.scene = scene.name;
    }
    return s;
}

} // namespace shadowlab
