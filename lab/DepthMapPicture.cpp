#include "DepthMapPicture.h"

#include "FrameStatsText.h"

#include "Renderer.h"

#include <QPainter>
#include <QPainterPath>
#include <QPolygonF>
#include <QStringList>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace shadowlab {

namespace {

const QColor kTextColour(225, 228, 235);
const QColor kFootprintColour(255, 150, 40);
const QColor kVolumeColour(235, 235, 235);
constexpr int kMargin = 8;

// A world distance with three significant digits at least: 0.00012 wu and 4,870 wu both read.
QString distanceText(double d)
{
    const double magnitude = std::abs(d);
    if (magnitude >= 100.0 || magnitude == 0.0 || !std::isfinite(d))
        return QString::number(d, 'f', magnitude >= 100.0 ? 0 : 2);
    return QString::number(d, 'f', std::clamp(int(std::ceil(-std::log10(magnitude))) + 2, 2, 8));
}

// The first of `texts` that fits `width` pixels, else the last one elided.
QString fitting(const QFontMetrics& metrics, const QStringList& texts, int width)
{
    for (const QString& text : texts) {
        if (metrics.horizontalAdvance(text) <= width)
            return text;
    }
    return metrics.elidedText(texts.last(), Qt::ElideRight, width);
}

// Where the segment from `inside` to `outside` (pixels) leaves `frame`.
QPointF exitPoint(QPointF inside, QPointF outside, const QRectF& frame)
{
    double t = 1.0;
    const QPointF d = outside - inside;
    if (d.x() > 0.0) t = std::min(t, (frame.right() - inside.x()) / d.x());
    if (d.x() < 0.0) t = std::min(t, (frame.left() - inside.x()) / d.x());
    if (d.y() > 0.0) t = std::min(t, (frame.bottom() - inside.y()) / d.y());
    if (d.y() < 0.0) t = std::min(t, (frame.top() - inside.y()) / d.y());
    return inside + d * std::clamp(t, 0.0, 1.0);
}

} // namespace

QColor cacheColour(ViewCause cause)
{
    switch (cause) {
    case ViewCause::Cached:
        return {70, 190, 100};
    case ViewCause::Stale:
        return {235, 170, 40};
    case ViewCause::Unseen:
        return {170, 110, 230};
    case ViewCause::Casters:
        return {225, 60, 70};
    case ViewCause::Light:
        return {80, 140, 240};
    case ViewCause::New:
        return {215, 215, 225};
    }
    return {};
}

namespace {

// Each view's (or page's) square of the map with why it holds what it holds, under shadow.cache.
std::vector<DepthMapFacts::CacheTile> cacheTiles(const Renderer& renderer)
{
    std::vector<DepthMapFacts::CacheTile> tiles;
    if (renderer.lastPlan().cache == ShadowCachePolicy::Off || !renderer.lastPlan().shadows)
        return tiles;
    const FrameStats& stats = renderer.lastFrame();
    const ShadowMap& map = renderer.shadowMap();
    const double columns = std::max(1, map.columns()), rows = std::max(1, map.rows());
    if (renderer.lastPlan().virtualMap) {
        for (const auto& [slot, cause] : stats.pageCauses) {
            const double x = (slot % map.columns()) / columns, y = double(slot / map.columns()) / rows;
            tiles.push_back({QRectF(x, y, 1.0 / columns, 1.0 / rows), cause});
        }
        return tiles;
    }
    const std::vector<ShadowView>& views = renderer.shadowViews().set.views;
    for (std::size_t i = 0; i < stats.viewCauses.size(); ++i) {
        const double x = i < views.size() ? views[i].column / columns : 0.0, y = i < views.size() ? views[i].row / rows : 0.0;
        tiles.push_back({QRectF(x, y, 1.0 / columns, 1.0 / rows), stats.viewCauses[i]});
    }
    return tiles;
}

} // namespace

