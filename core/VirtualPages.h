#pragma once

#include "Bounds.h"
#include "LightMath.h"
#include "Settings.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

namespace shadowlab {

// Virtual shadow maps (shadow.virtual): a directional light's clipmap, each level a virtual map
// of kVirtualLevelPages² pages of kVirtualPageTexels² texels, each level's texel twice the one
// before, the coarsest covering the whole scene. Pages sit on one grid in the light's view
// plane, fixed by the scene and the light alone: the camera only moves each level's window of
// pages (snapped to whole pages), so a page drawn once stays valid until the light or the scene
// changes. A page is stored in a slot of a physical pool with a border of kVirtualPageBorder
// texels drawn from its neighbours' area, so a filter's taps near its edge read true depth.
inline constexpr int kVirtualPageTexels = 128;
inline constexpr int kVirtualPageBorder = 4;
inline constexpr int kVirtualSlotTexels = kVirtualPageTexels + 2 * kVirtualPageBorder;
inline constexpr int kVirtualLevelPages = 128;      // per side of a level's window: 16384² virtual texels
inline constexpr int kMaxVirtualLevels = 16;

// A page of the clipmap: its level and where it lies on that level's grid (whole pages from the
// light's axis through the scene's centre).
struct VirtualPage {
    int level = 0;
    int x = 0, y = 0;
    bool operator==(const VirtualPage&) const = default;
    std::uint64_t key() const;
};

// Where the light's clipmap lies: the light's view, every level's page size, the depth range.
struct VirtualLayout {
    LightVolume coarsest;       // the coarsest level's four pages around the axis: an ortho volume over the scene
    glm::dmat4 view{1.0};       // world -> the light's view (x, y across it)
    int levels = 1;
    double finestTexel = 1.0;   // world size of a texel of level 0
    double texel(int level) const;
    double pageWorld(int level) const { return texel(level) * kVirtualPageTexels; }
    bool operator==(const VirtualLayout&) const = default;
};

// The layout of `settings`' light over a scene of `sceneBounds` (not empty, finite): the grid's
// origin on the light's axis through the scene's middle, the coarsest level's pages each as
// wide as half the scene (so its four pages around the axis hold all of it), the depth range the
// scene's whole extent along the light.
VirtualLayout virtualLayout(const LightSettings& light, const Bounds& sceneBounds, int levels);

// Each level's window: its first page on the level's grid. Level windows follow the camera's
// position across the light, snapped to whole pages; the coarsest stays on the scene.
std::vector<glm::ivec2> virtualWindows(const VirtualLayout& layout, const glm::dvec3& cameraPosition);

// The ortho volume one page is drawn with: its square on the grid and the border around it.
LightVolume virtualPageVolume(const VirtualLayout& layout, const VirtualPage& page);

// Where `bounds` lies across the light, in the layout's view plane (x, y of VirtualLayout::view):
// the square a caster there can shadow, at any depth.
struct AcrossLight {
    glm::dvec2 min{0.0}, max{0.0};
};
AcrossLight acrossLight(const VirtualLayout& layout, const Bounds& bounds);
// Whether a page's drawn square (its border included) overlaps `area`: a caster there is in the
// page (shadow.cache=pages draws such a page again when the caster moves).
bool pageOverlaps(const VirtualLayout& layout, const VirtualPage& page, const AcrossLight& area);

// The pool of physical pages and which virtual page each holds, least recently used first out.
class VirtualPageCache {
public:
    // `poolSide`² slots, all free: also what the light or the scene changing does.
    void reset(int poolSide);

    struct Update {
        std::vector<std::pair<VirtualPage, int>> draw;  // pages newly placed, with their slot: to draw
        int requested = 0;          // distinct pages the frame asked for
        int coarsened = 0;          // ... of which asked for at a finer level than they got
        int levelsCoarsened = 0;    // the most levels a request was coarsened by
        int overflow = 0;           // pages of the coarsest level that did not fit (a pool smaller than one view)
        int evicted = 0;            // cached pages given up for new ones
    };
    // Makes every page of `requests` resident: the pages the frame's pixels need, deduplicated.
    // When they are more than the pool holds, the finest level's requests become requests for
    // their parents, level by level, until they fit. Pages not asked for stay as long as no new
    // page needs their slot.
    Update update(std::vector<VirtualPage> requests, int levels);

    std::optional<int> slotOf(const VirtualPage& page) const;
    // Whether the last update() served `page`: the frame's pixels read it.
    bool inUse(const VirtualPage& page) const;
    // Gives up `page` and frees its slot (an out-of-date page no pixel reads: drawing it again
    // would be work for nothing, and a later request draws it anew).
    void evict(const VirtualPage& page);
    int resident() const { return int(m_pages.size()); }
    int poolSide() const { return m_poolSide; }
    int capacity() const { return m_poolSide * m_poolSide; }
    // The integer page table: per level, kVirtualLevelPages² entries (rows level * kVirtualLevelPages
    // up), each the slot + 1 of the page its window holds there (wrapped: page mod the window's
    // size) or 0 where none is resident.
    std::vector<std::uint16_t> pageTable(const std::vector<glm::ivec2>& windows) const;
    // Every resident page with its slot.
    std::vector<std::pair<VirtualPage, int>> residentPages() const;

private:
    struct Entry {
        VirtualPage page;
        int slot = 0;
        std::uint64_t lastUsed = 0;
    };
    int m_poolSide = 0;
    std::uint64_t m_frame = 0;
    std::unordered_map<std::uint64_t, Entry> m_pages;
    std::vector<int> m_free;
};

// A page the request pass asked for, from its packed value (0: none) and the level windows.
std::optional<VirtualPage> decodePageRequest(std::uint32_t value, const std::vector<glm::ivec2>& windows);

} // namespace shadowlab
