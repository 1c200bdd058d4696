#include "ModelImporter.h"

#include "Limits.h"
#include "ModelFileChecks.h"
#include "NodeAnimation.h"
#include "SceneFileError.h"

#include <assimp/DefaultIOSystem.h>
#include <assimp/GltfMaterial.h>
#include <assimp/Importer.hpp>
#include <assimp/ProgressHandler.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <set>

namespace shadowlab {

namespace {

constexpr int kMaxNodeDepth = 256;   // deeper trees are cycles or generated nonsense

// Remembers every file Assimp opens (the model, a glTF's .bin, an OBJ's .mtl) so the scene's
// identity covers them all.
class RecordingIoSystem : public Assimp::DefaultIOSystem {
public:
    Assimp::IOStream* Open(const char* file, const char* mode) override
    {
        Assimp::IOStream* stream = DefaultIOSystem::Open(file, mode);
        if (stream)
            opened.insert(QFileInfo(QString::fromUtf8(file)).absoluteFilePath());
        return stream;
    }
    std::set<QString> opened;
};

bool isFinite(const aiVector3D& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Splits `mesh` into pieces of at most kMeshChunkTriangles triangles by recursive median
// splits of the triangle centroids along the longest axis: each piece is compact in space.
void splitMesh(const Mesh& mesh, std::vector<Mesh>& pieces)
{
    const std::size_t triangles = mesh.indices.size() / 3;
    if (triangles <= kMeshChunkTriangles) {
        pieces.push_back(mesh);
        return;
    }
    std::vector<glm::vec3> centroid(triangles);
    for (std::size_t t = 0; t < triangles; ++t) {
        centroid[t] = (mesh.vertices[mesh.indices[3 * t]].position + mesh.vertices[mesh.indices[3 * t + 1]].position
                       + mesh.vertices[mesh.indices[3 * t + 2]].position) / 3.0f;
    }
    std::vector<std::uint32_t> order(triangles);
    std::iota(order.begin(), order.end(), 0u);
    std::vector<std::uint32_t> remap(mesh.vertices.size(), UINT32_MAX);

    const auto addPiece = [&](std::size_t begin, std::size_t end) {
        Mesh piece;
        piece.indices.reserve((end - begin) * 3);
        for (std::size_t i = begin; i < end; ++i) {
            for (int corner = 0; corner < 3; ++corner) {
                const std::uint32_t old = mesh.indices[3 * order[i] + std::size_t(corner)];
                if (remap[old] == UINT32_MAX) {
                    remap[old] = std::uint32_t(piece.vertices.size());
                    piece.vertices.push_back(mesh.vertices[old]);
                }
                piece.indices.push_back(remap[old]);
            }
        }
        for (std::size_t i = begin; i < end; ++i) {
            for (int corner = 0; corner < 3; ++corner)
                remap[mesh.indices[3 * order[i] + std::size_t(corner)]] = UINT32_MAX;
        }
        pieces.push_back(std::move(piece));
    };
    const auto split = [&](auto& self, std::size_t begin, std::size_t end) -> void {
        if (end - begin <= kMeshChunkTriangles) {
            addPiece(begin, end);
            return;
        }
        glm::vec3 lo(INFINITY), hi(-INFINITY);
        for (std::size_t i = begin; i < end; ++i) {
            lo = glm::min(lo, centroid[order[i]]);
            hi = glm::max(hi, centroid[order[i]]);
        }
        const glm::vec3 extent = hi - lo;
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        const std::size_t middle = begin + (end - begin) / 2;
        std::nth_element(order.begin() + std::ptrdiff_t(begin), order.begin() + std::ptrdiff_t(middle), order.begin() + std::ptrdiff_t(end),
                         [&](std::uint32_t a, std::uint32_t b) { return centroid[a][axis] < centroid[b][axis]; });
        self(self, begin, middle);
        self(self, middle, end);
    };
    split(split, 0, triangles);
}

struct Importing {
    QString path;
    const aiScene* ai = nullptr;
    Scene scene;
    std::vector<std::vector<int>> piecesOfMesh;     // Assimp mesh -> our meshes
    std::map<unsigned, int> imageOfMaterial;        // -1: no usable texture
    std::set<QString> extraFiles;                   // textures read, for the identity
    std::set<QString> ignored;                      // material properties not drawn
    NodeAnimation animation;                        // the file's first animation
    QStringList stillNodes;                         // animated, but with numbers that do not hold together
    QString stillProblem;                           // what is wrong with the first of them
    bool resampled = false;                         // an animation with more key times than kMaxMotionKeys
};

QString texturePath(const aiMaterial* material, aiTextureType& type)
{
    for (aiTextureType t : {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE}) {
        aiString path;
        if (material->GetTextureCount(t) > 0 && material->GetTexture(t, 0, &path) == AI_SUCCESS && path.length > 0) {
            type = t;
            return QString::fromUtf8(path.C_Str());
        }
    }
    return QString();
}

// The material's base-colour texture as an index into scene.images, or -1 (with a warning
// when it names a texture that cannot be read).
int loadImage(Importing& in, const aiMaterial* material)
{
    aiTextureType type = aiTextureType_NONE;
    const QString name = texturePath(material, type);
    if (name.isEmpty())
        return -1;
    QImage image;
    if (const aiTexture* embedded = in.ai->GetEmbeddedTexture(name.toUtf8().constData())) {
        if (embedded->mHeight == 0) {
            image.loadFromData(reinterpret_cast<const uchar*>(embedded->pcData), int(embedded->mWidth));
        } else {
            image = QImage(int(embedded->mWidth), int(embedded->mHeight), QImage::Format_ARGB32);
            for (unsigned y = 0; y < embedded->mHeight; ++y) {
                for (unsigned x = 0; x < embedded->mWidth; ++x) {
                    const aiTexel& t = embedded->pcData[y * embedded->mWidth + x];
                    image.setPixel(int(x), int(y), qRgba(t.r, t.g, t.b, t.a));
                }
            }
        }
    } else {
        const QString file = QFileInfo(QFileInfo(in.path).dir(), QString(name).replace(QLatin1Char('\\'), QLatin1Char('/'))).absoluteFilePath();
        if (image.load(file))
            in.extraFiles.insert(file);
    }
    if (image.isNull()) {
        aiString materialName;
        material->Get(AI_MATKEY_NAME, materialName);
        in.scene.warnings << QStringLiteral("texture '%1' of material '%2' cannot be read (missing, or not an image Qt reads; TGA, TIFF and WebP "
                                            "need the package qt6-image-formats-plugins); drawing its base colour instead — put the "
                                            "texture next to the model")
                                 .arg(name, QString::fromUtf8(materialName.C_Str()));
        return -1;
    }
    if (image.width() > kMaxImageSide || image.height() > kMaxImageSide) {
        in.scene.warnings << QStringLiteral("texture '%1' is %2 × %3 texels; drawn at most %4 texels wide")
                                 .arg(name).arg(image.width()).arg(image.height()).arg(kMaxImageSide);
        image = image.scaled(std::min(image.width(), kMaxImageSide), std::min(image.height(), kMaxImageSide), Qt::KeepAspectRatio,
                             Qt::SmoothTransformation);
    }
    in.scene.images.push_back(image.convertToFormat(QImage::Format_RGBA8888));
    return int(in.scene.images.size() - 1);
}

// glTF's alphaMode: MASK cuts the surface where the base-colour alpha is below alphaCutoff
// (0.5 unless given); BLEND, which ShadowLab does not composite, is drawn and cast as MASK at 0.5,
// said once per material. Sets the object's cut-off and base alpha; true for MASK and BLEND.
bool readAlphaMode(Importing& in, const aiMaterial* material, float baseAlpha, bool firstUse, SceneObject& object)
{
    aiString mode;
    if (material->Get(AI_MATKEY_GLTF_ALPHAMODE, mode) != AI_SUCCESS)
        return false;
    const QString name = QString::fromUtf8(mode.C_Str());
    if (name != QLatin1String("MASK") && name != QLatin1String("BLEND"))
        return false;
    float cutoff = 0.5f;
    if (name == QLatin1String("MASK"))
        material->Get(AI_MATKEY_GLTF_ALPHACUTOFF, cutoff);
    if (!std::isfinite(cutoff))
        cutoff = 0.5f;
    if (name == QLatin1String("BLEND")) {
        cutoff = 0.5f;
        if (firstUse) {
            aiString materialName;
            material->Get(AI_MATKEY_NAME, materialName);
            in.scene.warnings << QStringLiteral("material '%1' blends (alphaMode BLEND); drawn and cast as a cut-out at alpha 0.5, "
                                                "with no translucent colour")
                                     .arg(QString::fromUtf8(materialName.C_Str()));
        }
    }
    // glTF keeps a texel whose alpha is at least the cut-off: one of 0 or less keeps every texel,
    // which is opaque.
    object.alphaCutoff = std::clamp(cutoff, 0.0f, 1.0f);
    object.baseAlpha = std::isfinite(baseAlpha) ? std::clamp(baseAlpha, 0.0f, 1.0f) : 1.0f;
    return true;
}

void noteIgnoredProperties(Importing& in, const aiMaterial* material, bool cutout)
{
    const std::pair<aiTextureType, const char*> kinds[] = {
        {aiTextureType_NORMALS, "normal maps"},       {aiTextureType_HEIGHT, "height maps"},
        {aiTextureType_SPECULAR, "specular maps"},    {aiTextureType_EMISSIVE, "emission"},
        {aiTextureType_METALNESS, "metalness"},       {aiTextureType_DIFFUSE_ROUGHNESS, "roughness"},
        {aiTextureType_AMBIENT_OCCLUSION, "occlusion"}, {aiTextureType_LIGHTMAP, "occlusion"},
        {aiTextureType_OPACITY, "transparency"},      {aiTextureType_UNKNOWN, "metallic-roughness"}};
    for (const auto& [type, label] : kinds) {
        if (material->GetTextureCount(type) > 0)
            in.ignored.insert(QString::fromLatin1(label));
    }
    float opacity = 1.0f;
    if (!cutout && material->Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS && opacity < 1.0f)
        in.ignored.insert(QStringLiteral("transparency"));
}

void convertMeshes(Importing& in)
{
    std::size_t triangles = 0;
    for (unsigned m = 0; m < in.ai->mNumMeshes; ++m) {
        if (in.ai->mMeshes[m]->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)
            triangles += in.ai->mMeshes[m]->mNumFaces;
    }
    if (triangles == 0)
        throw SceneFileError(in.path, QStringLiteral("has no triangles (only points or lines, or nothing at all); export surfaces, not a point cloud or curves"));
    if (triangles > kMaxModelTriangles)
        throw SceneFileError(in.path, QStringLiteral("has %1 triangles, more than the %2 ShadowLab loads; decimate it first")
                                          .arg(triangles).arg(kMaxModelTriangles));

    for (unsigned m = 0; m < in.ai->mNumMeshes; ++m) {
        const aiMesh* source = in.ai->mMeshes[m];
        in.piecesOfMesh.emplace_back();
        if (!(source->mPrimitiveTypes & aiPrimitiveType_TRIANGLE))
            continue;
        Mesh mesh;
        mesh.vertices.resize(source->mNumVertices);
        std::size_t bad = 0;
        for (unsigned v = 0; v < source->mNumVertices; ++v) {
            Vertex& out = mesh.vertices[v];
            const aiVector3D& p = source->mVertices[v];
            if (!isFinite(p))
                ++bad;
            out.position = {p.x, p.y, p.z};
            glm::vec3 n(0.0f, 1.0f, 0.0f);
            if (source->mNormals && isFinite(source->mNormals[v])) {
                const glm::vec3 candidate(source->mNormals[v].x, source->mNormals[v].y, source->mNormals[v].z);
                if (glm::length(candidate) > 1e-12f)
                    n = glm::normalize(candidate);
            }
            out.normal = n;
            out.uv = source->mTextureCoords[0] ? glm::vec2(source->mTextureCoords[0][v].x, source->mTextureCoords[0][v].y) : glm::vec2(0.0f);
        }
        if (bad > 0)
            throw SceneFileError(in.path, QStringLiteral("mesh '%1' has %2 vertex positions that are not finite numbers (NaN or infinity); "
                                                         "repair or export the mesh again")
                                              .arg(QString::fromUtf8(source->mName.C_Str()))
                                              .arg(bad));
        mesh.indices.reserve(std::size_t(source->mNumFaces) * 3);
        for (unsigned f = 0; f < source->mNumFaces; ++f) {
            const aiFace& face = source->mFaces[f];
            if (face.mNumIndices != 3)
                continue;   // points and lines left in a mixed mesh
            for (int c = 0; c < 3; ++c) {
                if (face.mIndices[c] >= source->mNumVertices)
                    throw SceneFileError(in.path, QStringLiteral("mesh '%1' indexes a vertex that does not exist; the file is damaged")
                                                      .arg(QString::fromUtf8(source->mName.C_Str())));
                mesh.indices.push_back(face.mIndices[c]);
            }
        }
        if (mesh.indices.empty())
            continue;   // nothing but points and lines after all
        std::vector<Mesh> pieces;
        splitMesh(mesh, pieces);
        for (Mesh& piece : pieces) {
            in.scene.meshes.push_back(std::move(piece));
            in.piecesOfMesh.back().push_back(int(in.scene.meshes.size() - 1));
        }
    }
}

// Where the objects of an animated node sit at time 0 and how they move (`object`'s model and
// motion): a path through the node's placements over the clip. Nothing is applied above the
// root node (checkPlacedSize() scales afterwards, `pre` included), so pre and post are the
// identity: the mesh is in node space. A node the animation holds still gets no motion, only
// its pose; one whose keys do not hold together stays where its node puts it.
void animate(Importing& in, const aiNode* node, const NodePose& pose, SceneObject& object)
{
    in.resampled = in.resampled || pose.resampled;
    const Motion motion = in.animation.motionOf(pose);
    if (const QString problem = motionProblem(motion); !problem.isEmpty()) {
        if (in.stillNodes.isEmpty())
            in.stillProblem = problem;
        in.stillNodes << QString::fromUtf8(node->mName.C_Str());
        return;
    }
    object.model = motion.at(0.0);
    if (!holdsStill(pose))
        object.motion = motion;
}

void addNode(Importing& in, const aiNode* node, const glm::dmat4& parent, const NodePose* parentPose, int depth)
{
    if (depth > kMaxNodeDepth)
        throw SceneFileError(in.path, QStringLiteral("its node tree is deeper than %1 levels (a cycle?); flatten the hierarchy").arg(kMaxNodeDepth));
    const glm::dmat4 world = parent * toGlm(node->mTransformation);
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(world[c][r]))
                throw SceneFileError(in.path, QStringLiteral("node '%1' has a transform that is not finite numbers (NaN or infinity); repair the hierarchy")
                                                  .arg(QString::fromUtf8(node->mName.C_Str())));
        }
    }
    const std::optional<NodePose> pose = in.animation.poseOf(node, parentPose);
    SceneObject placed;     // what every mesh of the node shares
    placed.name = QString::fromUtf8(node->mName.C_Str());
    placed.model = world;
    placed.texture = TextureKind::Flat;
    if (pose && node->mNumMeshes > 0)
        animate(in, node, *pose, placed);
    for (unsigned i = 0; i < node->mNumMeshes; ++i) {
        const unsigned m = node->mMeshes[i];
        if (m >= in.ai->mNumMeshes)
            continue;
        const unsigned materialIndex = in.ai->mMeshes[m]->mMaterialIndex;
        SceneObject object = placed;
        if (materialIndex < in.ai->mNumMaterials) {
            const aiMaterial* material = in.ai->mMaterials[materialIndex];
            aiColor4D colour(1.0f, 1.0f, 1.0f, 1.0f);
            if (aiGetMaterialColor(material, AI_MATKEY_BASE_COLOR, &colour) != AI_SUCCESS)
                aiGetMaterialColor(material, AI_MATKEY_COLOR_DIFFUSE, &colour);
            object.baseColour = glm::clamp(glm::vec3(colour.r, colour.g, colour.b), glm::vec3(0.0f), glm::vec3(1.0f));
            auto found = in.imageOfMaterial.find(materialIndex);
            const bool firstUse = found == in.imageOfMaterial.end();
            if (firstUse)
                found = in.imageOfMaterial.emplace(materialIndex, loadImage(in, material)).first;
            const bool cutout = readAlphaMode(in, material, colour.a, firstUse, object);
            if (firstUse)
                noteIgnoredProperties(in, material, cutout);
            if (found->second >= 0) {
                object.texture = TextureKind::Image;
                object.image = found->second;
            }
        }
        for (int piece : in.piecesOfMesh.at(m)) {
            object.mesh = piece;
            in.scene.objects.push_back(object);
        }
    }
    for (unsigned c = 0; c < node->mNumChildren; ++c)
        addNode(in, node->mChildren[c], world, pose ? &*pose : nullptr, depth + 1);
}