DepthMapFacts depthMapFacts(const Renderer& renderer, const std::optional<DepthSpan>& span, const std::optional<QPointF>& pointer)
{
    DepthMapFacts facts;
    facts.light = renderer.lightFrame();
    facts.span = span;
    facts.fitted = renderer.lastFit().fitted;
    facts.mapSize = renderer.shadowMap().size();
    facts.moment = renderer.depthMapMoment();
    // What moved, while something does: a new scene or a changed setting goes without saying.
    using Redraw = FrameStats::Redraw;
    const Redraw redraw = renderer.lastFrame().redraw;
    if (redraw == Redraw::Casters || redraw == Redraw::Light || redraw == Redraw::Camera)
        facts.redrawn = redrawStatusText(renderer.lastFrame());
    facts.views = std::max<int>(1, int(renderer.shadowViews().set.views.size()));
    // Several views sit in tiles side by side: the picture is of the whole texture.
    const ShadowMap& map = renderer.shadowMap();
    facts.columns = map.columns();
    facts.rows = map.rows();
    facts.aspect = facts.views > 1 && map.height() > 0 ? double(map.width()) / map.height() : DepthMapPicture::aspect(facts.light);
    // One map: where the camera looks, over it. (Several views side by side each have their own
    // projection; one outline over all of them would be wrong.)
    if (const Scene* scene = renderer.scene(); scene && facts.views == 1)
        facts.footprint = cameraFootprint(scene->bounds(), renderer.cameraFrame().viewProjection, facts.light.shadowMatrix);
    // A virtual map's texture is its pool: square, its slots in no light volume's place.
    facts.pool = virtualPoolFacts(renderer, pointer);
    facts.cacheTiles = cacheTiles(renderer);
    if (facts.pool) {
        facts.footprint.clear();
        facts.aspect = 1.0;
    }
    return facts;
}

double depthToDistance(const LightFrame& light, double depth, const std::optional<glm::dvec2>& uv)
{
    const double n = light.nearPlane, f = light.farPlane;
    double along = light.perspective ? 2.0 * n * f / (f + n - (depth * 2.0 - 1.0) * (f - n)) : n + depth * (f - n);
    if (light.volume.warped) {
        if (!uv)
            return std::nan("");
        // The texel's point in the light's view space: the warp undone.
        const glm::dvec4 p = glm::inverse(light.volume.warp) * glm::dvec4(*uv * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
        along = -p.z / p.w;
    }
    // A fitted ortho volume's near and far count from a point on its axis, not from the light.
    return along + glm::dot(light.volume.origin - light.position, light.volume.direction);
}

QRect DepthMapPicture::mapArea() const
{
    return {0, 0, m_size.width(), std::max(0, m_size.height() - kLegendHeight)};
}

QRect DepthMapPicture::legendBar() const
{
    const int top = mapArea().bottom() + 1 + 22;
    return {kMargin, top, std::max(0, m_size.width() - 2 * kMargin), 12};
}

double DepthMapPicture::aspect(const LightFrame& light)
{
    const double w = light.volume.width(), h = light.volume.height();
    return w > 0.0 && h > 0.0 && std::isfinite(w / h) ? std::clamp(w / h, 1e-3, 1e3) : 1.0;
}

QRectF DepthMapPicture::visible(double aspect, double zoom, QPointF centre) const
{
    const QRect area = mapArea();
    const double w = std::max(1, area.width()), h = std::max(1, area.height());
    // Pixels per unit of map height at this zoom; a unit of map width is `aspect` times as wide.
    const double scale = std::min(w / aspect, h) * zoom;
    const QSizeF extent(w / (aspect * scale), h / scale);
    return {centre - QPointF(extent.width(), extent.height()) * 0.5, extent};
}

QRectF DepthMapPicture::homeRegion()
{
    constexpr double margin = 0.02;
    return QRectF(QPointF(-margin, -margin), QPointF(1.0 + margin, 1.0 + margin));
}

QRectF DepthMapPicture::footprintRegion(const DepthMapFacts& facts)
{
    double x0 = 0.0, y0 = 0.0, x1 = 1.0, y1 = 1.0;
    for (const glm::dvec2& p : facts.footprint) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            continue;
        x0 = std::min(x0, p.x);
        y0 = std::min(y0, p.y);
        x1 = std::max(x1, p.x);
        y1 = std::max(y1, p.y);
    }
    x0 = std::max(x0, -kFrameLimit);
    y0 = std::max(y0, -kFrameLimit);
    x1 = std::min(x1, 1.0 + kFrameLimit);
    y1 = std::min(y1, 1.0 + kFrameLimit);
    // A little room around whatever touches the edge.
    const double margin = 0.03 * std::max(x1 - x0, y1 - y0);
    return QRectF(QPointF(x0 - margin, y0 - margin), QPointF(x1 + margin, y1 + margin));
}

