#pragma once

#include "CachedCopy.h"
#include "FrameStats.h"
#include "GpuScene.h"
#include "LightMath.h"
#include "Settings.h"
#include "ShaderProgram.h"
#include "UniformBlocks.h"
#include "VirtualPages.h"

#include <glm/vec2.hpp>

#include <QSize>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace shadowlab {

class ShadowMap;
class ShadowStorage;
struct FramePlan;

// What the request pass and the lit pass's VIRTUAL_MAP lookup read of a virtual map: its
// clipmap (no levels before pages were requested) and its page table.
struct VirtualMapUniforms {
    VirtualMapBlock block;
    GLuint pageTable = 0;
};

// A directional light's virtual shadow map (core/VirtualPages.h) on the GL side: the request
// pass over the camera's view, read back in the same frame and deduplicated; the page cache's
// new pages drawn into their slots of the pool (the renderer's map, through the depth storage);
// the integer page table the lit pass reads.
class VirtualShadowMap {
public:
    explicit VirtualShadowMap(GlFunctions* gl);
    ~VirtualShadowMap();

    // Bytes of the page table (the pool is the renderer's shadow map).
    std::int64_t pageTableBytes() const { return std::int64_t(kVirtualLevelPages) * kVirtualLevelPages * m_pageTableLevels * 2; }

    // Where the request pass's pixels become a set of pages: reduced on the GPU to a flag per
    // page and read back as such (virtual_reduce.vert), or read back whole and deduplicated here.
    // The same pages either way.
    enum class Reduction { Gpu, Cpu };
    // Takes the requests again on the next frame.
    void setReduction(Reduction reduction)
    {
        if (reduction == m_reduction)
            return;
        m_reduction = reduction;
        m_requestKey.reset();
    }
    Reduction reduction() const { return m_reduction; }
    // The distinct pages the last request pass asked for.
    const std::vector<VirtualPage>& requests() const { return m_requests; }
    // Asynchronous requests (the window): a request pass's pages are read back a frame later,
    // through a pixel-pack buffer and a fence, so the frame does not wait for the GPU; until
    // they arrive the lookup reads the nearest coarser resident level. The first requests of
    // an empty pool are read at once. Off (the command line, the tests): in the same frame. A
    // change asks for the pages again on the next frame.
    void setAsyncRequests(bool async)
    {
        if (async == m_async)
            return;
        m_async = async;
        m_requestKey.reset();
    }

    // Objects moved, receivers among them: the next update() asks again which pages the frame's
    // pixels need (a cache of pages keeps the pages, not the requests). With `within` (the
    // pixels where moving objects were and are, windowPixels()), only those pixels ask again
    // while the camera, the size and the layout stand: every other pixel sees what it saw.
    void askAgain(const std::optional<std::vector<QRect>>& within = std::nullopt)
    {
        if (within) {
            m_askWithin.insert(m_askWithin.end(), within->begin(), within->end());
            m_askAgainWithin = m_askAgainWithin || !within->empty();    // none: no pixel sees another thing
        } else {
            // Every pixel, on the next pass that runs (one read back later included): the
            // buffer no longer holds what its pixels see.
            m_askEverywhere = true;
            m_requestKey.reset();
            m_bufferKey.reset();
            m_stillKey.reset();
            m_askWithin.clear();
            m_askAgainWithin = false;
        }
    }
    // The pixels the last request pass drew (all of them, or those it asked again).
    qint64 requestPixels() const { return m_requestPixels; }

    // The layout for the light of `settings` over the scene (kept while both stay the same).
    const VirtualLayout& layout(const Settings& settings, const Bounds& sceneBounds);

    // The frame of `plan`: asks which pages the pixels `camera` sees at `size` need (again only when the
    // camera, the size or the layout changed), makes them resident, draws the new ones with
    // `storage` into its slots of the renderer's map, and rebuilds the page table. `invalidate`
    // (what the pages depend on changed: the light, the scene, the depth pass's state) drops
    // every cached page first. `frameOf` gives a page volume's light frame; `casterDraws` gets
    // the casters drawn. Leaves the framebuffer binding to the caller.
    VirtualMapStats update(const GpuScene& scene, const FramePlan& plan, const CameraFrame& camera, QSize size, bool invalidate,
                           ShadowStorage& storage, const std::function<LightFrame(const LightVolume&)>& frameOf, int* casterDraws);

    // shadow.cache=pages: draws again, in their slots, the resident pages the frame reads that
    // `moved` (where moving casters were and are) overlaps, except those update() drew this
    // frame, and gives up those it does not read; every other page keeps what it holds, which
    // no moved caster touches.
    // Returns the pages drawn, and gives each resident page its cause in `causes`.
    int redrawTouched(const GpuScene& scene, const FramePlan& plan, const std::vector<Bounds>& moved, ShadowStorage& storage,
                      const std::function<LightFrame(const LightVolume&)>& frameOf, int* casterDraws, std::vector<std::pair<int, ViewCause>>& causes);