// What of the file's animations and skins is not played, said before the objects are placed.
void noteAnimation(Importing& in)
{
    const aiScene* ai = in.ai;
    const auto named = [](const aiAnimation* animation) {
        return animation->mName.length > 0 ? QStringLiteral("'%1'").arg(QString::fromUtf8(animation->mName.C_Str())) : QStringLiteral("(unnamed)");
    };
    if (ai->mNumAnimations > 1) {
        in.scene.warnings << QStringLiteral("the file has %1 animations; only the first, %2, plays — export the one you want first")
                                 .arg(ai->mNumAnimations).arg(named(ai->mAnimations[0]));
    }
    if (ai->mNumAnimations > 0 && (ai->mAnimations[0]->mNumMorphMeshChannels > 0 || ai->mAnimations[0]->mNumMeshChannels > 0)) {
        in.scene.warnings << QStringLiteral("animation %1 changes mesh shapes (morph targets or vertex animation), which ShadowLab does "
                                            "not play; the meshes are drawn in their base shape").arg(named(ai->mAnimations[0]));
    }
    std::size_t skinned = 0;
    for (unsigned m = 0; m < ai->mNumMeshes; ++m) {
        if (ai->mMeshes[m]->mNumBones > 0 && !in.piecesOfMesh.at(m).empty())
            ++skinned;
    }
    if (skinned > 0) {
        in.scene.warnings << QStringLiteral("%1 of %2 meshes are skinned (deformed by bones); ShadowLab moves whole nodes but does not "
                                            "deform skins yet, so they are drawn in their bind pose")
                                 .arg(skinned).arg(ai->mNumMeshes);
    }
}

