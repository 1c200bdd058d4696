#pragma once

#include "DepthViewPass.h"
#include "LightMath.h"
#include "VirtualPoolPicture.h"

#include <glm/vec2.hpp>

#include <QColor>
#include <QPointF>
#include <QRect>
#include <QRectF>
#include <QSize>

#include <optional>
#include <utility>
#include <vector>

class QPainter;

namespace shadowlab {

class Renderer;

// What the depth-map picture says besides the map itself.
struct DepthMapFacts {
    LightFrame light;
    std::optional<DepthSpan> span;          // the written depths the ramp is stretched over
    bool fitted = false;                    // light.fit=scene shaped the volume
    std::vector<glm::dvec2> footprint;      // the camera's visible region, map coordinates
    int mapSize = 0;
    int moment = 0;                         // 1-4: the pane shows that moment of a moments map, in grey
    int views = 1;                          // cascades or cube faces in tiles of the map
    int columns = 1;                        // ... laid out in this many columns
    int rows = 1;                           // ... and rows
    double aspect = 1.0;                    // width over height of the picture of the whole map
    // shadow.virtual: the map is the pool of pages, drawn with their levels and counts instead
    // of a light volume and the camera's region.
    std::optional<VirtualPoolFacts> pool;
    QString redrawn;                        // what moved and redrew the map last frame (redrawStatusText()); empty when nothing did
    // shadow.cache: why each view (or a virtual map's page) holds what it holds, over its square
    // of the map (map coordinates, y up): Unreal's cache visualisation.
    struct CacheTile {
        QRectF rect;
        ViewCause cause = ViewCause::Cached;
    };
    std::vector<CacheTile> cacheTiles;
};

// The colour of a cause in the depth pane's cache view.
QColor cacheColour(ViewCause cause);

// The facts of `renderer`'s last frame, with `span` measured by whoever draws, and the map
// point under the pointer where there is one (a virtual pool's slot is picked by it).
DepthMapFacts depthMapFacts(const Renderer& renderer, const std::optional<DepthSpan>& span, const std::optional<QPointF>& pointer = std::nullopt);

// What the light volume's label in the picture says, longest first (the longest that fits is
// drawn): its kind and size, and the map's texels; for several views, how they are laid out.
QStringList volumeTexts(const DepthMapFacts& facts);

// Distance from the light along its axis of a conventional [0, 1] depth: linear for an ortho
// light, the perspective depth curve inverted for a perspective one. A warped map's
// (light.warp) scale of depth varies over the map: there it needs the texel's `uv` in [0, 1]^2,
// and without one it is NaN.
double depthToDistance(const LightFrame& light, double depth, const std::optional<glm::dvec2>& uv = std::nullopt);

// The readable depth map, one layout for the explorer's pane and for `render --depth-out`: the
// map at the light volume's real aspect over the map area, and below it a legend (the colour
// bar from near to far in depth and in world distance from the light, and the hatching that
// means "empty: far plane"). Over the map: the light volume's outline with its size, and the
// camera's visible region. The GL side (map, colour bar) is DepthViewPass's; paint() writes
// the rest with QPainter, in logical pixels, y down.
class DepthMapPicture {
public:
    static constexpr int kLegendHeight = 58;

    explicit DepthMapPicture(QSize size) : m_size(size) {}

    QRect mapArea() const;
    QRect legendBar() const;
    // Width over height of the light volume (ortho: world units; perspective: tangents).
    static double aspect(const LightFrame& light);
    // The part of the map shown over mapArea() at `zoom` (1: the whole map fits) around `centre`.
    QRectF visible(double aspect, double zoom, QPointF centre) const;
    // What the picture frames before any zoom or pan, in map coordinates: the map, with a thin
    // margin, so it fills the picture along its tighter side. The camera's footprint is drawn
    // over it, cut at the picture's edge with a marker where it leaves.
    static QRectF homeRegion();
    // The map together with the camera's footprint, so the map is seen where it lies in what the
    // camera sees (View → Frame Camera Footprint). A footprint far larger than the map is cut at
    // kFrameLimit map sides around it, so the map keeps half the picture's side.
    static QRectF footprintRegion(const DepthMapFacts& facts);
    static constexpr double kFrameLimit = 0.5;     // map sides beyond each edge of the map
    // The zoom and centre at which visible() shows `region` whole.
    std::pair<double, QPointF> framing(double aspect, const QRectF& region) const;
    // `region` shown whole at the facts' aspect: what the picture shows before any zoom or pan.
    QRectF regionVisible(const DepthMapFacts& facts, const QRectF& region) const;
    QRectF homeVisible(const DepthMapFacts& facts) const { return regionVisible(facts, homeRegion()); }
    QPointF toPixel(QPointF mapPoint, const QRectF& visible) const;
    QPointF toMap(QPointF pixel, const QRectF& visible) const;
    // `rect` in GL viewport pixels (y up) of a framebuffer `devicePixelRatio` times this size.
    QRect glViewport(const QRect& rect, double devicePixelRatio) const;

    void paint(QPainter& painter, const DepthMapFacts& facts, const QRectF& visible) const;

    // "0.1234 · 3.21 wu": a depth and its distance from the light, as the legend writes them,
    // with `decimals` for the depth (more where near and far differ only far down).
    static QString depthText(const LightFrame& light, double depth, int decimals = 4);
    // Decimals at which the depths `a` and `b` read apart (4 at least, 9 at most).
    static int depthDecimals(double a, double b);

private:
    QSize m_size;
};

} // namespace shadowlab
