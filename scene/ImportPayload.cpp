#include "ImportPayload.h"

#include "Limits.h"
#include "ModelImporter.h"
#include "SceneFileError.h"

#include <glm/geometric.hpp>

#include <QtEndian>

#include <cmath>
#include <cstring>
#include <type_traits>

namespace shadowlab {

namespace {

constexpr char kMagic[] = "SLIMPORT";
constexpr char kTrailer[] = "END.";
constexpr quint32 kVersion = 3;     // 3: objects carry their motion
constexpr quint32 kMaxStringBytes = 1 << 16;
constexpr quint32 kMaxWarnings = 1024;
constexpr std::size_t kMaxObjects = kMaxModelTriangles;    // one triangle each at the most
static_assert(sizeof(Vertex) == 8 * sizeof(float), "the payload sends a vertex as 8 floats");
static_assert(QSysInfo::ByteOrder == QSysInfo::LittleEndian, "vertex arrays are sent as they lie in memory");

class Writer {
public:
    template <typename T>
    void put(T value)
    {
        static_assert(std::is_arithmetic_v<T>);
        const T le = qToLittleEndian(value);
        m_bytes.append(reinterpret_cast<const char*>(&le), sizeof le);
    }
    void raw(const void* data, std::size_t size) { m_bytes.append(static_cast<const char*>(data), qsizetype(size)); }
    void string(const QString& text)
    {
        const QByteArray utf8 = text.toUtf8().left(kMaxStringBytes);
        put(quint32(utf8.size()));
        m_bytes.append(utf8);
    }
    QByteArray take() { return std::move(m_bytes); }

private:
    QByteArray m_bytes;
};

// What did not hold together in an answer; caught and worded once, in decodeImportReply().
struct Malformed {
    QString what;
};

class Reader {
public:
    explicit Reader(const QByteArray& bytes) : m_data(bytes.constData()), m_left(std::size_t(bytes.size())) {}

    std::size_t left() const { return m_left; }
    template <typename T>
    T get()
    {
        T value;
        std::memcpy(&value, take(sizeof value, "a number"), sizeof value);
        return qFromLittleEndian(value);
    }
    // `count` items of `itemBytes` each, refused before any allocation when the bytes are not there.
    const char* array(std::size_t count, std::size_t itemBytes, const char* what)
    {
        if (itemBytes != 0 && count > m_left / itemBytes)
            throw Malformed{QStringLiteral("%1 says %2 items, more than the answer holds").arg(QLatin1String(what)).arg(count)};
        return take(count * itemBytes, what);
    }
    std::size_t count(std::size_t maximum, std::size_t itemBytes, const char* what)
    {
        const quint32 n = get<quint32>();
        if (n > maximum)
            throw Malformed{QStringLiteral("%1 count %2 is over the limit of %3").arg(QLatin1String(what)).arg(n).arg(maximum)};
        if (itemBytes != 0 && n > m_left / itemBytes)
            throw Malformed{QStringLiteral("%1 count %2 is more than the answer holds").arg(QLatin1String(what)).arg(n)};
        return n;
    }
    QString string(const char* what)
    {
        const quint32 size = get<quint32>();
        if (size > kMaxStringBytes)
            throw Malformed{QStringLiteral("%1 is %2 bytes long").arg(QLatin1String(what)).arg(size)};
        const char* data = array(size, 1, what);
        return QString::fromUtf8(data, qsizetype(size));
    }
    void expect(const char* literal, const char* what)
    {
        const std::size_t size = std::strlen(literal);
        if (m_left < size || std::memcmp(m_data, literal, size) != 0)
            throw Malformed{QLatin1String(what)};
        take(size, what);
    }

private:
    const char* take(std::size_t size, const char* what)
    {
        if (size > m_left)
            throw Malformed{QStringLiteral("it ends inside %1").arg(QLatin1String(what))};
        const char* at = m_data;
        m_data += size;
        m_left -= size;
        return at;
    }