// What of the animation could not be played, said once after the objects are placed.
void noteUnplayedKeys(Importing& in)
{
    if (in.resampled) {
        in.scene.warnings << QStringLiteral("the animation has more than %1 key times on a node; it is taken at %1 even times instead, "
                                            "so the motion between them may be smoothed").arg(kMaxMotionKeys);
    }
    if (!in.stillNodes.isEmpty()) {
        in.stillNodes.removeDuplicates();
        const QString nodes = in.stillNodes.size() == 1 ? QStringLiteral("node '%1' is").arg(in.stillNodes.first())
                                                        : QStringLiteral("%1 nodes ('%2' first) are").arg(in.stillNodes.size()).arg(in.stillNodes.first());
        in.scene.warnings << QStringLiteral("%1 animated with keys that do not hold together (%2); drawn still where the file places "
                                            "them — export the animation again").arg(nodes, in.stillProblem);
    }
}

QString scaledWarning(double size, double factor)
{
    return QStringLiteral("the model is %1 units across, outside [%2, %3]; scaled by %4 to %5 units")
        .arg(size, 0, 'g', 3)
        .arg(kMinModelSize)
        .arg(kMaxModelSize)
        .arg(factor, 0, 'g', 3)
        .arg(kNormalisedModelSize);
}

// Scales every vertex of `scene` (as read, before node transforms) about the origin when the
// meshes' bounding box lies outside [kMinModelSize, kMaxModelSize]. Non-finite positions are
// left for the check after conversion, which names them.
void normaliseVertices(aiScene* scene, QStringList& warnings)
{
    Bounds bounds;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh* mesh = scene->mMeshes[m];
        for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
            if (isFinite(mesh->mVertices[v]))
                bounds.extend(glm::dvec3(mesh->mVertices[v].x, mesh->mVertices[v].y, mesh->mVertices[v].z));
        }
    }
    const double size = bounds.isEmpty() ? 0.0 : glm::length(bounds.max - bounds.min);
    if (size <= 0.0 || !std::isfinite(size) || (size >= kMinModelSize && size <= kMaxModelSize))
        return;
    const double factor = kNormalisedModelSize / size;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        aiMesh* mesh = scene->mMeshes[m];
        for (unsigned v = 0; v < mesh->mNumVertices; ++v)
            mesh->mVertices[v] = aiVector3D(ai_real(mesh->mVertices[v].x * factor), ai_real(mesh->mVertices[v].y * factor),
                                            ai_real(mesh->mVertices[v].z * factor));
    }
    warnings << scaledWarning(size, factor);
}

