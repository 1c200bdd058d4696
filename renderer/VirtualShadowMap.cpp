#include "VirtualShadowMap.h"

#include "CasterTexels.h"
#include "PassState.h"
#include "ShadowCache.h"
#include "RenderError.h"
#include "ShadowStorage.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowlab {

VirtualShadowMap::VirtualShadowMap(GlFunctions* gl) : m_gl(gl), m_block(gl), m_stillRequests(gl) {}

VirtualShadowMap::~VirtualShadowMap()
{
    if (m_fence)
        m_gl->glDeleteSync(m_fence);
}

const VirtualLayout& VirtualShadowMap::layout(const Settings& settings, const Bounds& sceneBounds)
{
    const LayoutKey key{settings.light, sceneBounds, settings.shadow.virtualLevels};
    if (!m_layoutKey || !(*m_layoutKey == key)) {
        m_layout = virtualLayout(settings.light, sceneBounds, settings.shadow.virtualLevels);
        m_layoutKey = key;
        ++m_layoutGeneration;
    }
    return *m_layout;
}

void VirtualShadowMap::allocateTargets(QSize size)
{
    m_bufferKey.reset();
    m_mirrored = false;
    m_requestFramebuffer.reset();
    m_gl->glActiveTexture(GL_TEXTURE0);
    m_requestTexture = makeTexture(m_gl);
    m_gl->glBindTexture(GL_TEXTURE_2D, m_requestTexture.id());
    m_gl->glTexImage2D(GL_TEXTURE_2D, 0, GL_R32UI, size.width(), size.height(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    m_requestDepth = makeTexture(m_gl);
    m_gl->glBindTexture(GL_TEXTURE_2D, m_requestDepth.id());
    m_gl->glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size.width(), size.height(), 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    const QString dimensions = QStringLiteral("%1 x %2").arg(size.width()).arg(size.height());
    labelGlObject(GlLabelKind::Texture, m_requestTexture.id(), QStringLiteral("virtual shadow map page requests, ") + dimensions);
    m_requestFramebuffer = makeFramebuffer(m_gl);
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, m_requestFramebuffer.id());
    m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_requestTexture.id(), 0);
    m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m_requestDepth.id(), 0);
    m_gl->glDrawBuffer(GL_COLOR_ATTACHMENT0);
    m_gl->glReadBuffer(GL_COLOR_ATTACHMENT0);
    labelGlObject(GlLabelKind::Framebuffer, m_requestFramebuffer.id(), QStringLiteral("virtual shadow map page requests"));
    if (const GLenum status = m_gl->glCheckFramebufferStatus(GL_FRAMEBUFFER); status != GL_FRAMEBUFFER_COMPLETE) {
        m_requestTexture.reset();
        throw RenderError(QStringLiteral("the %1 page-request target of shadow.virtual is incomplete (status 0x%2); set shadow.virtual=false")
                              .arg(dimensions).arg(status, 0, 16));
    }
    m_requestSize = size;
}

