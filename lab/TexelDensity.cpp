#include "TexelDensity.h"

#include "SharedShaderCode.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace shadowlab {

namespace {

// The view a receiver at `p` reads, as the lit pass picks it (shadow_lookup.glsl).
std::optional<std::size_t> viewOf(const ShadowViewFrames& views, const LightFrame& light, const glm::dvec3& p)
{
    const std::vector<ShadowView>& set = views.set.views;
    if (set.empty() || views.frames.size() != set.size())
        return std::nullopt;
    if (views.set.cube) {
        const std::size_t face = std::size_t(glsl::cubeFace(glm::vec3(p - light.position)));
        return face < set.size() ? std::optional(face) : std::nullopt;
    }
    if (views.set.cascaded) {
        const glm::dmat4& v = views.camera.view;
        const glm::dvec3 forward = -glm::dvec3(v[0][2], v[1][2], v[2][2]);
        glm::vec4 far(0.0f);
        const int count = int(std::min<std::size_t>(set.size(), 4));
        for (int i = 0; i < count; ++i)
            far[i] = float(set[std::size_t(i)].splitFar);
        const int i = glsl::cascadeIndex(float(glm::dot(p - views.camera.position, forward)), far, count);
        return i >= 0 ? std::optional(std::size_t(i)) : std::nullopt;     // beyond shadow.distance: no lookup
    }
    return 0;
}

} // namespace

namespace {

// Over the light-facing receiver pixels of `buffer`: `texelOf(i, j)` is pixel j's texel in the
// map that pixel i reads (nullopt: i reads none there), `adjust(i, t)` turns i's texels per pixel
// in that map into those of what it really reads (nullopt: it reads nothing).
template<typename TexelOf, typename Adjust>
TexelDensity measureDensity(const VisibilityBuffer& buffer, std::vector<double>* perPixel, TexelOf texelOf, Adjust adjust)
{
    TexelDensity density;
    const int w = buffer.size.width(), h = buffer.size.height();
    if (perPixel)
        perPixel->assign(std::size_t(std::max(w, 0)) * std::size_t(std::max(h, 0)), std::nan(""));
    if (w < 2 || h < 2 || buffer.positionVisibility.size() < std::size_t(w) * std::size_t(h))
        return density;
    std::vector<double> pixelsPerTexel;
    const auto at = [w](int x, int y) { return y * w + x; };
    // A neighbour on the same surface: light-facing, the same normal, on the pixel's plane.
    const auto sameSurface = [&](int i, int j) {
        if (buffer.mask(j) != VisibilityBuffer::FacingLight)
            return false;
        const glm::dvec3 n = buffer.normal(i);
        const glm::dvec3 step = buffer.worldPosition(j) - buffer.worldPosition(i);
        return glm::dot(n, buffer.normal(j)) > 0.999 && std::abs(glm::dot(n, step)) <= 1e-3 * glm::length(step) + 1e-9;
    };
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const int i = at(x, y);
            if (buffer.mask(i) != VisibilityBuffer::FacingLight)
                continue;
            const std::optional<glm::dvec2> t = texelOf(i, i);
            if (!t)
                continue;       // outside the map: lit without a lookup
            // One step right (or left) and one down (or up), on the same surface.
            std::optional<glm::dvec2> dx, dy;
            for (int sx : {1, -1}) {
                const int nx = x + sx;
                if (!dx && nx >= 0 && nx < w && sameSurface(i, at(nx, y)))
                    if (const auto u = texelOf(i, at(nx, y)))
                        dx = (*u - *t) * double(sx);
            }
            for (int sy : {1, -1}) {
                const int ny = y + sy;
                if (!dy && ny >= 0 && ny < h && sameSurface(i, at(x, ny)))
                    if (const auto u = texelOf(i, at(x, ny)))
                        dy = (*u - *t) * double(sy);
            }
            if (!dx || !dy)
                continue;
            const std::optional<double> texelsPerPixel = adjust(i, std::sqrt(std::abs(dx->x * dy->y - dx->y * dy->x)));
            if (!texelsPerPixel)
                continue;
            const double perTexel = *texelsPerPixel > 0.0 ? 1.0 / *texelsPerPixel : 1e30;
            ++density.counted;
            density.fine += perTexel <= 1.0;
            pixelsPerTexel.push_back(perTexel);
            if (perPixel)
                (*perPixel)[std::size_t(i)] = perTexel;
        }
    }
    if (!pixelsPerTexel.empty()) {
        auto middle = pixelsPerTexel.begin() + std::ptrdiff_t(pixelsPerTexel.size() / 2);
        std::nth_element(pixelsPerTexel.begin(), middle, pixelsPerTexel.end());
        density.medianPixelsPerTexel = *middle;
    }
    return density;
}

} // namespace