// Assimp's progress (0..1 through reading and post-processing) to a callback.
class ProgressForwarder : public Assimp::ProgressHandler {
public:
    explicit ProgressForwarder(std::function<void(double)> progress) : m_progress(std::move(progress)) {}
    bool Update(float percentage) override
    {
        if (percentage >= 0.0f && std::isfinite(percentage))
            m_progress(std::clamp(double(percentage), 0.0, 1.0));
        return true;
    }

private:
    std::function<void(double)> m_progress;
};

QByteArray hashFiles(const std::set<QString>& files)
{
    QCryptographicHash hash(QCryptographicHash::Sha256);
    for (const QString& path : files) {
        QFile file(path);
        if (file.open(QIODevice::ReadOnly))
            hash.addData(&file);
    }
    return hash.result().toHex();
}

// Assimp's reason for not reading `path`, as a refusal that says what to do.
[[noreturn]] void refuseUnread(const QString& path, const QString& suffix, const Assimp::Importer& importer)
{
    const QString reason = QString::fromUtf8(importer.GetErrorString()).trimmed();
    if (reason.contains(QStringLiteral("no faces")))
        throw SceneFileError(path, QStringLiteral("has no triangles (%1); export surfaces, not a point cloud or curves").arg(reason));
    // Every mesh was points or lines, which are dropped (see readModel).
    if (reason.contains(QStringLiteral("No meshes remaining")))
        throw SceneFileError(path, QStringLiteral("has no triangles, only points or lines; export surfaces, not a point cloud or curves"));
    // The suffix is known, the contents are not: another version or variant of the format.
    if (reason.contains(QStringLiteral("No suitable reader")))
        throw SceneFileError(path, QStringLiteral("is a version or variant of .%1 that cannot be read (glTF 1 binaries, for one); export "
                                                  "it again as glTF 2 (.glb) or OBJ").arg(suffix));
    throw SceneFileError(path, QStringLiteral("cannot be read: %1; the file is damaged, truncated or not what its name says — "
                                              "open it in another tool or export it again (glTF 2 .glb is the safest choice)")
                                   .arg(reason));
}