VirtualMapUniforms VirtualShadowMap::uniforms(const CameraFrame& camera) const
{
    VirtualMapUniforms u;
    if (!m_layout || m_windows.empty())
        return u;
    const VirtualLayout& layout = *m_layout;
    // q0 = light-view xy in level-0 pages from level 0's window, in double before the float.
    const double page0 = layout.pageWorld(0);
    const glm::dvec2 origin0(m_windows.front());
    glm::dmat4 toPages(1.0);
    toPages[0][0] = 1.0 / page0;
    toPages[1][1] = 1.0 / page0;
    toPages[3][0] = -origin0.x;
    toPages[3][1] = -origin0.y;
    glm::dmat4 m = toPages * layout.view * glm::translate(glm::dmat4(1.0), camera.position);
    // Depth as the pages store it: every page's frame has the coarsest window's depth row.
    const glm::dmat4 depth = m_depthMatrix * glm::translate(glm::dmat4(1.0), camera.position);
    for (int column = 0; column < 4; ++column)
        m[column][2] = depth[column][2];
    VirtualMapBlock& b = u.block;
    b.uVirtualLight = glm::mat4(m);
    b.uVirtualLevels = std::min(layout.levels, kMaxVirtualLevels);
    b.uVirtualLodBias = m_lodBias;
    for (int level = 0; level < b.uVirtualLevels; ++level) {
        const glm::ivec2 window = m_windows[std::size_t(level)];
        const glm::dvec2 offset = origin0 * std::ldexp(1.0, -level) - glm::dvec2(window);
        b.uVirtualLevelOffset[level] = glm::vec4(glm::vec2(offset), 0.0f, 0.0f);
        b.uVirtualWrap[level] = glm::ivec4(((window % kVirtualLevelPages) + kVirtualLevelPages) % kVirtualLevelPages, 0, 0);
    }
    b.uVirtualPoolSide = m_cache.poolSide();
    b.uVirtualTexel0 = float(layout.finestTexel);
    u.pageTable = m_pageTable.id();
    return u;
}

int VirtualShadowMap::drawRequests(const GpuScene& scene, const CameraFrame& camera, QSize size, const std::vector<QRect>* within, bool keepStill)
{
    if (!m_program) {
        m_program = std::make_unique<ShaderProgram>(m_gl, QStringLiteral("lit.vert"), QStringLiteral("virtual_request.frag"), QStringList());
        m_model = m_program->uniform("uModel");
        m_normalMatrix = m_program->uniform("uNormalMatrix");
        m_mvp = m_program->uniform("uModelViewProjection");
        m_receives = m_program->uniform("uReceives");
    }
    if (!m_requestTexture || m_requestSize != size)
        allocateTargets(size);
    const GLuint framebuffer = m_requestFramebuffer.id();
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    const QRect whole(QPoint(0, 0), size);
    PassState state;
    state.viewport = whole;
    state.depthTest = true;
    state.cullFace = GL_BACK;   // as the lit pass draws
    applyPassState(m_gl, state);
    m_block.upload(uniforms(camera).block);
    m_program->bind();
    const glm::dmat4 toCamera = glm::translate(glm::dmat4(1.0), -camera.position);
    int draws = 0;
    // The still objects or the moving ones, those that cover any of `areas`.
    const auto drawObjects = [&](bool moving, const std::vector<QRect>& areas) {
        for (const DrawItem& item : scene.drawItems()) {
            if (item.moves != moving)
                continue;
            const std::optional<QRect> covers = windowPixels(item.bounds, camera.viewProjection, size);
            if (covers && std::none_of(areas.begin(), areas.end(), [&](const QRect& area) { return covers->intersects(area); }))
                continue;
            m_program->set(m_model, glm::mat4(toCamera * item.model));
            m_program->set(m_normalMatrix, glm::mat3(item.normalMatrix));
            m_program->set(m_mvp, glm::mat4(camera.viewProjection * item.model));
            m_program->set(m_receives, int(item.receivesShadow));
            scene.draw(item, false);
            ++draws;
        }
    };
    if (within) {
        // Where moving objects were and are: the still objects' requests and depths as they
        // were drawn, and the moving objects over them, as one pass of both draws them. Every
        // moving object lies inside the areas, so nothing outside them changes.
        m_requestPixels = 0;
        for (const QRect& area : *within) {
            m_stillRequests.restore(framebuffer, area);
            m_requestPixels += qint64(area.width()) * area.height();
        }
        drawObjects(true, *within);
    } else {
        const GLuint none[4] = {0, 0, 0, 0};
        m_gl->glClearBufferuiv(GL_COLOR, 0, none);
        m_gl->glClearDepth(1.0);
        m_gl->glClear(GL_DEPTH_BUFFER_BIT);
        m_requestPixels = qint64(size.width()) * size.height();
        drawObjects(false, {whole});
        if (keepStill) {
            m_stillRequests.ensure(size, m_requestDepth.id(), m_requestTexture.id(), QStringLiteral("virtual shadow map still objects' requests"));
            m_stillRequests.save(framebuffer, whole);
        }
        drawObjects(true, {whole});
    }
    m_gl->glBindVertexArray(0);
    applyPassState(m_gl, PassState{});
    return draws;
}