    const char* m_data;
    std::size_t m_left;
};

void header(Writer& out, ImportReplyKind kind)
{
    out.raw(kMagic, 8);
    out.put(kVersion);
    out.put(quint8(kind));
}

bool finite(const glm::vec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void putVector(Writer& out, const glm::dvec3& v)
{
    for (int i = 0; i < 3; ++i)
        out.put(v[i]);
}

void putMatrix(Writer& out, const glm::dmat4& m)
{
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r)
            out.put(m[c][r]);
    }
}

void putMotion(Writer& out, const Motion& motion)
{
    out.put(quint8(motion.kind));
    out.put(quint8(motion.smooth));
    out.put(motion.period);
    out.put(motion.start);
    out.put(motion.amplitude);
    putVector(out, motion.point);
    putVector(out, motion.axis);
    putMatrix(out, motion.pre);
    putMatrix(out, motion.post);
    out.put(quint32(motion.keys.size()));
    for (const MotionKey& key : motion.keys) {
        out.put(key.time);
        putVector(out, key.position);
        for (const double q : {key.rotation.w, key.rotation.x, key.rotation.y, key.rotation.z})
            out.put(q);
        putVector(out, key.scale);
    }
}

glm::dvec3 readVector(Reader& in)
{
    glm::dvec3 v;
    for (int i = 0; i < 3; ++i)
        v[i] = in.get<double>();
    return v;
}

// A motion's fixed placement: finite, as motionProblem() does not look at it.
glm::dmat4 readMatrix(Reader& in)
{
    glm::dmat4 m;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            m[c][r] = in.get<double>();
            if (!std::isfinite(m[c][r]))
                throw Malformed{QStringLiteral("a motion's fixed placement is not finite")};
        }
    }
    return m;
}

constexpr std::size_t kMotionKeyBytes = 11 * sizeof(double);

// The motion of `object`, checked as a scene file's is (motionProblem()): finite numbers, key
// times from 0 increasing, unit rotations, at most kMaxMotionKeys keys.
Motion readMotion(Reader& in, const QString& object)
{
    Motion motion;
    const quint8 kind = in.get<quint8>();
    if (kind > quint8(Motion::Kind::Path))
        throw Malformed{QStringLiteral("object '%1' has motion kind %2").arg(object).arg(kind)};
    motion.kind = Motion::Kind(kind);
    motion.smooth = in.get<quint8>() != 0;
    motion.period = in.get<double>();
    motion.start = in.get<double>();
    motion.amplitude = in.get<double>();
    motion.point = readVector(in);
    motion.axis = readVector(in);
    motion.pre = readMatrix(in);
    motion.post = readMatrix(in);
    const std::size_t keys = in.count(kMaxMotionKeys, kMotionKeyBytes, "motion key");
    motion.keys.resize(keys);
    for (MotionKey& key : motion.keys) {
        key.time = in.get<double>();
        key.position = readVector(in);
        key.rotation.w = in.get<double>();
        key.rotation.x = in.get<double>();
        key.rotation.y = in.get<double>();
        key.rotation.z = in.get<double>();
        key.scale = readVector(in);
        // Drift that rounding leaves is put right; a rotation of unit length passes as sent (to
        // the bit, as the worker made it), one further off is refused below.
        const double drift = std::abs(glm::length(key.rotation) - 1.0);
        if (drift > 1e-12 && drift <= 1e-4)
            key.rotation = glm::normalize(key.rotation);
    }
    if (const QString problem = motionProblem(motion); !problem.isEmpty())
        throw Malformed{QStringLiteral("the motion of object '%1': %2").arg(object, problem)};
    return motion;
}

Mesh readMesh(Reader& in, std::size_t& triangles)
{
    Mesh mesh;
    mesh.convex = in.get<quint8>() != 0;
    const std::size_t vertices = in.get<quint32>();
    const std::size_t indices = in.get<quint32>();
    if (indices % 3 != 0)
        throw Malformed{QStringLiteral("a mesh has %1 indices, not whole triangles").arg(indices)};
    triangles += indices / 3;
    if (triangles > kMaxModelTriangles)
        throw Malformed{QStringLiteral("more than %1 triangles").arg(kMaxModelTriangles)};
    const char* vertexData = in.array(vertices, sizeof(Vertex), "a vertex array");
    const char* indexData = in.array(indices, sizeof(std::uint32_t), "an index array");
    if (indices == 0)
        throw Malformed{QStringLiteral("a mesh has no triangles")};
    mesh.vertices.resize(vertices);
    if (vertices > 0)
        std::memcpy(mesh.vertices.data(), vertexData, vertices * sizeof(Vertex));
    mesh.indices.resize(indices);
    std::memcpy(mesh.indices.data(), indexData, indices * sizeof(std::uint32_t));
    for (Vertex& v : mesh.vertices) {
        if (!finite(v.position))
            throw Malformed{QStringLiteral("a vertex position is not a finite number")};
        // A normal or UV that is not usable is drawn as a default rather than refused: it
        // changes shading, never the shadow or the memory touched.
        const float length = finite(v.normal) ? glm::length(v.normal) : 0.0f;
        if (!(length > 1e-12f) || !std::isfinite(length))
            v.normal = glm::vec3(0.0f, 1.0f, 0.0f);
        else if (std::abs(length - 1.0f) > 1e-4f)
            v.normal /= length;
        if (!std::isfinite(v.uv.x) || !std::isfinite(v.uv.y))
            v.uv = glm::vec2(0.0f);
    }
    for (std::uint32_t index : mesh.indices) {
        if (index >= vertices)
            throw Malformed{QStringLiteral("an index (%1) names a vertex a mesh of %2 does not have").arg(index).arg(vertices)};
    }
    return mesh;
}