TexelDensity measureTexelDensity(const VisibilityBuffer& buffer, const ShadowViewFrames& views, const LightFrame& light, int mapSize,
                                 std::vector<double>* perPixel)
{
    const auto texelOf = [&](int center, int i) -> std::optional<glm::dvec2> {
        const std::optional<std::size_t> view = viewOf(views, light, buffer.worldPosition(center));
        if (!view)
            return std::nullopt;
        const glm::dvec4 c = views.frames[*view].shadowMatrix * glm::dvec4(buffer.worldPosition(i), 1.0);
        if (!(c.w > 0.0))
            return std::nullopt;
        const glm::dvec2 t = glm::dvec2(c) / c.w * double(mapSize);
        if (center == i && (t.x < 0.0 || t.y < 0.0 || t.x > mapSize || t.y > mapSize))
            return std::nullopt;
        return t;
    };
    return measureDensity(buffer, perPixel, texelOf, [](int, double t) { return std::optional<double>(t); });
}

TexelDensity measureVirtualTexelDensity(const VisibilityBuffer& buffer, const VirtualShadowMap& map, std::vector<double>* perPixel)
{
    const std::optional<VirtualLayout>& layout = map.currentLayout();
    const std::vector<glm::ivec2>& windows = map.windows();
    if (!layout || int(windows.size()) != layout->levels)
        return {};
    // Level-0 texels on the grid, as the lookup takes them (virtual_pages.glsl), in double.
    const double page0 = layout->pageWorld(0);
    const auto gridTexel = [&](int i) {
        const glm::dvec3 p = glm::dvec3(layout->view * glm::dvec4(buffer.worldPosition(i), 1.0));
        return glm::dvec2(p) / page0 * double(kVirtualPageTexels);
    };
    // The page of `level` that holds level-0 texel `texel0`, where the level's window does
    // (shaders/shared/virtual_levels.glsl): as the lookup takes it, from level 0's window, with
    // the windows' offsets taken in double (VirtualShadowMap::uniforms).
    const glm::dvec2 origin0(windows.front());
    const auto inWindow = [&](int level, const glm::dvec2& texel0, glm::ivec2& page) {
        const glm::ivec2 w = windows[std::size_t(level)];
        const glm::vec2 q0(texel0 / double(kVirtualPageTexels) - origin0);
        const glm::vec2 offset(origin0 * std::ldexp(1.0, -level) - glm::dvec2(w));
        const glm::vec2 q = glsl::virtualLevelPosition(level, q0, offset);
        page = glm::ivec2(glm::floor(q)) + w;
        return glsl::virtualWindowHolds(q);
    };
    const auto texelOf = [&](int, int i) -> std::optional<glm::dvec2> { return gridTexel(i); };
    // The level the pixel asks for, then the one finer or the nearest coarser one resident.
    const auto adjust = [&](int i, double level0) -> std::optional<double> {
        const glm::dvec2 t = gridTexel(i);
        int asked = glsl::virtualDensityLevel(float(level0), map.lodBias(), layout->levels);
        glm::ivec2 page;
        while (asked < layout->levels && !inWindow(asked, t, page))
            ++asked;
        if (asked >= layout->levels)
            return std::nullopt;
        for (int k = -1; k < layout->levels; ++k) {
            const int level = glsl::virtualFallbackLevel(asked, k);
            if (level < 0 || level >= layout->levels || !inWindow(level, t, page))
                continue;
            if (map.cache().slotOf({level, page.x, page.y}))
                return level0 * std::ldexp(1.0, -level);
        }
        return std::nullopt;
    };
    return measureDensity(buffer, perPixel, texelOf, adjust);
}

} // namespace shadowlab