void VirtualShadowMap::reducePass(QSize size)
{
    const int levels = int(m_windows.size());
    if (!m_reduceProgram) {
        m_reduceProgram = std::make_unique<ShaderProgram>(m_gl, QStringLiteral("virtual_reduce.vert"), QStringLiteral("virtual_reduce.frag"), QStringList());
        m_reduceWidth = m_reduceProgram->uniform("uRequestWidth");
        m_reduceLevels = m_reduceProgram->uniform("uLevels");
        m_reduceRequests = m_reduceProgram->uniform("uRequests");
        m_pointArray = makeVertexArray(m_gl);
    }
    if (!m_flagTexture || m_flagLevels != levels) {
        m_gl->glActiveTexture(GL_TEXTURE0);
        m_flagTexture = makeTexture(m_gl);
        m_gl->glBindTexture(GL_TEXTURE_2D, m_flagTexture.id());
        m_gl->glTexImage2D(GL_TEXTURE_2D, 0, GL_R8UI, kVirtualLevelPages, kVirtualLevelPages * levels, 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, nullptr);
        m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        m_gl->glBindTexture(GL_TEXTURE_2D, 0);
        labelGlObject(GlLabelKind::Texture, m_flagTexture.id(), QStringLiteral("virtual shadow map requested pages"));
        m_flagFramebuffer = makeFramebuffer(m_gl);
        m_gl->glBindFramebuffer(GL_FRAMEBUFFER, m_flagFramebuffer.id());
        m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_flagTexture.id(), 0);
        m_gl->glDrawBuffer(GL_COLOR_ATTACHMENT0);
        m_gl->glReadBuffer(GL_COLOR_ATTACHMENT0);
        if (m_gl->glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            m_flagTexture.reset();
            throw RenderError(QStringLiteral("the virtual shadow map's page flags (R8UI, %1 levels) cannot be drawn into on this driver").arg(levels));
        }
        m_flagLevels = levels;
    }
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, m_flagFramebuffer.id());
    PassState state;
    state.viewport = QRect(0, 0, kVirtualLevelPages, kVirtualLevelPages * levels);
    applyPassState(m_gl, state);
    const GLuint none[4] = {0, 0, 0, 0};
    m_gl->glClearBufferuiv(GL_COLOR, 0, none);
    m_reduceProgram->bind();
    m_reduceProgram->set(m_reduceWidth, size.width());
    m_reduceProgram->set(m_reduceLevels, levels);
    m_reduceProgram->set(m_reduceRequests, 0);
    m_gl->glActiveTexture(GL_TEXTURE0);
    m_gl->glBindTexture(GL_TEXTURE_2D, m_requestTexture.id());
    m_gl->glBindVertexArray(m_pointArray.id());
    m_gl->glDrawArrays(GL_POINTS, 0, GLsizei(size.width()) * GLsizei(size.height()));
    m_gl->glBindVertexArray(0);
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
}

VirtualShadowMap::RequestBytes VirtualShadowMap::readRequestBytes(QSize size, void* into)
{
    if (m_reduction == Reduction::Gpu) {
        reducePass(size);
        const int rows = kVirtualLevelPages * int(m_windows.size());
        m_gl->glPixelStorei(GL_PACK_ALIGNMENT, 1);
        m_gl->glReadPixels(0, 0, kVirtualLevelPages, rows, GL_RED_INTEGER, GL_UNSIGNED_BYTE, into);
        m_gl->glPixelStorei(GL_PACK_ALIGNMENT, 4);
        return {true, requestBytes(size)};
    }
    m_gl->glPixelStorei(GL_PACK_ALIGNMENT, 4);
    m_gl->glReadPixels(0, 0, size.width(), size.height(), GL_RED_INTEGER, GL_UNSIGNED_INT, into);
    return {false, requestBytes(size)};
}

