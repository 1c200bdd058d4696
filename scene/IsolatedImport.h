#pragma once

#include "ImportLimits.h"
#include "Scene.h"
#include "SceneFileError.h"

#include <atomic>
#include <functional>
#include <optional>

namespace shadowlab {

// How one import runs: its limits, a way to stop it, and where its progress goes. The
// callbacks run on the calling thread.
struct ImportControl {
    ImportLimits limits = importLimits();
    const std::atomic<bool>* cancel = nullptr;      // set it to stop the worker at once
    std::function<void(double fraction)> progress;  // 0..1 while the worker reads
    QString workerProgram;                          // empty: importWorkerProgram()
};

// The import was stopped by ImportControl::cancel; nothing was changed.
class ImportCancelled : public SceneFileError {
public:
    explicit ImportCancelled(const QString& path)
        : SceneFileError(path, QStringLiteral("opening it was cancelled; nothing was changed")) {}
};

// Reads a model file the way importModel() does, in a separate process: Assimp is a large
// parser of untrusted bytes, and a crash, a hang or a runaway allocation in it must end as a
// refusal, not take the program down. The worker (`shadowlab-import-worker`) runs under the
// limits, with no standard input, a minimal environment, no core dumps, no files written and a
// death signal tied to its parent; what it sends back is checked again (ImportPayload.h).
// Throws SceneFileError naming the file and what happened: refused, crashed (with the signal),
// over a limit, an answer that does not hold together, or no answer; ImportCancelled when
// cancelled.
Scene importModelIsolated(const QString& path, const ImportControl& control = {});

// The faces a file's header states, where its format states them (PLY's "element face", OFF's
// counts line, a binary STL's count where the file's size agrees); nullopt otherwise. Read
// before the worker starts, so a file far over kMaxModelTriangles is refused at once.
std::optional<std::size_t> statedFaceCount(const QString& path);

// The worker's path: $SHADOWLAB_IMPORT_WORKER, else next to the running program or in
// ../libexec/shadowlab from it (installed), else, for a program in the build tree, where this
// build put it. Empty when none is there.
QString importWorkerProgram();

} // namespace shadowlab
