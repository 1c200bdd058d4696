#include "SceneShapes.h"

#include "MessageText.h"
#include "ModelImporter.h"
#include "SceneFileError.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <QJsonArray>
#include <QJsonObject>
#include <QStringList>

#include <array>
#include <cmath>
#include <map>
#include <utility>

namespace shadowlab {

namespace {

constexpr double kMaxShapeCoordinate = 1e7;

const QStringList kShapeNames{QStringLiteral("cube"), QStringLiteral("pyramid"), QStringLiteral("sphere"), QStringLiteral("torus"),
                              QStringLiteral("plane"), QStringLiteral("card"), QStringLiteral("ground")};
// The keys every shape takes, and those of each kind.
const QStringList kCommonKeys{QStringLiteral("shape"), QStringLiteral("name"), QStringLiteral("colour"), QStringLiteral("casts"),
                              QStringLiteral("receives")};
const QStringList kPlacedKeys{QStringLiteral("position"), QStringLiteral("rotation"), QStringLiteral("scale"), QStringLiteral("texture"),
                              QStringLiteral("motion")};
const QStringList kMotionNames{QStringLiteral("spin"), QStringLiteral("orbit"), QStringLiteral("swing"), QStringLiteral("bob"), QStringLiteral("path")};
// The longest period or path a motion may have, and the most keys: a clip, not a recording.
constexpr double kMaxMotionSeconds = 1e5;
constexpr int kMaxPathKeys = 10000;
QStringList keysOf(const QString& shape)
{
    if (shape == u"ground")
        return kCommonKeys + QStringList{QStringLiteral("height"), QStringLiteral("size"), QStringLiteral("tiles")};
    QStringList keys = kCommonKeys + kPlacedKeys;
    if (shape == u"torus")
        keys << QStringLiteral("major") << QStringLiteral("minor") << QStringLiteral("segments") << QStringLiteral("sides");
    else if (shape == u"sphere")
        keys << QStringLiteral("segments") << QStringLiteral("rings");
    else if (shape == u"plane")
        keys << QStringLiteral("size") << QStringLiteral("tiles");
    return keys;
}
// The smallest scale: below it a shape's normals would not survive the inverse transpose.
constexpr double kMinShapeScale = 1e-6;
const QStringList kTextureNames{QStringLiteral("wood"), QStringLiteral("checker"), QStringLiteral("flat")};

// One shape's fields, read with its place in the file for every message.
class ShapeReader {
public:
    ShapeReader(QJsonObject object, const QString& path, QString where) : m_object(std::move(object)), m_path(path), m_where(std::move(where)) {}

    [[noreturn]] void fail(const QString& problem) const { throw SceneFileError(m_path, QStringLiteral("%1: %2").arg(m_where, problem)); }