std::size_t VirtualShadowMap::requestBytes(QSize size) const
{
    return m_reduction == Reduction::Gpu ? std::size_t(kVirtualLevelPages) * kVirtualLevelPages * m_windows.size()
                                         : std::size_t(size.width()) * std::size_t(size.height()) * sizeof(std::uint32_t);
}

std::vector<VirtualPage> VirtualShadowMap::decodeRequests(const RequestBytes& bytes, const void* data, const std::vector<glm::ivec2>& windows)
{
    std::vector<VirtualPage> pages;
    if (bytes.flags) {
        // Texel (x, level * 128 + y) is the request 1 + level * 128² + y * 128 + x.
        const auto* flags = static_cast<const std::uint8_t*>(data);
        for (std::size_t i = 0; i < bytes.bytes; ++i) {
            if (flags[i] == 0)
                continue;
            if (const std::optional<VirtualPage> page = decodePageRequest(std::uint32_t(i) + 1u, windows))
                pages.push_back(*page);
        }
        return pages;
    }
    // Deduplicated over a flag per page of every window; neighbouring pixels mostly ask for the
    // same page, so the last one is remembered too. The pages come out in the flags' order, as
    // the GPU's reduction gives them: the pool places them in the same slots, so the frame does
    // not depend on which reduction ran.
    const auto* words = static_cast<const std::uint32_t*>(data);
    const std::size_t pagesPerLevel = std::size_t(kVirtualLevelPages) * kVirtualLevelPages;
    std::vector<std::uint8_t> seen(pagesPerLevel * windows.size(), 0);
    std::uint32_t last = 0;
    std::uint32_t lowest = std::numeric_limits<std::uint32_t>::max(), highest = 0;
    for (std::size_t i = 0; i < bytes.bytes / sizeof(std::uint32_t); ++i) {
        const std::uint32_t value = words[i];
        if (value == 0 || value == last)
            continue;
        last = value;
        if (value - 1 >= seen.size())
            continue;
        seen[value - 1] = 1;
        lowest = std::min(lowest, value - 1);
        highest = std::max(highest, value - 1);
    }
    for (std::uint32_t i = lowest; i <= highest && i < seen.size(); ++i) {
        if (seen[i] == 0)
            continue;
        if (const std::optional<VirtualPage> page = decodePageRequest(i + 1u, windows))
            pages.push_back(*page);
    }
    return pages;
}

std::vector<VirtualPage> VirtualShadowMap::readRequests(QSize size, const std::vector<QRect>* within)
{
    if (within && m_reduction == Reduction::Cpu && m_mirrored)
        return readRequestsWithin(size, *within);
    m_readback.resize((requestBytes(size) + sizeof(std::uint32_t) - 1) / sizeof(std::uint32_t));
    const RequestBytes bytes = readRequestBytes(size, m_readback.data());
    m_mirrored = !bytes.flags;
    m_pageCounts.clear();
    return decodeRequests(bytes, m_readback.data(), m_windows);
}