// Reads the file, brings absurd sizes into range, then post-processes: Assimp's vertex
// welding and normal generation use tolerances that merge a 10^-6 model's vertices.
const aiScene* readModel(Assimp::Importer& importer, const QString& path, const QFileInfo& info, const QString& suffix, QStringList& warnings)
{
    // Points and lines are dropped: they cast no shadow and have no normal.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    importer.SetPropertyFloat(AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, 60.0f);
    const unsigned flags = aiProcess_Triangulate | aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType
                           | aiProcess_ValidateDataStructure | aiProcess_FlipUVs;
    if (!importer.ReadFile(info.absoluteFilePath().toStdString(), 0))
        refuseUnread(path, suffix, importer);
    normaliseVertices(const_cast<aiScene*>(importer.GetScene()), warnings);
    const aiScene* ai = importer.ApplyPostProcessing(flags);
    if (!ai)
        refuseUnread(path, suffix, importer);
    if ((ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !ai->mRootNode)
        throw SceneFileError(path, QStringLiteral("has no complete scene (no triangles, or parts missing); export surfaces again"));
    return ai;
}

// The scene as placed by its nodes: refused when it has no size, scaled when its size is absurd.
void checkPlacedSize(Importing& in)
{
    const Bounds bounds = in.scene.bounds();
    const double size = glm::length(bounds.max - bounds.min);
    if (!std::isfinite(size))
        throw SceneFileError(in.path, QStringLiteral("has node transforms that are not finite numbers; repair the hierarchy"));
    if (size <= 0.0)
        throw SceneFileError(in.path, QStringLiteral("has all its vertices at one point; there is nothing to shadow"));
    if (size < kMinModelSize || size > kMaxModelSize) {
        const double factor = kNormalisedModelSize / size;
        const glm::dmat4 scale = glm::scale(glm::dmat4(1.0), glm::dvec3(factor));
        for (SceneObject& object : in.scene.objects) {
            if (object.motion) {
                object.motion->pre = scale * object.motion->pre;
                object.model = object.motion->at(0.0);
            } else {
                object.model = scale * object.model;
            }
        }
        in.scene.warnings << scaledWarning(size, factor);
    }
}

} // namespace