std::pair<double, QPointF> DepthMapPicture::framing(double aspect, const QRectF& region) const
{
    const QSizeF whole = visible(aspect, 1.0, {0.5, 0.5}).size();   // at zoom 1 the map just fits
    const double zoom = std::min(whole.width() / std::max(region.width(), 1e-9), whole.height() / std::max(region.height(), 1e-9));
    return {std::clamp(zoom, 1e-3, 1.0), region.center()};
}

QRectF DepthMapPicture::regionVisible(const DepthMapFacts& facts, const QRectF& region) const
{
    const auto [zoom, centre] = framing(facts.aspect, region);
    return visible(facts.aspect, zoom, centre);
}

QPointF DepthMapPicture::toPixel(QPointF p, const QRectF& visible) const
{
    const QRect area = mapArea();
    return {area.x() + (p.x() - visible.x()) / visible.width() * area.width(),
            area.y() + (1.0 - (p.y() - visible.y()) / visible.height()) * area.height()};
}

QPointF DepthMapPicture::toMap(QPointF pixel, const QRectF& visible) const
{
    const QRect area = mapArea();
    return {visible.x() + (pixel.x() - area.x()) / std::max(1, area.width()) * visible.width(),
            visible.y() + (1.0 - (pixel.y() - area.y()) / std::max(1, area.height())) * visible.height()};
}

QRect DepthMapPicture::glViewport(const QRect& rect, double dpr) const
{
    return {int(std::lround(rect.x() * dpr)), int(std::lround((m_size.height() - rect.y() - rect.height()) * dpr)),
            int(std::lround(rect.width() * dpr)), int(std::lround(rect.height() * dpr))};
}

QString DepthMapPicture::depthText(const LightFrame& light, double depth, int decimals)
{
    if (light.volume.warped)    // no one distance for a depth over a warped map
        return QString::number(depth, 'f', decimals);
    return QStringLiteral("%1 · %2 wu").arg(depth, 0, 'f', decimals).arg(distanceText(depthToDistance(light, depth)));
}

int DepthMapPicture::depthDecimals(double a, double b)
{
    const double apart = std::abs(a - b);
    return apart > 0.0 && std::isfinite(apart) ? std::clamp(int(std::ceil(-std::log10(apart))) + 1, 4, 9) : 4;
}

QStringList volumeTexts(const DepthMapFacts& facts)
{
    const LightVolume& v = facts.light.volume;
    const QString size = v.perspective ? QStringLiteral("%1° × %2°")
                                             .arg(glm::degrees(std::atan(v.right) - std::atan(v.left)), 0, 'f', 0)
                                             .arg(glm::degrees(std::atan(v.top) - std::atan(v.bottom)), 0, 'f', 0)
                                       : QStringLiteral("%1 × %2 wu%3").arg(v.width(), 0, 'f', 2).arg(v.height(), 0, 'f', 2)
                                             .arg(v.warped ? QStringLiteral(", lispsm-warped") : QString());
    const QString kind = facts.fitted ? QStringLiteral("fitted") : QStringLiteral("manual");
    const QString volumeText = facts.views > 1
        ? (facts.rows > 1 ? QStringLiteral("%1 views in a %2 × %3 grid, %4 × %4 texels each").arg(facts.views).arg(facts.columns).arg(facts.rows).arg(facts.mapSize)
                          : QStringLiteral("%1 views side by side, %2 × %2 texels each").arg(facts.views).arg(facts.mapSize))
        : QStringLiteral("%1 light volume %2, %3 × %3 texels").arg(kind, size).arg(facts.mapSize);
    return {volumeText, QStringLiteral("%1 light volume %2").arg(kind, size), size};
}

namespace {

// What the steps of DepthMapPicture::paint() draw with: the painter, the label font's metrics
// and the map's area.
struct Canvas {
    QPainter& painter;
    const QFontMetrics& metrics;
    QRect area;
};

// The light volume: the map's border, dashed, and its label in the top corner.
void drawVolume(const Canvas& c, const QRectF& border, const DepthMapFacts& facts)
{
    QPainter& painter = c.painter;
    const QFontMetrics& metrics = c.metrics;
    painter.setPen(QPen(kVolumeColour, 1.0, Qt::DashLine));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(border);
    // On a dark plate, so it reads over the map's brightest depths and never runs past the pane.
    const int labelRoom = std::max(0, c.area.width() - 16);
    const QString volumeShown = fitting(metrics, volumeTexts(facts), labelRoom);
    const QPointF volumeLabel(std::max(border.left(), double(c.area.left())) + 6, std::max(border.top(), double(c.area.top())) + 6 + metrics.ascent());
    const double volumeX = std::min(volumeLabel.x(), double(c.area.right()) - 6 - metrics.horizontalAdvance(volumeShown));
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0, 0, 0, 150));
    painter.drawRoundedRect(QRectF(volumeX - 3, volumeLabel.y() - metrics.ascent() - 2, metrics.horizontalAdvance(volumeShown) + 6, metrics.height() + 3), 3, 3);
    painter.setBrush(Qt::NoBrush);
    painter.setPen(kVolumeColour);
    painter.drawText(QPointF(volumeX, volumeLabel.y()), volumeShown);
}

