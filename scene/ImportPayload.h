#pragma once

#include "Scene.h"

#include <QByteArray>
#include <QString>

namespace shadowlab {

// The import worker's answer on its standard output: a scene, or a refusal with the reason.
// Little-endian, length-prefixed, with a magic and a trailer:
//
//   "SLIMPORT" u32 version  u8 kind   (1 scene, 2 refusal, 3 out of memory)
//   refusal:  string message
//   scene:    string name, string identity, u32 n × string warning, u8 has-ground [f64 height]
//             u32 meshes   × { u8 convex, u32 vertices, u32 indices, vertices × 8 f32, indices × u32 }
//             u32 images   × { u32 width, u32 height, width × height × RGBA8 }
//             u32 objects  × { string name, u32 mesh, 16 f64 (column-major), u8 texture,
//                              u8 casts, u8 receives, 3 f32 colour, i32 image,
//                              f32 alpha cut-off, f32 base alpha, u8 moves [motion] }
//   motion:   u8 kind, u8 smooth, f64 period, f64 start, f64 amplitude, 3 f64 point, 3 f64 axis,
//             16 f64 pre, 16 f64 post (column-major),
//             u32 keys × { f64 time, 3 f64 position, 4 f64 rotation (w x y z), 3 f64 scale }
//   "END."
enum class ImportReplyKind : quint8 { Scene = 1, Refusal = 2, OutOfMemory = 3 };

QByteArray encodeImportedScene(const Scene& scene);
QByteArray encodeImportRefusal(ImportReplyKind kind, const QString& message);

struct ImportReply {
    ImportReplyKind kind = ImportReplyKind::Refusal;
    Scene scene;            // when kind is Scene
    QString message;        // otherwise
};

// Reads an answer that came from another process, so nothing in it is trusted: every count is
// checked against the bytes left before anything is allocated, indices against their vertices,
// numbers for being finite, references between meshes, objects and images for range, and
// motions as a scene file's are (motionProblem(), at most kMaxMotionKeys keys); a moving
// object's placement is its motion's at time 0.
// Throws SceneFileError naming `path` and what did not hold together.
ImportReply decodeImportReply(const QByteArray& bytes, const QString& path);

} // namespace shadowlab