std::vector<VirtualPage> VirtualShadowMap::readRequestsWithin(QSize size, const std::vector<QRect>& within)
{
    // The software profile's reduction (RasteriserTuning::cpuVirtualRequests), where reading
    // the whole buffer back costs as much as drawing the few pixels that changed.
    const std::size_t pages = std::size_t(kVirtualLevelPages) * kVirtualLevelPages * m_windows.size();
    if (m_pageCounts.size() != pages) {
        m_pageCounts.assign(pages, 0);
        for (const std::uint32_t word : m_readback) {
            if (word != 0 && word - 1 < pages)
                ++m_pageCounts[word - 1];
        }
    }
    std::vector<std::uint32_t> words;
    m_gl->glPixelStorei(GL_PACK_ALIGNMENT, 4);
    for (const QRect& area : within) {
        words.resize(std::size_t(area.width()) * std::size_t(area.height()));
        m_gl->glReadPixels(area.x(), area.y(), area.width(), area.height(), GL_RED_INTEGER, GL_UNSIGNED_INT, words.data());
        for (int y = 0; y < area.height(); ++y) {
            for (int x = 0; x < area.width(); ++x) {
                std::uint32_t& was = m_readback[std::size_t(area.y() + y) * std::size_t(size.width()) + std::size_t(area.x() + x)];
                const std::uint32_t now = words[std::size_t(y) * std::size_t(area.width()) + std::size_t(x)];
                if (now == was)
                    continue;
                if (was != 0 && was - 1 < pages)
                    --m_pageCounts[was - 1];
                if (now != 0 && now - 1 < pages)
                    ++m_pageCounts[now - 1];
                was = now;
            }
        }
    }
    // In the flags' order, as decodeRequests() gives them.
    std::vector<VirtualPage> requested;
    for (std::size_t i = 0; i < pages; ++i) {
        if (m_pageCounts[i] == 0)
            continue;
        if (const std::optional<VirtualPage> page = decodePageRequest(std::uint32_t(i) + 1u, m_windows))
            requested.push_back(*page);
    }
    return requested;
}

void VirtualShadowMap::startReadback(QSize size, const RequestKey& key)
{
    if (!m_pixelPack)
        m_pixelPack = makeBuffer(m_gl);
    m_gl->glBindBuffer(GL_PIXEL_PACK_BUFFER, m_pixelPack.id());
    m_gl->glBufferData(GL_PIXEL_PACK_BUFFER, GLsizeiptr(requestBytes(size)), nullptr, GL_STREAM_READ);
    m_pendingBytes = readRequestBytes(size, nullptr);
    m_mirrored = false;
    m_gl->glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    m_fence = m_gl->glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    m_gl->glFlush();
    m_pendingKey = key;
    m_pendingWindows = m_windows;
}