QImage readImage(Reader& in)
{
    const quint32 width = in.get<quint32>();
    const quint32 height = in.get<quint32>();
    if (width == 0 || height == 0 || width > quint32(kMaxImageSide) || height > quint32(kMaxImageSide))
        throw Malformed{QStringLiteral("a texture is %1 × %2 texels").arg(width).arg(height)};
    const char* pixels = in.array(std::size_t(width) * height, 4, "a texture");
    QImage image(int(width), int(height), QImage::Format_RGBA8888);
    if (image.isNull())
        throw Malformed{QStringLiteral("a %1 × %2 texture does not fit in memory").arg(width).arg(height)};
    for (quint32 y = 0; y < height; ++y)
        std::memcpy(image.scanLine(int(y)), pixels + std::size_t(y) * width * 4, std::size_t(width) * 4);
    return image;
}

SceneObject readObject(Reader& in, const Scene& scene)
{
    SceneObject object;
    object.name = in.string("an object's name");
    const quint32 mesh = in.get<quint32>();
    if (mesh >= scene.meshes.size())
        throw Malformed{QStringLiteral("an object names mesh %1 of %2").arg(mesh).arg(scene.meshes.size())};
    object.mesh = int(mesh);
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            object.model[c][r] = in.get<double>();
            if (!std::isfinite(object.model[c][r]))
                throw Malformed{QStringLiteral("an object's placement is not finite")};
        }
    }
    const quint8 texture = in.get<quint8>();
    if (texture > quint8(TextureKind::Image))
        throw Malformed{QStringLiteral("an object has texture kind %1").arg(texture)};
    object.texture = TextureKind(texture);
    object.castsShadow = in.get<quint8>() != 0;
    object.receivesShadow = in.get<quint8>() != 0;
    for (int i = 0; i < 3; ++i)
        object.baseColour[i] = in.get<float>();
    object.baseColour = finite(object.baseColour) ? glm::clamp(object.baseColour, 0.0f, 1.0f) : glm::vec3(1.0f);
    object.image = in.get<qint32>();
    const bool hasImage = object.image >= 0 && std::size_t(object.image) < scene.images.size();
    if ((object.texture == TextureKind::Image) != hasImage || (object.image < -1 || (object.image >= 0 && !hasImage)))
        throw Malformed{QStringLiteral("an object names texture %1 of %2").arg(object.image).arg(scene.images.size())};
    const float cutoff = in.get<float>(), alpha = in.get<float>();
    if (!std::isfinite(cutoff) || !std::isfinite(alpha) || cutoff < 0.0f || cutoff > 1.0f || alpha < 0.0f || alpha > 1.0f)
        throw Malformed{QStringLiteral("an object's alpha cut-off or base alpha is outside [0, 1]")};
    object.alphaCutoff = cutoff;
    object.baseAlpha = alpha;
    if (in.get<quint8>() != 0) {
        object.motion = readMotion(in, object.name);
        // Where it is at 0 is the motion's to say, whatever placement came with it.
        object.model = object.motion->at(0.0);
    }
    return object;
}

Scene readScene(Reader& in)
{
    Scene scene;
    scene.name = in.string("the scene's name");
    scene.identity = in.string("the scene's identity").toLatin1();
    if (scene.identity.size() > 128)
        throw Malformed{QStringLiteral("its identity is %1 bytes long").arg(scene.identity.size())};
    const std::size_t warnings = in.count(kMaxWarnings, 4, "warning");
    for (std::size_t i = 0; i < warnings; ++i)
        scene.warnings << in.string("a warning");
    if (in.get<quint8>() != 0) {
        const double ground = in.get<double>();
        if (!std::isfinite(ground))
            throw Malformed{QStringLiteral("the ground height is not finite")};
        scene.groundHeight = ground;
    }
    std::size_t triangles = 0;
    const std::size_t meshes = in.count(kMaxObjects, 9, "mesh");
    scene.meshes.reserve(meshes);
    for (std::size_t i = 0; i < meshes; ++i)
        scene.meshes.push_back(readMesh(in, triangles));
    const std::size_t images = in.count(kMaxWarnings, 12, "texture");
    for (std::size_t i = 0; i < images; ++i)
        scene.images.push_back(readImage(in));
    const std::size_t objects = in.count(kMaxObjects, 4 + 4 + 128 + 3 + 12 + 4 + 8 + 1, "object");
    scene.objects.reserve(objects);
    for (std::size_t i = 0; i < objects; ++i)
        scene.objects.push_back(readObject(in, scene));
    if (scene.objects.empty())
        throw Malformed{QStringLiteral("a scene with no objects")};
    // Finite numbers can still multiply to infinity: the placed bounds must be finite too.
    const Bounds bounds = scene.bounds();
    if (!std::isfinite(bounds.min.x + bounds.min.y + bounds.min.z + bounds.max.x + bounds.max.y + bounds.max.z))
        throw Malformed{QStringLiteral("its placed meshes reach beyond finite numbers")};
    return scene;
}

} // namespace