// Where the footprint `polygon` (pixels) leaves `frame`: an arrowhead on the edge, pointing the way out.
void drawExitArrows(QPainter& painter, const QPolygonF& polygon, const QRectF& frame)
{
    painter.setPen(Qt::NoPen);
    painter.setBrush(kFootprintColour);
    for (qsizetype i = 0; i < polygon.size(); ++i) {
        const QPointF a = polygon[i], b = polygon[(i + 1) % polygon.size()];
        if (frame.contains(a) == frame.contains(b))
            continue;
        const QPointF in = frame.contains(a) ? a : b, out = frame.contains(a) ? b : a;
        const QPointF tip = exitPoint(in, out, frame);
        QPointF dir = out - in;
        dir /= std::max(1e-9, std::hypot(dir.x(), dir.y()));
        const QPointF side(-dir.y(), dir.x());
        painter.drawPolygon(QPolygonF{tip, tip - dir * 10.0 + side * 5.0, tip - dir * 10.0 - side * 5.0});
    }
    painter.setBrush(Qt::NoBrush);
}

// The footprint's label at the polygon's lowest point on screen, kept inside the pane; `cut`
// when the footprint goes on beyond the picture.
void drawFootprintLabel(const Canvas& c, const QPolygonF& polygon, bool cut)
{
    const QFontMetrics& metrics = c.metrics;
    const QRect& area = c.area;
    const QPointF anchor = *std::max_element(polygon.begin(), polygon.end(), [](QPointF a, QPointF b) { return a.y() < b.y(); });
    // The longest that fits: a narrow pane (compare mode) still reads what it is.
    const QString text = cut ? fitting(metrics, {QStringLiteral("what the camera sees (it goes on beyond the frame)"),
                                                 QStringLiteral("what the camera sees (and beyond)"), QStringLiteral("what the camera sees")},
                                       std::max(0, area.width() - 8))
                             : fitting(metrics, {QStringLiteral("what the camera sees")}, std::max(0, area.width() - 8));
    const double width = metrics.horizontalAdvance(text);
    const double x = std::max(double(area.left() + 4), std::min(anchor.x() - width / 2.0, double(area.right() - 4) - width));
    const double y = std::clamp(anchor.y() + metrics.ascent() + 3, double(area.top() + metrics.ascent() + 4), double(area.bottom() - 4));
    c.painter.setPen(QColor(0, 0, 0, 160));
    c.painter.drawText(QPointF(x + 1, y + 1), text);
    c.painter.setPen(kFootprintColour);
    c.painter.drawText(QPointF(x, y), text);
}

// The camera's visible region over the map, where it has one.
void drawFootprint(const Canvas& c, const DepthMapPicture& picture, const DepthMapFacts& facts, const QRectF& visible)
{
    if (facts.footprint.size() < 3)
        return;
    QPolygonF polygon;
    bool cut = false;
    for (const glm::dvec2& p : facts.footprint) {
        polygon << picture.toPixel({p.x, p.y}, visible);
        cut = cut || !visible.contains(QPointF(p.x, p.y));
    }
    c.painter.setPen(QPen(kFootprintColour, 2.0));
    c.painter.drawPolygon(polygon);
    drawExitArrows(c.painter, polygon, QRectF(c.area).adjusted(1, 1, -1, -1));
    drawFootprintLabel(c, polygon, cut);
}

// Where the picture shows beyond the map: lit, as clamp-to-border makes it. Said in the top
// corner when it lies outside the map (the camera's label takes the bottom).
void drawOutsideNote(const Canvas& c, const DepthMapPicture& picture, const QRectF& visible)
{
    const QString outside = QStringLiteral("outside the map: lit");
    const QRectF outsideBox(c.area.left() + 4, c.area.top() + 4, c.metrics.horizontalAdvance(outside), c.metrics.height());
    const QRectF outsideMap(picture.toMap(outsideBox.bottomLeft(), visible), picture.toMap(outsideBox.topRight(), visible));
    if (!outsideMap.intersects(QRectF(0.0, 0.0, 1.0, 1.0))) {
        c.painter.setPen(QColor(150, 156, 170));
        c.painter.drawText(outsideBox, Qt::AlignLeft | Qt::AlignVCenter, outside);
    }
}

