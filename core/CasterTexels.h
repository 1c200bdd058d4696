#pragma once

#include "LightMath.h"
#include "ShadowReach.h"

#include <QRect>
#include <QSize>

#include <optional>

#include <vector>

namespace shadowlab {

// Which texels of one view's map its shadow pass can write: the casters' images, each the
// projection of its box clipped to the view's sides, in whole texels with one of margin for
// the rasteriser's rounding. Everything outside keeps what a clear wrote, so a pass need clear
// and draw no more (renderer/WrittenTexels.h), and a view whose rectangle is empty needs no
// pass at all: its lookups read the cleared far depth, lit. On any rasteriser the clear is
// then the size of the casters, not of the map.
struct CasterTexels {
    // Every caster the pass draws (those `casters` says cast and culledFrom() keeps), in texels
    // of the view's own square [0, mapSize)²; empty: nothing. Outside it a moments map holds
    // the far plane's moments, a constant its blur leaves as it is (without coverage, floors
    // too, drawn as far around each caster as a lookup beside it reads: MomentsPass).
    QRect drawn;
    // Each caster's own rectangle, whose bounds `drawn` is.
    std::vector<QRect> pieces;

    void add(const CasterTexels& other);
};

CasterTexels casterTexels(const LightFrame& view, int mapSize, const std::vector<ReachObject>& casters);

// `rects` with those that overlap merged into their bounds, until none do, so that no texel is
// in two; past `most`, their bounds (core/JoinOverlapping.h). Empty ones are dropped.
std::vector<QRect> joinOverlapping(const std::vector<QRect>& rects, std::size_t most);

// The casters' rectangles grown by `margin` texels, cut to `within` and joined where they
// overlap (joinOverlapping): where a pass draws, clears and, for a moments map without
// coverage, draws floors (renderer/MomentsPass.h).
std::vector<QRect> aroundCasters(const CasterTexels& texels, int margin, const QRect& within, std::size_t most);

// Which texels of one view's map the camera's pixels may read: the image of the camera's
// frustum cut to `receivers` (the box around every receiver), grown by `margin` texels for
// how far a lookup reads around its point (lookupReachTexels). A moving caster's texels
// outside it change no pixel of the frame, so shadow.cache may leave them for a frame that
// reads them (renderer/ShadowCache.h). Empty: the frame reads nothing of the view.
QRect readTexels(const LightFrame& view, int mapSize, const CameraFrame& camera, const Bounds& receivers, double margin);

// The pixels of a `size` viewport (OpenGL's window coordinates: x right, y up from the bottom
// left) that `box` can cover through `viewProjection`, with a pixel of margin for rounding;
// nullopt where it reaches behind the camera, so that any pixel may be. Empty: none.
std::optional<QRect> windowPixels(const Bounds& box, const glm::dmat4& viewProjection, QSize size);

} // namespace shadowlab