    VirtualMapUniforms uniforms(const CameraFrame& camera) const;
    const VirtualPageCache& cache() const { return m_cache; }
    const std::vector<glm::ivec2>& windows() const { return m_windows; }
    const std::optional<VirtualLayout>& currentLayout() const { return m_layout; }
    // The last frame's shadow.virtual_lod_bias.
    int lodBias() const { return m_lodBias; }

private:
    // Every page dropped, for a pool of poolSide² slots.
    void resetPool(int poolSide);
    // Into the request buffer: every pixel, the still objects first (kept in m_stillRequests
    // with `keepStill`), then the moving ones. With `within`, only those pixels: the still
    // objects' requests copied back there and the moving objects drawn over them; the rest keep
    // what the buffer holds for the same camera, size and layout.
    int drawRequests(const GpuScene& scene, const CameraFrame& camera, QSize size, const std::vector<QRect>* within, bool keepStill);
    struct RequestKey;
    // The request pass where the pages must be asked for again (everywhere, or where objects
    // moved), its requests read back now or a read-back started: whether requests arrived
    // this frame. `requestDraws` gets the pass's draws.
    bool askForPages(const GpuScene& scene, const FramePlan& plan, const CameraFrame& camera, const RequestKey& key, int& requestDraws);
    // The request pass's result as bytes: a flag a page (reduced on the GPU) or a word a pixel.
    struct RequestBytes {
        bool flags = false;
        std::size_t bytes = 0;
    };
    void reducePass(QSize size);
    std::size_t requestBytes(QSize size) const;
    // Into client memory `into`, or the bound pixel-pack buffer with nullptr.
    RequestBytes readRequestBytes(QSize size, void* into);
    static std::vector<VirtualPage> decodeRequests(const RequestBytes& bytes, const void* data, const std::vector<glm::ivec2>& windows);
    // With `within` (the pixels the last pass drew, under the CPU reduction of a buffer read
    // whole before): only those pixels read back, and the pages from a count per page of the
    // pixels asking for it.
    std::vector<VirtualPage> readRequests(QSize size, const std::vector<QRect>* within = nullptr);
    std::vector<VirtualPage> readRequestsWithin(QSize size, const std::vector<QRect>& within);
    void startReadback(QSize size, const RequestKey& key);
    // Takes the pending read-back's pages if it has arrived (or, with `wait`, once it has).
    bool collectReadback(bool wait);
    void allocateTargets(QSize size);
    void uploadPageTable();

    GlFunctions* m_gl;
    std::unique_ptr<ShaderProgram> m_program;
    GLint m_model = -1, m_normalMatrix = -1, m_mvp = -1, m_receives = -1;
    UniformBuffer<VirtualMapBlock> m_block;
    GlTexture m_requestTexture;
    GlTexture m_requestDepth;
    GlFramebuffer m_requestFramebuffer;
    QSize m_requestSize;
    std::vector<std::uint32_t> m_readback;  // a synchronous read-back: request words, or page flags four to a word
    bool m_mirrored = false;                // m_readback holds every word the request buffer holds
    std::vector<std::uint32_t> m_pageCounts;    // readRequestsWithin(): pixels asking for each page (empty: not counted)
    Reduction m_reduction = Reduction::Gpu;
    std::unique_ptr<ShaderProgram> m_reduceProgram;
    GLint m_reduceWidth = -1, m_reduceLevels = -1, m_reduceRequests = -1;
    GlVertexArray m_pointArray;         // core profile draws need one; the points have no attributes
    GlTexture m_flagTexture;            // R8UI, 128 x 128 * levels: a flag per page of every window
    GlFramebuffer m_flagFramebuffer;
    int m_flagLevels = 0;
    GlTexture m_pageTable;
    int m_pageTableLevels = 0;

    struct LayoutKey {
        LightSettings light;
        Bounds bounds;
        int levels = 0;
        bool operator==(const LayoutKey& o) const
        {
            return light == o.light && bounds.min == o.bounds.min && bounds.max == o.bounds.max && levels == o.levels;
        }
    };
    std::optional<LayoutKey> m_layoutKey;
    std::optional<VirtualLayout> m_layout;
    std::vector<glm::ivec2> m_windows;
    int m_layoutGeneration = 0;
    int m_cacheLayoutGeneration = -1;   // the layout the cached pages were drawn with
    glm::dmat4 m_depthMatrix{1.0};      // the coarsest window's depthShadowMatrix: every page's depth
    VirtualPageCache m_cache;
    int m_poolSide = 0;
    int m_lodBias = 0;
    bool m_tableDirty = true;
    // What the last requests were taken for: while it stays, they stand.
    struct RequestKey {
        glm::dmat4 viewProjection{1.0};
        glm::dvec3 position{0.0};
        QSize size;
        int layoutGeneration = 0;
        int lodBias = 0;
        bool operator==(const RequestKey&) const = default;
    };
    std::optional<RequestKey> m_requestKey;
    std::optional<RequestKey> m_bufferKey;      // what the request buffer holds, every pixel of it
    CachedCopy m_stillRequests;                 // shadow.cache=pages: the still objects' requests and depths
    std::optional<RequestKey> m_stillKey;       // ... for what
    std::vector<QRect> m_askWithin;             // askAgain()'s pixels since the last request pass
    bool m_askAgainWithin = false;
    bool m_askEverywhere = false;               // askAgain() without pixels, until a pass runs
    qint64 m_requestPixels = 0;
    std::vector<VirtualPage> m_requests;
    bool m_async = false;
    GlBuffer m_pixelPack;
    GLsync m_fence = nullptr;           // the pending read-back's, null when none is pending
    RequestBytes m_pendingBytes;
    RequestKey m_pendingKey;
    std::vector<glm::ivec2> m_pendingWindows;
    VirtualMapStats m_lastStats;        // what the last frame that placed pages found
    std::vector<int> m_drawnSlots;      // the slots update() drew this frame
};

} // namespace shadowlab