// Why the last frame drew the map, in the top right corner: a moving caster's footprint is
// redrawn as it moves, and the pane says so.
void drawRedrawNote(const Canvas& c, const DepthMapFacts& facts)
{
    if (facts.redrawn.isEmpty())
        return;
    const QString text = c.metrics.elidedText(facts.redrawn, Qt::ElideRight, std::max(0, c.area.width() / 2 - 8));
    const QRectF box(c.area.right() - 4 - c.metrics.horizontalAdvance(text), c.area.top() + 4, c.metrics.horizontalAdvance(text), c.metrics.height());
    c.painter.fillRect(box.adjusted(-3, 0, 3, 0), QColor(30, 32, 40, 170));
    c.painter.setPen(QColor(235, 200, 120));
    c.painter.drawText(box, Qt::AlignRight | Qt::AlignVCenter, text);
}

// shadow.cache: each view or page tinted by why it holds what it holds, and a key with the counts
// in the bottom left corner.
void drawCacheTiles(const Canvas& c, const DepthMapPicture& picture, const QRectF& visible, const DepthMapFacts& facts)
{
    if (facts.cacheTiles.empty())
        return;
    std::map<ViewCause, int> counts;
    for (const DepthMapFacts::CacheTile& tile : facts.cacheTiles) {
        QColor fill = cacheColour(tile.cause);
        const QRectF pixels = QRectF(picture.toPixel(tile.rect.topLeft(), visible), picture.toPixel(tile.rect.bottomRight(), visible)).normalized();
        QColor edge = fill;
        fill.setAlpha(tile.cause == ViewCause::Cached ? 35 : 70);     // the depths stay readable under the tint
        c.painter.fillRect(pixels, fill);
        c.painter.setPen(QPen(edge, 1.5));
        c.painter.drawRect(pixels.adjusted(1, 1, -1, -1));
        ++counts[tile.cause];
    }
    const int line = c.metrics.height();
    int y = c.area.bottom() - 4 - line * int(counts.size());
    for (const auto& [cause, count] : counts) {
        const QString text = QStringLiteral("%1 %2").arg(count).arg(toString(cause));
        const QRectF box(c.area.left() + 4 + line, y, c.metrics.horizontalAdvance(text), line);
        c.painter.fillRect(QRectF(c.area.left() + 2, y, line + box.width() + 4, line), QColor(30, 32, 40, 170));
        c.painter.fillRect(QRectF(c.area.left() + 5, y + 2, line - 4, line - 4), cacheColour(cause));
        c.painter.setPen(QColor(230, 230, 235));
        c.painter.drawText(box, Qt::AlignLeft | Qt::AlignVCenter, text);
        y += line;
    }
}

// What the colour bar shows, longest first.
QStringList legendTitles(const DepthMapFacts& facts)
{
    if (facts.moment == 1)
        return {QStringLiteral("moments map, first moment: depth from near (black) to far (white)"),
                QStringLiteral("first moment: depth, near to far"), QStringLiteral("first moment")};
    if (facts.moment > 1)
        return {QStringLiteral("moments map, moment %1 (grey, 0 to 1)").arg(facts.moment), QStringLiteral("moment %1 (0 to 1)").arg(facts.moment)};
    if (facts.span)
        return {QStringLiteral("depth from the light · stretched to the map's contents"), QStringLiteral("depth from the light, stretched"),
                QStringLiteral("depth")};
    return {QStringLiteral("nothing drawn into the map"), QStringLiteral("empty map")};
}