    double number(const char* key, double fallback, double lo, double hi) const
    {
        const QJsonValue v = m_object.value(QLatin1String(key));
        if (v.isUndefined())
            return fallback;
        if (!v.isDouble() || !(v.toDouble() >= lo && v.toDouble() <= hi))
            fail(QStringLiteral("\"%1\" must be a number in [%2, %3]").arg(QLatin1String(key)).arg(lo).arg(hi));
        return v.toDouble();
    }
    int whole(const char* key, int fallback, int lo, int hi) const
    {
        const QJsonValue v = m_object.value(QLatin1String(key));
        if (v.isUndefined())
            return fallback;
        if (!v.isDouble() || v.toDouble() != std::floor(v.toDouble()) || !(v.toDouble() >= lo && v.toDouble() <= hi))
            fail(QStringLiteral("\"%1\" must be a whole number in [%2, %3]").arg(QLatin1String(key)).arg(lo).arg(hi));
        return int(v.toDouble());
    }
    // Three numbers, or one for all three.
    glm::dvec3 vector(const char* key, glm::dvec3 fallback, double lo, double hi) const
    {
        const QJsonValue v = m_object.value(QLatin1String(key));
        if (v.isUndefined())
            return fallback;
        glm::dvec3 result(v.toDouble());
        if (v.isArray() && v.toArray().size() == 3) {
            for (int i = 0; i < 3; ++i)
                result[i] = v.toArray()[i].isDouble() ? v.toArray()[i].toDouble() : NAN;
        } else if (!v.isDouble()) {
            result = glm::dvec3(NAN);
        }
        for (int i = 0; i < 3; ++i) {
            if (!(result[i] >= lo && result[i] <= hi))
                fail(QStringLiteral("\"%1\" must be three numbers in [%2, %3], e.g. [0, 1, 0]").arg(QLatin1String(key)).arg(lo).arg(hi));
        }
        return result;
    }
    bool flag(const char* key, bool fallback = true) const
    {
        const QJsonValue v = m_object.value(QLatin1String(key));
        if (!v.isUndefined() && !v.isBool())
            fail(QStringLiteral("\"%1\" must be true or false").arg(QLatin1String(key)));
        return v.toBool(fallback);
    }
    // One of `names`, by its index.
    int choice(const char* key, const QStringList& names, int fallback) const
    {
        const QJsonValue v = m_object.value(QLatin1String(key));
        if (v.isUndefined() && fallback >= 0)
            return fallback;
        if (!v.isString())
            fail(QStringLiteral("needs a \"%1\", one of %2").arg(QLatin1String(key), names.join(QStringLiteral(", "))));
        const int index = names.indexOf(v.toString());
        if (index < 0)
            fail(QStringLiteral("\"%1\": '%2' is not one of %3%4")
                     .arg(QLatin1String(key), displayText(v.toString()), names.join(QStringLiteral(", ")), didYouMean(v.toString(), names)));
        return index;
    }
    // Every key one of `keys`; `what` names the object in the message ("a torus").
    void refuseUnknownKeys(const QStringList& keys, const QString& what) const
    {
        for (auto it = m_object.begin(); it != m_object.end(); ++it) {
            if (!keys.contains(it.key()))
                fail(QStringLiteral("unknown key \"%1\"%2; %3 takes %4")
                         .arg(displayText(it.key()), didYouMean(it.key(), keys), what, keys.join(QStringLiteral(", "))));
        }
    }
    // Translation, then rotation (about an axis, or about z, y and x in turn), then scale.
    glm::dmat4 placement() const
    {
        glm::dmat4 m = turned(glm::translate(glm::dmat4(1.0), position()));
        const glm::dvec3 scale = vector("scale", glm::dvec3(1.0), 0.0, kMaxShapeCoordinate);
        if (!(scale.x >= kMinShapeScale && scale.y >= kMinShapeScale && scale.z >= kMinShapeScale))
            fail(QStringLiteral("\"scale\" must be positive, at least %1").arg(kMinShapeScale));
        return glm::scale(m, scale);
    }
    glm::dvec3 position() const { return vector("position", glm::dvec3(0.0), -kMaxShapeCoordinate, kMaxShapeCoordinate); }
    // `m` then "rotation": {"angle": degrees, "axis": [x, y, z]}, or degrees about z, y and x in turn.
    glm::dmat4 turned(glm::dmat4 m) const
    {
        const QJsonValue rotation = m_object.value(QStringLiteral("rotation"));
        if (rotation.isObject()) {
            const ShapeReader about(rotation.toObject(), m_path, m_where + QStringLiteral(".rotation"));
            about.refuseUnknownKeys({QStringLiteral("angle"), QStringLiteral("axis")}, QStringLiteral("a rotation"));
            const double angle = about.number("angle", 0.0, -36000.0, 36000.0);
            const glm::dvec3 axis = about.direction("axis", glm::dvec3(0.0, 1.0, 0.0));
            return angle != 0.0 ? glm::rotate(m, glm::radians(angle), axis) : m;
        }
        const glm::dvec3 degrees = vector("rotation", glm::dvec3(0.0), -36000.0, 36000.0);
        m = glm::rotate(m, glm::radians(degrees.z), glm::dvec3(0, 0, 1));
        m = glm::rotate(m, glm::radians(degrees.y), glm::dvec3(0, 1, 0));
        return glm::rotate(m, glm::radians(degrees.x), glm::dvec3(1, 0, 0));
    }
    // A direction: three numbers, not all zero, made unit length.
    glm::dvec3 direction(const char* key, glm::dvec3 fallback) const
    {
        const glm::dvec3 axis = vector(key, fallback, -1e6, 1e6);
        if (!(glm::length(axis) > 1e-12))
            fail(QStringLiteral("\"%1\" must not be zero").arg(QLatin1String(key)));
        return glm::normalize(axis);
    }
    // The shape's "motion", if any, for a shape placed by `model` at `origin`.
    std::optional<Motion> motion(const glm::dmat4& model, const glm::dvec3& origin) const;
    // A child object's reader ("motion", "keys[2]").
    ShapeReader child(const QJsonValue& value, const QString& name, const QString& example) const
    {
        if (!value.isObject())
            fail(QStringLiteral("\"%1\" must be an object, e.g. %2").arg(name, example));
        return ShapeReader(value.toObject(), m_path, m_where + QLatin1Char('.') + name);
    }
    QJsonValue value(const char* key) const { return m_object.value(QLatin1String(key)); }

private:
    QJsonObject m_object;
    const QString& m_path;
    QString m_where;
};

std::optional<Motion> ShapeReader::motion(const glm::dmat4& model, const glm::dvec3& origin) const
{
    const QJsonValue value = m_object.value(QStringLiteral("motion"));
    if (value.isUndefined())
        return std::nullopt;
    const ShapeReader r = child(value, QStringLiteral("motion"), QStringLiteral("{\"type\": \"spin\", \"period\": 4}"));
    Motion motion;
    motion.kind = Motion::Kind(r.choice("type", kMotionNames, -1));
    const QString& type = kMotionNames[int(motion.kind)];
    QStringList keys{QStringLiteral("type"), QStringLiteral("start")};
    if (motion.kind == Motion::Kind::Path)
        keys << QStringLiteral("keys") << QStringLiteral("smooth");
    else
        keys << QStringLiteral("period") << QStringLiteral("axis");
    if (motion.kind == Motion::Kind::Spin || motion.kind == Motion::Kind::Orbit)
        keys << QStringLiteral("speed");
    if (motion.kind == Motion::Kind::Orbit || motion.kind == Motion::Kind::Swing)
        keys << QStringLiteral("centre");
    if (motion.kind == Motion::Kind::Swing)
        keys << QStringLiteral("angle");
    if (motion.kind == Motion::Kind::Bob)
        keys << QStringLiteral("amplitude");
    r.refuseUnknownKeys(keys, QStringLiteral("a %1 motion").arg(type));
    motion.start = r.number("start", 0.0, -kMaxMotionSeconds, kMaxMotionSeconds);

    if (motion.kind != Motion::Kind::Path) {
        motion.axis = r.direction("axis", glm::dvec3(0.0, 1.0, 0.0));
        motion.period = r.number("period", 4.0, 1e-3, kMaxMotionSeconds);
        if (!r.value("speed").isUndefined()) {
            if (!r.value("period").isUndefined())
                r.fail(QStringLiteral("give \"period\" (seconds a turn) or \"speed\" (degrees a second), not both"));
            const double speed = r.number("speed", 90.0, -1e6, 1e6);
            if (std::abs(speed) < 1e-3)
                r.fail(QStringLiteral("\"speed\" must be at least 0.001 degrees a second either way; leave \"motion\" out for a still shape"));
            motion.period = std::min(360.0 / std::abs(speed), kMaxMotionSeconds);
            if (speed < 0.0)
                motion.axis = -motion.axis;
        }
        motion.point = motion.kind == Motion::Kind::Spin ? origin : r.vector("centre", origin, -kMaxShapeCoordinate, kMaxShapeCoordinate);
        if (motion.kind == Motion::Kind::Swing)
            motion.amplitude = glm::radians(r.number("angle", 30.0, 0.0, 180.0));
        if (motion.kind == Motion::Kind::Bob)
            motion.amplitude = r.number("amplitude", 0.5, 0.0, kMaxShapeCoordinate);
        motion.post = model;
        return motion;
    }

    // A path places the shape's origin at its keys and turns it by their rotation after its own.
    const QJsonValue list = r.value("keys");
    if (!list.isArray() || list.toArray().size() < 2)
        r.fail(QStringLiteral("a path needs \"keys\", a list of at least two, e.g. [{\"time\": 0, \"position\": [0, 1, 0]}, "
                              "{\"time\": 2, \"position\": [4, 1, 0]}]"));
    if (list.toArray().size() > kMaxPathKeys)
        r.fail(QStringLiteral("a path may have at most %1 keys").arg(kMaxPathKeys));
    motion.smooth = r.flag("smooth", false);
    const QJsonArray array = list.toArray();
    for (qsizetype k = 0; k < array.size(); ++k) {
        const ShapeReader key = r.child(array[k], QStringLiteral("keys[%1]").arg(k), QStringLiteral("{\"time\": 0, \"position\": [0, 1, 0]}"));
        key.refuseUnknownKeys({QStringLiteral("time"), QStringLiteral("position"), QStringLiteral("rotation")}, QStringLiteral("a path key"));
        if (key.value("time").isUndefined())
            key.fail(QStringLiteral("needs a \"time\" in seconds"));
        MotionKey mk;
        mk.time = key.number("time", 0.0, 0.0, kMaxMotionSeconds);
        mk.position = key.vector("position", origin, -kMaxShapeCoordinate, kMaxShapeCoordinate);
        mk.rotation = glm::normalize(glm::quat_cast(glm::dmat3(key.turned(glm::dmat4(1.0)))));
        if (k == 0 && mk.time != 0.0)
            key.fail(QStringLiteral("the first key's \"time\" must be 0"));
        if (k > 0 && !(mk.time > motion.keys.back().time))
            key.fail(QStringLiteral("\"time\" must be after the key before's (%1 s); keys go in order of time").arg(motion.keys.back().time));
        motion.keys.push_back(mk);
    }
    motion.period = motion.keys.back().time;
    motion.post = glm::translate(glm::dmat4(1.0), -origin) * model;
    return motion;
}

// The mesh of a shape and the parameters that make it, for sharing one mesh between equal shapes.
struct ShapeMesh {
    int kind = 0;
    double a = 0.0, b = 0.0;
    int c = 0, d = 0;
    auto operator<=>(const ShapeMesh&) const = default;
};

ShapeMesh shapeMesh(const ShapeReader& r, int kind)
{
    const QString& name = kShapeNames[kind];
    if (name == u"torus") {
        const double major = r.number("major", 1.0, 1e-6, 1e6), minor = r.number("minor", 0.35, 1e-6, 1e6);
        if (!(minor < major))
            r.fail(QStringLiteral("a torus's \"minor\" radius must be smaller than its \"major\" one"));
        return {kind, major, minor, r.whole("segments", 64, 3, 1024), r.whole("sides", 24, 3, 1024)};
    }
    if (name == u"sphere")
        return {kind, 0.0, 0.0, r.whole("segments", 32, 3, 1024), r.whole("rings", 16, 3, 1024)};
    if (name == u"plane" || name == u"ground") {
        const double size = r.number("size", 25.0, 1e-6, 1e6);
        return {kind, size, r.number("tiles", size, 1e-6, 1e6), 0, 0};
    }
    return {kind};
}

Mesh makeMesh(const ShapeMesh& m)
{
    const QString& name = kShapeNames[m.kind];
    if (name == u"cube")
        return meshes::cube();
    if (name == u"pyramid")
        return meshes::pyramid();
    if (name == u"sphere")
        return meshes::sphere(m.c, m.d);
    if (name == u"torus")
        return meshes::torus(float(m.a), float(m.b), m.c, m.d);
    if (name == u"card")
        return meshes::card();
    return meshes::plane(float(m.a), float(m.b));
}

} // namespace

bool appendShapes(Scene& scene, const QJsonArray& shapes, const QString& path)
{
    std::map<ShapeMesh, int> meshOf;
    bool closed = true;
    std::size_t triangles = 0;
    for (qsizetype i = 0; i < shapes.size(); ++i) {
        const QString where = QStringLiteral("shapes[%1]").arg(i);
        if (!shapes[i].isObject())
            throw SceneFileError(path, QStringLiteral("%1 must be an object, e.g. {\"shape\": \"cube\"}").arg(where));
        const QJsonObject object = shapes[i].toObject();
        const ShapeReader r(object, path, where);
        const int kind = r.choice("shape", kShapeNames, -1);
        const bool ground = kShapeNames[kind] == u"ground";
        r.refuseUnknownKeys(keysOf(kShapeNames[kind]), QStringLiteral("a %1").arg(kShapeNames[kind]));
        const ShapeMesh key = shapeMesh(r, kind);
        auto [it, added] = meshOf.emplace(key, int(scene.meshes.size()));
        if (added)
            scene.meshes.push_back(makeMesh(key));

        SceneObject o;
        o.name = object.value(QStringLiteral("name")).toString(ground ? QStringLiteral("ground") : QStringLiteral("%1 %2").arg(kShapeNames[kind]).arg(i + 1));
        o.mesh = it->second;
        if (ground) {
            const double height = r.number("height", 0.0, -kMaxShapeCoordinate, kMaxShapeCoordinate);
            o.model = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, height, 0.0));
            o.texture = TextureKind::Checker;
            scene.groundHeight = height;
        } else {
            o.model = r.placement();
            o.motion = r.motion(o.model, r.position());
            if (o.motion)
                o.model = o.motion->at(0.0);
            o.texture = std::array{TextureKind::Wood, TextureKind::Checker, TextureKind::Flat}[std::size_t(r.choice("texture", kTextureNames, 0))];
        }
        o.baseColour = glm::vec3(r.vector("colour", glm::dvec3(1.0), 0.0, 1.0));
        o.castsShadow = r.flag("casts");
        o.receivesShadow = r.flag("receives");
        const QString& name = kShapeNames[kind];
        closed = closed && (!o.castsShadow || ground || (name != u"plane" && name != u"card"));
        // What a model may be, a file of shapes may be: as many triangles, and within reach of float.
        triangles += scene.meshes[std::size_t(o.mesh)].indices.size() / 3;
        if (triangles > kMaxModelTriangles)
            r.fail(QStringLiteral("the shapes so far have %1 triangles, more than the %2 a scene may have; use fewer divisions").arg(triangles).arg(kMaxModelTriangles));
        const Bounds placed = scene.worldBounds(o);
        if (glm::any(glm::greaterThan(glm::max(glm::abs(placed.min), glm::abs(placed.max)), glm::dvec3(kMaxShapeCoordinate))))
            r.fail(QStringLiteral("reaches beyond %1 units from the origin; move it closer or make it smaller").arg(kMaxShapeCoordinate));
        scene.objects.push_back(std::move(o));
    }
    return closed;
}

} // namespace shadowlab
