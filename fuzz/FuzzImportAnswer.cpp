// The import worker's answer, as the parent reads it (decodeImportReply): it comes from a process
// that has just parsed an untrusted file, so it is untrusted too. A refusal (SceneFileError) is
// the expected outcome for most inputs; a crash, a sanitizer report, an uncaught exception, a
// hang or a decoded scene that breaks its own invariants is a bug.
#include "ImportPayload.h"
#include "SceneFileError.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

using namespace shadowlab;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const QByteArray bytes = QByteArray::fromRawData(reinterpret_cast<const char*>(data), qsizetype(size));
    try {
        const ImportReply reply = decodeImportReply(bytes, QStringLiteral("fuzz.glb"));
        for (const Mesh& mesh : reply.scene.meshes) {
            for (std::uint32_t index : mesh.indices) {
                if (index >= mesh.vertices.size())
                    std::abort();
            }
            for (const Vertex& v : mesh.vertices) {
                for (int c = 0; c < 3; ++c) {
                    // Each component on its own: a sum of finite floats may overflow.
                    if (!std::isfinite(v.position[c]) || !std::isfinite(v.normal[c]) || std::abs(v.normal[c]) > 1.001f)
                        std::abort();
                }
            }
        }
        for (const SceneObject& object : reply.scene.objects) {
            if (object.mesh < 0 || std::size_t(object.mesh) >= reply.scene.meshes.size())
                std::abort();
            if (object.image >= 0 && std::size_t(object.image) >= reply.scene.images.size())
                std::abort();
        }
    } catch (const SceneFileError&) {
    }
    return 0;
}