// The legend's first row: its title, and the swatch of an empty texel with its words, each
// shortened to what the pane's width leaves them.
void drawLegendTitle(const Canvas& c, const QRect& legend, const DepthMapFacts& facts)
{
    QPainter& painter = c.painter;
    const QFontMetrics& metrics = c.metrics;
    const int titleBaseline = legend.top() + 6 + metrics.ascent();
    const int width = std::max(0, legend.width() - 2 * kMargin);
    const QString empty = fitting(metrics, {QStringLiteral("empty: far plane, lit"), QStringLiteral("empty: lit")}, width / 3);
    const QRect swatch(legend.right() - kMargin - metrics.horizontalAdvance(empty) - 18, legend.top() + 6, 14, metrics.height() - 2);
    painter.setPen(kTextColour);
    const int titleRoom = swatch.left() - kMargin - 6;
    painter.drawText(QRect(legend.left() + kMargin, legend.top() + 6, titleRoom, metrics.height()), Qt::AlignLeft | Qt::AlignVCenter,
                     fitting(metrics, legendTitles(facts), titleRoom));
    painter.fillRect(swatch, QColor(77, 77, 77));
    painter.fillRect(swatch, QBrush(QColor(90, 90, 90), Qt::BDiagPattern));
    painter.drawText(QPointF(swatch.right() + 5, titleBaseline), empty);
}

// The colour bar's frame (its ramp is GL's; a moments map's grey is drawn here) and near and far
// under its ends.
void drawLegendBar(const Canvas& c, const QRect& bar, const DepthMapFacts& facts)
{
    QPainter& painter = c.painter;
    const QFontMetrics& metrics = c.metrics;
    if (facts.moment > 0) {
        // A moments map is drawn in grey over the light volume's whole depth range: the bar
        // says so instead of the depth ramp.
        QLinearGradient grey(bar.topLeft(), bar.topRight());
        grey.setColorAt(0.0, Qt::black);
        grey.setColorAt(1.0, Qt::white);
        painter.fillRect(bar, grey);
    }
    painter.setPen(QPen(kTextColour, 1.0));
    painter.drawRect(QRectF(bar).adjusted(-0.5, -0.5, 0.5, 0.5));
    const DepthSpan span = facts.moment > 0 ? DepthSpan{0.0, 1.0} : facts.span.value_or(DepthSpan{});
    const int rowBaseline = bar.bottom() + 3 + metrics.ascent();
    // As many decimals as make near and far read apart (a perspective map packs its depths near 1).
    const int decimals = DepthMapPicture::depthDecimals(span.nearest, span.farthest);
    QString nearText = facts.moment > 1 ? QStringLiteral("0") : QStringLiteral("near %1").arg(DepthMapPicture::depthText(facts.light, span.nearest, decimals));
    QString farText = facts.moment > 1 ? QStringLiteral("1") : QStringLiteral("far %1").arg(DepthMapPicture::depthText(facts.light, span.farthest, decimals));
    if (facts.moment <= 1 && !facts.light.volume.warped && metrics.horizontalAdvance(nearText) + metrics.horizontalAdvance(farText) + 12 > bar.width()) {
        // A narrow pane: the world distances only (the depths are in the PNG's text and the tooltip).
        nearText = QStringLiteral("near %1 wu").arg(distanceText(depthToDistance(facts.light, span.nearest)));
        farText = QStringLiteral("far %1 wu").arg(distanceText(depthToDistance(facts.light, span.farthest)));
    }
    painter.drawText(QPointF(bar.left(), rowBaseline), nearText);
    painter.drawText(QPointF(bar.right() - metrics.horizontalAdvance(farText), rowBaseline), farText);
}

} // namespace

void DepthMapPicture::paint(QPainter& painter, const DepthMapFacts& facts, const QRectF& visible) const
{
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    QFont font = painter.font();
    font.setPixelSize(11);
    painter.setFont(font);
    const QFontMetrics metrics(font);
    const Canvas canvas{painter, metrics, mapArea()};

    // Over the map: the light volume (the map's border) and the camera's visible region.
    painter.setClipRect(canvas.area);
    if (facts.pool) {
        paintVirtualPool(painter, canvas.area, [&](QPointF p) { return toPixel(p, visible); }, *facts.pool);
    } else {
        drawVolume(canvas, QRectF(toPixel({0.0, 1.0}, visible), toPixel({1.0, 0.0}, visible)), facts);
        drawFootprint(canvas, *this, facts, visible);
    }
    drawCacheTiles(canvas, *this, visible, facts);
    drawOutsideNote(canvas, *this, visible);
    drawRedrawNote(canvas, facts);
    painter.setClipping(false);

    // The legend, on the pane's clear colour: title and the empty swatch, the colour bar (drawn
    // by GL), near and far.
    drawLegendTitle(canvas, QRect(0, canvas.area.bottom() + 1, m_size.width(), kLegendHeight), facts);
    drawLegendBar(canvas, legendBar(), facts);
    painter.restore();
}

} // namespace shadowlab
