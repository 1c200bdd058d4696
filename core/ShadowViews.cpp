#include "ShadowViews.h"

#include "LightWarp.h"

#include <functional>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

// Texels a cube face's map reaches past 90°, on each side: a wide filter at a face's edge
// still reads its own face.
constexpr double kFaceMarginTexels = 4.0;

// A symmetric cone (square frustum) of full angle `fov` degrees from `position` along `axis`,
// reaching far past any scene: what a spot's cone or a cube face can see.
glm::dmat4 coneFrustum(const glm::dvec3& position, const glm::dvec3& axis, double fov)
{
    const double t = std::tan(glm::radians(fov) * 0.5);
    const double n = 1e-9 * std::max(1.0, glm::length(position));
    return glm::frustum(-t * n, t * n, -t * n, t * n, n, 1e15) * stableLookAlong(position, axis);
}

// Rounded up to a step of 2^(1/64): float noise in a slice's corners cannot change it.
double roundUpFine(double x)
{
    return std::exp2(std::ceil(std::log2(x) * 64.0) / 64.0);
}

// light.warp = lispsm on a directional light's view whose receivers the camera sees between
// view depths nearDepth and farDepth. `plain` gives the unwarped fit of the same view to weigh
// the warp against (called only when a warp is made); where the warp gains too little, that
// one is drawn instead.
void warpView(const Settings& settings, const CameraFrame& camera, double nearDepth, double farDepth, FittedLight& fit,
              const std::function<FittedLight()>& plain)
{
    if (!usesLightWarp(settings) || !fit.anythingToShadow)
        return;
    WarpShape shape;
    const LightVolume warped = lispsmVolume(fit.volume, camera, {.nearDepth = nearDepth, .farDepth = farDepth, .scale = settings.light.warpScale, .outline = fit.focus},
                                            &shape);
    if (!shape.warped) {
        fit.warpSkip = FittedLight::WarpSkip::AlongLight;
        return;
    }
    FittedLight unwarped = plain();
    const double gain = warpNearGain(warped, unwarped.volume, settings.map.size, camera, fit.focus);
    if (gain < kWarpLeastGain) {
        fit = std::move(unwarped);
        fit.warpGain = gain;
        fit.warpSkip = FittedLight::WarpSkip::NoGain;
        return;
    }
    fit.volume = warped;
    fit.warped = true;
    fit.warpGain = gain;
    fit.warpNearDistance = shape.nearDistance;
    fit.texelAfter = texelWorldSize(fit.volume, settings.map.size);
}

} // namespace

bool usesShadowViews(const Settings& settings)
{
    return settings.light.type == LightType::Point || (settings.light.type == LightType::Directional && settings.shadow.cascades > 1);
}

bool usesLightWarp(const Settings& settings)
{
    return settings.light.warp == LightWarp::Lispsm && settings.light.type == LightType::Directional;
}

bool slicesDepth(const Settings& settings)
{
    if (settings.shadow.virtualMap || settings.shadow.cache != ShadowCachePolicy::Off)
        return false;
    if (settings.light.type == LightType::Point)
        return true;
    return settings.light.projection == LightProjection::Ortho && !usesLightWarp(settings) && !usesShadowViews(settings);
}

bool usesVisibleDepth(const Settings& settings)
{
    return settings.shadow.enabled && settings.shadow.depthFit == DepthFit::Sdsm && settings.light.type == LightType::Directional
        && settings.shadow.cascades > 1;
}

ShadowTileGrid shadowTileGrid(const Settings& settings)
{
    if (settings.light.type == LightType::Point)
        return {3, 2};
    if (usesShadowViews(settings))
        return {std::min(settings.shadow.cascades, 2), (settings.shadow.cascades + 1) / 2};
    return {};
}

std::vector<double> cascadeSplits(CascadeSplit scheme, double lambda, double nearPlane, double farPlane, int count)
{
    count = std::max(count, 1);
    if (!(nearPlane > 0.0) || !std::isfinite(nearPlane))
        nearPlane = 1e-3;
    if (!(farPlane > nearPlane) || !std::isfinite(farPlane))
        farPlane = nearPlane * 2.0;
    lambda = scheme == CascadeSplit::Uniform ? 0.0 : scheme == CascadeSplit::Logarithmic ? 1.0 : std::clamp(lambda, 0.0, 1.0);
    std::vector<double> splits(std::size_t(count) + 1);
    for (int i = 0; i <= count; ++i) {
        const double f = double(i) / count;
        const double uniform = nearPlane + (farPlane - nearPlane) * f;
        const double logarithmic = nearPlane * std::pow(farPlane / nearPlane, f);
        splits[std::size_t(i)] = lambda * logarithmic + (1.0 - lambda) * uniform;
    }
    splits.front() = nearPlane;
    splits.back() = farPlane;
    return splits;
}

