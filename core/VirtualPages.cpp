#include "VirtualPages.h"

#include "SharedShaderCode.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>

namespace shadowlab {

namespace {

int wrapped(int value, int size)
{
    const int r = value % size;
    return r < 0 ? r + size : r;
}

} // namespace

std::uint64_t VirtualPage::key() const
{
    return (std::uint64_t(std::uint32_t(level)) << 48) ^ (std::uint64_t(std::uint32_t(x) & 0xffffffu) << 24)
        ^ std::uint64_t(std::uint32_t(y) & 0xffffffu);
}

double VirtualLayout::texel(int level) const
{
    return std::ldexp(finestTexel, level);
}

VirtualLayout virtualLayout(const LightSettings& light, const Bounds& sceneBounds, int levels)
{
    VirtualLayout layout;
    layout.levels = std::clamp(levels, 1, kMaxVirtualLevels);
    const glm::dvec3 direction = glm::normalize(light.target - light.position);
    LightVolume& v = layout.coarsest;
    v.origin = sceneBounds.center();
    v.direction = direction;
    layout.view = stableLookAlong(v.origin, direction, v.up);
    // The scene's extent across and along the light, from its box's corners.
    double half = 0.0, nearest = 0.0, farthest = 0.0;
    for (const glm::dvec3& corner : sceneBounds.corners()) {
        const glm::dvec3 p = glm::dvec3(layout.view * glm::dvec4(corner, 1.0));
        half = std::max({half, std::abs(p.x), std::abs(p.y)});
        nearest = std::min(nearest, -p.z);
        farthest = std::max(farthest, -p.z);
    }
    // A scene of one point still gets a window and a depth range.
    const double scale = std::max({half, farthest - nearest, 1e-6 * std::max(1.0, glm::length(v.origin))});
    half = std::max(half, 1e-3 * scale);
    const double margin = 0.01 * scale;
    v.nearPlane = nearest - margin;
    v.farPlane = farthest + margin;
    // The coarsest level holds the whole scene in its two pages either side of the axis: a
    // scene seen no wider than 256 pixels needs nothing finer.
    const double coarsestPage = half * 1.01;
    layout.finestTexel = std::ldexp(coarsestPage / kVirtualPageTexels, -(layout.levels - 1));
    v.left = -coarsestPage;
    v.right = coarsestPage;
    v.bottom = -coarsestPage;
    v.top = coarsestPage;
    return layout;
}

std::vector<glm::ivec2> virtualWindows(const VirtualLayout& layout, const glm::dvec3& cameraPosition)
{
    const glm::dvec3 c = glm::dvec3(layout.view * glm::dvec4(cameraPosition, 1.0));
    std::vector<glm::ivec2> windows;
    for (int level = 0; level < layout.levels; ++level) {
        if (level == layout.levels - 1) {
            windows.emplace_back(-kVirtualLevelPages / 2);
            break;
        }
        // The camera's page, kept within the grid a level could ever need (the coarsest window,
        // in this level's pages), so a camera far off the scene gives finite windows.
        const double page = layout.pageWorld(level);
        const double limit = double(kVirtualLevelPages / 2) * std::ldexp(1.0, layout.levels - 1 - level);
        const auto centre = [&](double coordinate) {
            return int(std::clamp(std::round(coordinate / page), -limit, limit)) - kVirtualLevelPages / 2;
        };
        windows.emplace_back(centre(c.x), centre(c.y));
    }
    return windows;
}

LightVolume virtualPageVolume(const VirtualLayout& layout, const VirtualPage& page)
{
    LightVolume v = layout.coarsest;
    const double size = layout.pageWorld(page.level);
    const double border = layout.texel(page.level) * kVirtualPageBorder;
    v.left = page.x * size - border;
    v.right = (page.x + 1) * size + border;
    v.bottom = page.y * size - border;
    v.top = (page.y + 1) * size + border;
    return v;
}

AcrossLight acrossLight(const VirtualLayout& layout, const Bounds& bounds)
{
    AcrossLight area{glm::dvec2(std::numeric_limits<double>::max()), glm::dvec2(std::numeric_limits<double>::lowest())};
    for (const glm::dvec3& corner : bounds.corners()) {
        const glm::dvec2 p(layout.view * glm::dvec4(corner, 1.0));
        area.min = glm::min(area.min, p);
        area.max = glm::max(area.max, p);
    }
    return area;
}

bool pageOverlaps(const VirtualLayout& layout, const VirtualPage& page, const AcrossLight& area)
{
    const LightVolume v = virtualPageVolume(layout, page);
    return area.min.x <= v.right && area.max.x >= v.left && area.min.y <= v.top && area.max.y >= v.bottom;
}

void VirtualPageCache::reset(int poolSide)
{
    m_poolSide = std::max(poolSide, 1);
    m_pages.clear();
    m_free.clear();
    // Handed out from the front: slot 0 first.
    for (int slot = capacity() - 1; slot >= 0; --slot)
        m_free.push_back(slot);
}

namespace {

// The frame's distinct requests, made to fit `capacity` pages: while there are too many, the
// finest level's requests move to their parents (merged parents keep the deepest coarsening of
// their children); what still does not fit at the coarsest level is cut and counted.
std::vector<VirtualPage> fitRequests(std::vector<VirtualPage> requests, int levels, int capacity, VirtualPageCache::Update& result)
{
    std::unordered_set<std::uint64_t> seen;
    std::erase_if(requests, [&](const VirtualPage& p) { return !seen.insert(p.key()).second; });
    result.requested = int(requests.size());
    std::vector<int> levelsOf(requests.size(), 0);
    while (int(requests.size()) > capacity) {
        int finest = levels;
        for (const VirtualPage& p : requests)
            finest = std::min(finest, p.level);
        if (finest >= levels - 1)
            break;
        for (std::size_t i = 0; i < requests.size(); ++i) {
            VirtualPage& p = requests[i];
            if (p.level != finest)
                continue;
            p = {p.level + 1, int(std::floor(p.x / 2.0)), int(std::floor(p.y / 2.0))};
            ++levelsOf[i];
        }
        std::unordered_map<std::uint64_t, std::size_t> firstOf;
        std::vector<VirtualPage> merged;
        std::vector<int> mergedLevels;
        for (std::size_t i = 0; i < requests.size(); ++i) {
            auto [it, inserted] = firstOf.emplace(requests[i].key(), merged.size());
            if (inserted) {
                merged.push_back(requests[i]);
                mergedLevels.push_back(levelsOf[i]);
            } else {
                mergedLevels[it->second] = std::max(mergedLevels[it->second], levelsOf[i]);
            }
        }
        requests = std::move(merged);
        levelsOf = std::move(mergedLevels);
    }
    for (int coarsenedBy : levelsOf) {
        if (coarsenedBy > 0) {
            ++result.coarsened;
            result.levelsCoarsened = std::max(result.levelsCoarsened, coarsenedBy);
        }
    }
    if (int(requests.size()) > capacity) {
        result.overflow = int(requests.size()) - capacity;
        requests.resize(std::size_t(capacity));
    }
    return requests;
}

} // namespace

VirtualPageCache::Update VirtualPageCache::update(std::vector<VirtualPage> requests, int levels)
{
    ++m_frame;
    Update result;
    requests = fitRequests(std::move(requests), levels, capacity(), result);
    // Mark what stays, then place what is new, taking free slots first and then the least
    // recently used pages that this frame does not need.
    std::vector<VirtualPage> missing;
    for (const VirtualPage& p : requests) {
        if (auto it = m_pages.find(p.key()); it != m_pages.end())
            it->second.lastUsed = m_frame;
        else
            missing.push_back(p);
    }
    std::vector<Entry*> evictable;
    if (missing.size() > m_free.size()) {
        for (auto& [key, entry] : m_pages) {
            if (entry.lastUsed != m_frame)
                evictable.push_back(&entry);
        }
        std::sort(evictable.begin(), evictable.end(), [](const Entry* a, const Entry* b) {
            return a->lastUsed != b->lastUsed ? a->lastUsed < b->lastUsed : a->slot < b->slot;
        });
    }
    std::size_t nextEvicted = 0;
    for (const VirtualPage& p : missing) {
        int slot = 0;
        if (!m_free.empty()) {
            slot = m_free.back();
            m_free.pop_back();
        } else {
            Entry* victim = evictable[nextEvicted++];
            slot = victim->slot;
            m_pages.erase(victim->page.key());
            ++result.evicted;
        }
        m_pages[p.key()] = Entry{p, slot, m_frame};
        result.draw.emplace_back(p, slot);
    }
    return result;
}

std::optional<int> VirtualPageCache::slotOf(const VirtualPage& page) const
{
    const auto it = m_pages.find(page.key());
    return it == m_pages.end() ? std::nullopt : std::optional<int>(it->second.slot);
}

bool VirtualPageCache::inUse(const VirtualPage& page) const
{
    const auto it = m_pages.find(page.key());
    return it != m_pages.end() && it->second.lastUsed == m_frame;
}

void VirtualPageCache::evict(const VirtualPage& page)
{
    const auto it = m_pages.find(page.key());
    if (it == m_pages.end())
        return;
    m_free.push_back(it->second.slot);
    m_pages.erase(it);
}

std::vector<std::uint16_t> VirtualPageCache::pageTable(const std::vector<glm::ivec2>& windows) const
{
    constexpr int n = kVirtualLevelPages;
    std::vector<std::uint16_t> table(std::size_t(n) * n * windows.size(), 0);
    for (const auto& [key, entry] : m_pages) {
        const VirtualPage& p = entry.page;
        if (p.level < 0 || p.level >= int(windows.size()))
            continue;
        const glm::ivec2 w = windows[std::size_t(p.level)];
        if (p.x < w.x || p.x >= w.x + n || p.y < w.y || p.y >= w.y + n)
            continue;   // cached, but outside the level's window this frame
        const std::size_t row = std::size_t(p.level * n + wrapped(p.y, n));
        table[row * n + std::size_t(wrapped(p.x, n))] = std::uint16_t(entry.slot + 1);
    }
    return table;
}

std::vector<std::pair<VirtualPage, int>> VirtualPageCache::residentPages() const
{
    std::vector<std::pair<VirtualPage, int>> pages;
    for (const auto& [key, entry] : m_pages)
        pages.emplace_back(entry.page, entry.slot);
    std::sort(pages.begin(), pages.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
    return pages;
}

std::optional<VirtualPage> decodePageRequest(std::uint32_t value, const std::vector<glm::ivec2>& windows)
{
    if (value == 0)
        return std::nullopt;
    const glm::ivec3 request = glsl::virtualUnpackRequest(value);
    if (std::size_t(request.x) >= windows.size())
        return std::nullopt;
    const glm::ivec2 w = windows[std::size_t(request.x)];
    return VirtualPage{request.x, w.x + request.y, w.y + request.z};
}

} // namespace shadowlab