QStringList modelSuffixes()
{
    Assimp::Importer importer;
    std::string list;
    importer.GetExtensionList(list);   // "*.3ds;*.obj;..."
    QStringList suffixes;
    for (const QString& part : QString::fromStdString(list).split(QLatin1Char(';'), Qt::SkipEmptyParts))
        suffixes << part.mid(2).toLower();
    return suffixes;
}

Scene importModel(const QString& path, const std::function<void(double)>& progress)
{
    const QFileInfo info(path);
    const QString suffix = checkModelFile(path, info);
    Assimp::Importer importer;
    auto* io = new RecordingIoSystem;   // owned by the importer
    importer.SetIOHandler(io);
    if (progress)
        importer.SetProgressHandler(new ProgressForwarder(progress));   // owned by the importer
    QStringList warnings;
    const aiScene* ai = readModel(importer, path, info, suffix, warnings);

    Importing in;
    in.path = path;
    in.ai = ai;
    in.scene.name = info.absoluteFilePath();
    in.scene.warnings = warnings;
    convertMeshes(in);
    in.animation = NodeAnimation(ai);
    noteAnimation(in);
    addNode(in, ai->mRootNode, glm::dmat4(1.0), nullptr, 0);
    noteUnplayedKeys(in);
    if (in.scene.objects.empty())
        throw SceneFileError(path, QStringLiteral("places no triangle mesh in its scene; export the meshes as part of the scene"));
    checkPlacedSize(in);
    if (!in.ignored.empty()) {
        in.scene.warnings << QStringLiteral("materials: only the base colour and base-colour texture are drawn; ignored: %1")
                                 .arg(QStringList(in.ignored.begin(), in.ignored.end()).join(QStringLiteral(", ")));
    }
    std::set<QString> files = io->opened;
    files.insert(info.absoluteFilePath());
    files.insert(in.extraFiles.begin(), in.extraFiles.end());
    in.scene.identity = hashFiles(files);
    return std::move(in.scene);
}

} // namespace shadowlab