bool VirtualShadowMap::collectReadback(bool wait)
{
    if (!m_fence)
        return false;
    const GLenum state = m_gl->glClientWaitSync(m_fence, wait ? GL_SYNC_FLUSH_COMMANDS_BIT : 0, wait ? GLuint64(10'000'000'000) : 0);
    if (state != GL_ALREADY_SIGNALED && state != GL_CONDITION_SATISFIED)
        return false;
    m_gl->glDeleteSync(m_fence);
    m_fence = nullptr;
    m_gl->glBindBuffer(GL_PIXEL_PACK_BUFFER, m_pixelPack.id());
    const void* data = m_gl->glMapBufferRange(GL_PIXEL_PACK_BUFFER, 0, GLsizeiptr(m_pendingBytes.bytes), GL_MAP_READ_BIT);
    if (data) {
        m_requests = decodeRequests(m_pendingBytes, data, m_pendingWindows);
        m_gl->glUnmapBuffer(GL_PIXEL_PACK_BUFFER);
    }
    m_gl->glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    m_requestKey = m_pendingKey;
    return true;
}

void VirtualShadowMap::uploadPageTable()
{
    const std::vector<std::uint16_t> table = m_cache.pageTable(m_windows);
    const int levels = int(m_windows.size());
    m_gl->glActiveTexture(GL_TEXTURE0);
    if (!m_pageTable || m_pageTableLevels != levels) {
        m_pageTable = makeTexture(m_gl);
        m_gl->glBindTexture(GL_TEXTURE_2D, m_pageTable.id());
        m_gl->glTexImage2D(GL_TEXTURE_2D, 0, GL_R16UI, kVirtualLevelPages, kVirtualLevelPages * levels, 0, GL_RED_INTEGER, GL_UNSIGNED_SHORT, nullptr);
        m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
        labelGlObject(GlLabelKind::Texture, m_pageTable.id(), QStringLiteral("virtual shadow map page table"));
        m_pageTableLevels = levels;
    }
    m_gl->glBindTexture(GL_TEXTURE_2D, m_pageTable.id());
    m_gl->glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    m_gl->glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kVirtualLevelPages, kVirtualLevelPages * levels, GL_RED_INTEGER, GL_UNSIGNED_SHORT, table.data());
    m_gl->glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
}

void VirtualShadowMap::resetPool(int poolSide)
{
    m_cache.reset(poolSide);
    m_poolSide = poolSide;
    m_cacheLayoutGeneration = m_layoutGeneration;
    m_tableDirty = true;
    m_requestKey.reset();   // what the receivers ask for is asked again: they may have moved
    m_bufferKey.reset();    // and the still objects may be others
    m_stillKey.reset();
    if (m_fence) {          // pages of what is gone
        m_gl->glDeleteSync(m_fence);
        m_fence = nullptr;
    }
}

bool VirtualShadowMap::askForPages(const GpuScene& scene, const FramePlan& plan, const CameraFrame& camera, const RequestKey& key, int& requestDraws)
{
    // Requests read back asynchronously arrive a frame or more after their pass.
    bool arrived = m_fence && collectReadback(false);
    const bool asked = !m_requestKey || !(*m_requestKey == key) || m_askAgainWithin || m_askEverywhere;
    if (!asked || (m_fence && m_pendingKey == key))
        return arrived;
    // Only where objects moved, while the buffer and the still objects' copy hold this camera's
    // requests. The copy is taken once the camera stands (a second pass at the same key): a
    // moving camera asks everywhere anyway.
    constexpr std::size_t kMostAreas = 8;
    const std::vector<QRect> within = fewRects(m_askWithin, kMostAreas);
    const bool pages = plan.cache == ShadowCachePolicy::Pages;
    const bool partly = m_askAgainWithin && pages && m_bufferKey == key && m_stillKey == key;
    const bool keepStill = pages && m_bufferKey == key;
    requestDraws = drawRequests(scene, camera, key.size, partly ? &within : nullptr, keepStill);
    if (!partly)
        m_stillKey = keepStill ? std::optional<RequestKey>(key) : std::nullopt;
    if (!pages)
        m_stillRequests.release();
    m_bufferKey = key;
    m_askWithin.clear();
    m_askAgainWithin = false;
    m_askEverywhere = false;
    if (m_async && m_cache.resident() > 0) {
        if (m_fence)
            arrived = collectReadback(true) || arrived;     // one read-back in flight at a time
        startReadback(key.size, key);
        return arrived;
    }
    m_requests = readRequests(key.size, partly ? &within : nullptr);
    m_requestKey = key;
    return true;
}

VirtualMapStats VirtualShadowMap::update(const GpuScene& scene, const FramePlan& plan, const CameraFrame& camera, QSize size, bool invalidate,
                                         ShadowStorage& storage, const std::function<LightFrame(const LightVolume&)>& frameOf, int* casterDraws)
{
    const Settings& settings = plan.settings;
    if (!m_layout)
        throw RenderError(QStringLiteral("the virtual shadow map has no layout: layout() comes first"));
    VirtualMapStats stats;
    m_drawnSlots.clear();
    m_depthMatrix = frameOf(m_layout->coarsest).depthShadowMatrix;
    // A new layout (the light turned, the scene changed) leaves no page where it was.
    if (invalidate || m_poolSide != settings.shadow.virtualPool || m_cacheLayoutGeneration != m_layoutGeneration)
        resetPool(settings.shadow.virtualPool);
    const QSize requestSize(std::max(size.width(), 1), std::max(size.height(), 1));
    m_lodBias = settings.shadow.virtualLodBias;
    const RequestKey key{camera.viewProjection, camera.position, requestSize, m_layoutGeneration, m_lodBias};
    std::vector<glm::ivec2> windows = virtualWindows(*m_layout, camera.position);
    if (windows != m_windows) {
        m_windows = std::move(windows);
        m_tableDirty = true;
    }
    const bool arrived = askForPages(scene, plan, camera, key, stats.requestDraws);
    if (!arrived && !m_tableDirty) {
        // The same requests over the same pages and windows: nothing to place, draw or upload.
        const int requestDraws = stats.requestDraws;
        stats = m_lastStats;
        stats.drawn = 0;
        stats.requestDraws = requestDraws;
        stats.requestsPending = m_fence != nullptr;
        if (casterDraws)
            *casterDraws = 0;
        return stats;
    }
    const VirtualPageCache::Update placed = m_cache.update(m_requests, m_layout->levels);
    stats.requested = placed.requested;
    stats.coarsened = placed.coarsened;
    stats.levelsCoarsened = placed.levelsCoarsened;
    stats.overflow = placed.overflow;
    stats.poolPages = m_cache.capacity();
    int draws = 0;
    for (const auto& [page, slot] : placed.draw) {
        m_drawnSlots.push_back(slot);
        const QRect tile((slot % m_poolSide) * kVirtualSlotTexels, (slot / m_poolSide) * kVirtualSlotTexels, kVirtualSlotTexels, kVirtualSlotTexels);
        draws += storage.draw(scene, frameOf(virtualPageVolume(*m_layout, page)), plan, tile, nullptr, nullptr);
    }
    stats.drawn = int(placed.draw.size());
    stats.resident = m_cache.resident();
    for (const VirtualPage& page : m_requests) {
        if ((stats.finestLevel < 0 || page.level < stats.finestLevel) && m_cache.slotOf(page))
            stats.finestLevel = page.level;
    }
    if (casterDraws)
        *casterDraws = draws;
    if (m_tableDirty || !placed.draw.empty()) {
        uploadPageTable();
        m_tableDirty = false;
    }
    stats.requestsPending = m_fence != nullptr;
    m_lastStats = stats;
    return stats;
}

int VirtualShadowMap::redrawTouched(const GpuScene& scene, const FramePlan& plan, const std::vector<Bounds>& moved, ShadowStorage& storage,
                                    const std::function<LightFrame(const LightVolume&)>& frameOf, int* casterDraws,
                                    std::vector<std::pair<int, ViewCause>>& causes)
{
    causes.clear();
    if (!m_layout)
        return 0;
    std::vector<AcrossLight> areas;
    areas.reserve(moved.size());
    for (const Bounds& bounds : moved)
        areas.push_back(acrossLight(*m_layout, bounds));
    int drawn = 0;
    bool evicted = false;
    for (const auto& [page, slot] : m_cache.residentPages()) {
        if (std::find(m_drawnSlots.begin(), m_drawnSlots.end(), slot) != m_drawnSlots.end()) {
            causes.emplace_back(slot, ViewCause::New);
            continue;
        }
        const bool touched = std::any_of(areas.begin(), areas.end(), [&](const AcrossLight& a) { return pageOverlaps(*m_layout, page, a); });
        // A touched page this frame does not read is given up, not drawn.
        if (touched && !m_cache.inUse(page)) {
            m_cache.evict(page);
            evicted = true;
            continue;
        }
        causes.emplace_back(slot, touched ? ViewCause::Casters : ViewCause::Cached);
        if (!touched)
            continue;
        const QRect tile((slot % m_poolSide) * kVirtualSlotTexels, (slot / m_poolSide) * kVirtualSlotTexels, kVirtualSlotTexels, kVirtualSlotTexels);
        const int draws = storage.draw(scene, frameOf(virtualPageVolume(*m_layout, page)), plan, tile, nullptr, nullptr);
        if (casterDraws)
            *casterDraws += draws;
        ++drawn;
    }
    if (evicted)
        uploadPageTable();
    return drawn;
}

} // namespace shadowlab