QByteArray encodeImportedScene(const Scene& scene)
{
    Writer out;
    header(out, ImportReplyKind::Scene);
    out.string(scene.name);
    out.string(QString::fromLatin1(scene.identity));
    out.put(quint32(scene.warnings.size()));
    for (const QString& warning : scene.warnings)
        out.string(warning);
    out.put(quint8(scene.groundHeight.has_value()));
    if (scene.groundHeight)
        out.put(*scene.groundHeight);
    out.put(quint32(scene.meshes.size()));
    for (const Mesh& mesh : scene.meshes) {
        out.put(quint8(mesh.convex));
        out.put(quint32(mesh.vertices.size()));
        out.put(quint32(mesh.indices.size()));
        out.raw(mesh.vertices.data(), mesh.vertices.size() * sizeof(Vertex));
        out.raw(mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
    }
    out.put(quint32(scene.images.size()));
    for (const QImage& source : scene.images) {
        const QImage image = source.convertToFormat(QImage::Format_RGBA8888);
        out.put(quint32(image.width()));
        out.put(quint32(image.height()));
        for (int y = 0; y < image.height(); ++y)
            out.raw(image.constScanLine(y), std::size_t(image.width()) * 4);
    }
    out.put(quint32(scene.objects.size()));
    for (const SceneObject& object : scene.objects) {
        out.string(object.name);
        out.put(quint32(object.mesh));
        for (int c = 0; c < 4; ++c) {
            for (int r = 0; r < 4; ++r)
                out.put(object.model[c][r]);
        }
        out.put(quint8(object.texture));
        out.put(quint8(object.castsShadow));
        out.put(quint8(object.receivesShadow));
        for (int i = 0; i < 3; ++i)
            out.put(object.baseColour[i]);
        out.put(qint32(object.image));
        out.put(object.alphaCutoff);
        out.put(object.baseAlpha);
        out.put(quint8(object.motion.has_value()));
        if (object.motion)
            putMotion(out, *object.motion);
    }
    out.raw(kTrailer, 4);
    return out.take();
}

QByteArray encodeImportRefusal(ImportReplyKind kind, const QString& message)
{
    Writer out;
    header(out, kind);
    out.string(message);
    out.raw(kTrailer, 4);
    return out.take();
}

ImportReply decodeImportReply(const QByteArray& bytes, const QString& path)
{
    try {
        Reader in(bytes);
        in.expect(kMagic, "it does not start as an import answer does");
        if (const quint32 version = in.get<quint32>(); version != kVersion)
            throw Malformed{QStringLiteral("it is version %1, not %2 (a worker of another build?)").arg(version).arg(kVersion)};
        ImportReply reply;
        const quint8 kind = in.get<quint8>();
        if (kind == quint8(ImportReplyKind::Scene)) {
            reply.kind = ImportReplyKind::Scene;
            reply.scene = readScene(in);
        } else if (kind == quint8(ImportReplyKind::Refusal) || kind == quint8(ImportReplyKind::OutOfMemory)) {
            reply.kind = ImportReplyKind(kind);
            reply.message = in.string("the refusal");
        } else {
            throw Malformed{QStringLiteral("its kind is %1").arg(kind)};
        }
        in.expect(kTrailer, "it does not end where it should");
        if (in.left() != 0)
            throw Malformed{QStringLiteral("%1 bytes follow its end").arg(in.left())};
        return reply;
    } catch (const Malformed& malformed) {
        throw SceneFileError(path, QStringLiteral("the importer sent back an answer that does not hold together (%1); nothing was "
                                                  "changed — the file is damaged or not what its name says")
                                       .arg(malformed.what));
    }
}

} // namespace shadowlab