const std::vector<glm::dvec3>& cubeFaceAxes()
{
    static const std::vector<glm::dvec3> axes{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    return axes;
}

double cubeFaceFov(int mapSize)
{
    const double texels = std::max(double(mapSize), 4.0 * kFaceMarginTexels);
    return 2.0 * glm::degrees(std::atan(texels / (texels - 2.0 * kFaceMarginTexels)));
}

FittedLight fitCascadeSphere(const LightSettings& light, const std::vector<FitObject>& objects, const glm::dmat4& slice, int mapSize,
                             const glm::dvec3& mapUp)
{
    FittedLight result;
    const glm::dvec3 direction = glm::normalize(light.target - light.position);
    const std::array<glm::dvec3, 8> corners = frustumCorners(slice);
    glm::dvec3 centre(0.0);
    for (const glm::dvec3& c : corners)
        centre += c / 8.0;
    double radius = 0.0;
    for (const glm::dvec3& c : corners)
        radius = std::max(radius, glm::length(c - centre));
    radius = roundUpFine(std::max(radius, 1e-9 * std::max(1.0, glm::length(centre))));

    const glm::dmat4 view = stableLookAlong(light.target, direction, mapUp);
    const auto toLight = [&view](const glm::dvec3& p) {
        const glm::dvec3 v(view * glm::dvec4(p, 1.0));
        return glm::dvec3(v.x, v.y, -v.z);
    };
    // Whole texels: the map's grid stays put in light space while the camera moves.
    const double texel = 2.0 * radius / double(mapSize);
    glm::dvec3 middle = toLight(centre);
    middle.x = std::round(middle.x / texel) * texel;
    middle.y = std::round(middle.y / texel) * texel;
    const glm::dvec2 low(middle.x - radius, middle.y - radius), high(middle.x + radius, middle.y + radius);

    // Depth: the receivers under the square (casters nearer the light are clamped to the near
    // plane by the depth pass and still cast).
    const glm::dmat4 column = glm::ortho(low.x, high.x, low.y, high.y, -1e300, 1e300) * view;
    Bounds depths;
    bool casterOver = false;
    FrustaClip clip({column, slice});
    for (const FitObject& object : objects) {
        if (object.bounds.isEmpty())
            continue;
        Bounds inLight;
        for (const glm::dvec3& c : object.bounds.corners())
            inLight.extend(toLight(c));
        if (inLight.max.x < low.x || inLight.min.x > high.x || inLight.max.y < low.y || inLight.min.y > high.y)
            continue;
        casterOver = casterOver || object.casts;
        if (!object.receives)
            continue;
        for (const glm::dvec3& p : clip(object.bounds))
            depths.extend(toLight(p));
    }
    result.texelBefore = result.texelAfter = texel;
    result.fitted = true;
    if (depths.isEmpty() || !casterOver) {
        result.anythingToShadow = false;
        depths = Bounds();
        depths.extend(glm::dvec3(0.0, 0.0, middle.z - radius));
        depths.extend(glm::dvec3(0.0, 0.0, middle.z + radius));
    }
    // Snapped to a quarter of the radius, so small camera moves keep the same depth range.
    const double grid = radius * 0.25;
    const double nearPlane = std::floor((depths.min.z - grid * 1e-3) / grid) * grid;
    const double farPlane = std::ceil((depths.max.z + grid * 1e-3) / grid) * grid;
    const double mid = (nearPlane + farPlane) * 0.5;
    const glm::dvec3 right(view[0][0], view[1][0], view[2][0]);
    const glm::dvec3 up(view[0][1], view[1][1], view[2][1]);
    LightVolume& v = result.volume;
    v.perspective = false;
    v.direction = direction;
    v.up = mapUp;
    v.origin = light.target + right * middle.x + up * middle.y + direction * mid;
    v.left = v.bottom = -radius;
    v.right = v.top = radius;
    v.nearPlane = nearPlane - mid;
    v.farPlane = std::max(farPlane - mid, v.nearPlane + grid);
    if (mapUp != glm::dvec3(0.0)) {
        // A warped cascade needs to cover only its slice's outline within the square.
        std::vector<glm::dvec2> outline;
        for (const glm::dvec3& c : corners)
            outline.emplace_back(toLight(c));
        result.focus = focusOutline(std::move(outline), glm::dvec2(middle), glm::dvec2(2.0 * radius), 4.0 * texel);
    }
    return result;
}

std::pair<double, double> cascadeDepthRange(const Settings& settings, const CameraFrame& camera, const std::optional<VisibleDepthRange>& visible)
{
    const double nearest = camera.nearPlane;
    const double farthest = std::max(std::min(settings.shadow.distance, camera.farPlane), nearest * (1.0 + 1e-6));
    if (settings.shadow.depthFit != DepthFit::Sdsm || !visible || !std::isfinite(visible->nearest) || !std::isfinite(visible->farthest)
        || visible->farthest < visible->nearest)
        return {nearest, farthest};
    // Within the distance's range: receivers beyond shadow.distance stay lit, as without sdsm.
    const double low = std::clamp(visible->nearest * (1.0 - kSdsmPadding), nearest, farthest);
    if (low >= farthest)
        return {nearest, farthest};     // everything drawn lies beyond the distance: lit
    const double high = std::clamp(visible->farthest * (1.0 + kSdsmPadding), low, farthest);
    // One depth drawn (a wall face-on): a slice of the padding's width around it.
    return {low, std::max(high, std::min(low * (1.0 + kSdsmPadding), farthest))};
}

ShadowViewSet fitShadowViews(const Settings& settings, const std::vector<FitObject>& objects, const CameraFrame& camera, double aspect,
                             const std::optional<VisibleDepthRange>& visible)
{
    ShadowViewSet set;
    const ShadowTileGrid grid = shadowTileGrid(settings);
    set.columns = grid.columns;
    set.rows = grid.rows;
    const LightSettings& light = settings.light;
    const int mapSize = settings.map.size;
    if (light.type == LightType::Point) {
        set.cube = true;
        const double distance = std::max(glm::length(light.target - light.position), 1e-9);
        const double fov = cubeFaceFov(mapSize);
        for (std::size_t face = 0; face < cubeFaceAxes().size(); ++face) {
            const glm::dvec3& axis = cubeFaceAxes()[face];
            LightSettings faceLight = light;
            faceLight.type = LightType::Spot;
            faceLight.projection = LightProjection::Perspective;
            faceLight.target = light.position + axis * distance;
            faceLight.fov = fov;
            ShadowView view;
            view.axis = axis;
            view.column = int(face % 3);
            view.row = int(face / 3);
            // Each face answers for the directions whose major axis is its own.
            // Manual: the face as set (light.near, light.far), a little over 90°.
            view.fit = fitLight(faceLight, objects, camera.viewProjection, mapSize, {coneFrustum(light.position, axis, 90.0)});
            set.views.push_back(std::move(view));
        }
        return set;
    }
    if (light.type == LightType::Directional && settings.shadow.cascades > 1) {
        set.cascaded = true;
        const int count = settings.shadow.cascades;
        const glm::dvec3 mapUp = usesLightWarp(settings) ? warpAxis(camera, light.target - light.position) : glm::dvec3(0.0);
        const auto [nearest, farthest] = cascadeDepthRange(settings, camera, visible);
        const std::vector<double> splits = cascadeSplits(settings.shadow.split, settings.shadow.splitLambda, nearest, farthest, count);
        const double safeAspect = std::isfinite(aspect) && aspect > 0.0 ? aspect : 1.0;
        for (int i = 0; i < count; ++i) {
            ShadowView view;
            view.column = i % 2;
            view.row = i / 2;
            view.splitNear = splits[std::size_t(i)];
            view.splitFar = splits[std::size_t(i) + 1];
            // Slices overlap by the blend band, so a blended pixel is covered by both maps.
            const double blendStart = view.splitNear - settings.shadow.blend * (view.splitNear - (i > 0 ? splits[std::size_t(i) - 1] : view.splitNear));
            const glm::dmat4 slice = glm::perspective(glm::radians(settings.camera.fov), safeAspect, std::max(blendStart, camera.nearPlane), view.splitFar) * camera.view;
            const auto fit = [&](const glm::dvec3& up) {
                return light.stabilize ? fitCascadeSphere(light, objects, slice, mapSize, up) : fitLight(light, objects, slice, mapSize, {}, up);
            };
            view.fit = fit(mapUp);
            warpView(settings, camera, std::max(blendStart, camera.nearPlane), view.splitFar, view.fit, [&] { return fit(glm::dvec3(0.0)); });
            set.views.push_back(std::move(view));
        }
        return set;
    }
    ShadowView view;
    std::vector<glm::dmat4> within;
    if (light.type == LightType::Spot)
        within.push_back(coneFrustum(light.position, glm::normalize(light.target - light.position), light.fov));
    const glm::dvec3 mapUp = usesLightWarp(settings) ? warpAxis(camera, light.target - light.position) : glm::dvec3(0.0);
    view.fit = fitLight(light, objects, camera.viewProjection, mapSize, within, mapUp);
    const bool seen = view.fit.seenFarDepth > 0.0;
    warpView(settings, camera, seen ? std::max(view.fit.seenNearDepth, camera.nearPlane) : camera.nearPlane,
             seen ? view.fit.seenFarDepth : camera.farPlane, view.fit,
             [&] { return fitLight(light, objects, camera.viewProjection, mapSize, within); });
    set.views.push_back(std::move(view));
    return set;
}

} // namespace shadowlab
