#pragma once

#include "FrameStats.h"
#include "LightMath.h"
#include "Settings.h"

#include <QRect>

#include <optional>
#include <vector>

namespace shadowlab {

// Whether `policy` keeps a copy of each view's still casters (static, every-n, on-demand), as
// opposed to none (off) or a virtual map's pages (pages).
inline bool keepsViews(ShadowCachePolicy policy)
{
    return policy == ShadowCachePolicy::Static || policy == ShadowCachePolicy::EveryN || policy == ShadowCachePolicy::OnDemand;
}


// shadow.cache for a light's views (one map, cascades, cube faces), without GL: what each view
// does this frame, from why it would be drawn and the policy, and what each view holds. The
// storages keep the copies (ShadowStorage::drawCached); the renderer runs the decisions. So a
// moving light, a changed setting or a new fit draws everything, and a moving caster only the
// views it touches (where it was, or where it is now), each from its copy of the still casters.
// `rects` merged where they overlap or touch, so that no texel is in two of them.
std::vector<QRect> mergedRects(std::vector<QRect> rects);
// The same, at most `most` of them (1 or more): where more are left, the two whose union grows
// the covered area least are merged first.
std::vector<QRect> fewRects(std::vector<QRect> rects, std::size_t most);

class ShadowCache {
public:
    enum class Work {
        Keep,           // nothing: the tile holds what it should (or, stale, what it held)
        Clear,          // nothing to shadow: read lit
        Draw,           // every caster, no copy (off)
        Refresh,        // still casters, a copy of them, moving casters over it
        Restore,        // the copy back, moving casters over it
    };
    struct Decision {
        Work work = Work::Keep;
        ViewCause cause = ViewCause::Cached;
        // Restore: the texels of the view's square (its own, [0, size)²) that moving casters
        // left or reach now, as rectangles that do not overlap; everything else holds what it
        // should already.
        std::vector<QRect> areas;
    };
    // What a frame brings. `wanted[i]`: view i's volume, nullopt with nothing to shadow.
    // `movingTexels[i]`: where each moving caster lies in view i now (core/CasterTexels.h;
    // none: none there).
    struct Frame {
        ShadowCachePolicy policy = ShadowCachePolicy::Off;
        int interval = 1;                   // every-n
        bool fresh = false;                 // what every view shares changed: all are drawn
        ViewCause freshCause = ViewCause::New;
        bool castersMoved = false;          // a moving caster is elsewhere than last frame
        bool requested = false;             // on-demand: draw what is stale (Renderer::requestShadowRedraw)
        std::vector<std::optional<LightVolume>> wanted;
        std::vector<std::vector<QRect>> movingTexels;
        // `readTexels[i]`: the texels of view i the frame's pixels may read (core/CasterTexels.h
        // readTexels); a view past its end is read everywhere. A moving caster's move that no
        // pixel reads leaves the view as it is, marked unseen, until one does.
        std::vector<QRect> readTexels;
    };
    std::vector<Decision> decide(const Frame& frame);
    // After view i's work: the volume it was drawn at (nullopt: cleared), and where moving
    // casters are in its square now (empty: none drawn).
    void done(std::size_t i, const Decision& decision, const std::optional<LightVolume>& volume, const std::vector<QRect>& moving);
    // Every view forgotten: the next frame draws all.
    void reset() { m_views.clear(); }
    // The views it knows (0 after reset()).
    std::size_t viewCount() const { return m_views.size(); }

private:
    struct View {
        std::optional<LightVolume> volume;  // as drawn; nullopt: cleared
        std::vector<QRect> moving;          // where moving casters were drawn into it
        bool stale = false;                 // a moving caster moved since its last draw, and it was kept
        bool unseen = false;                // ... where no pixel read it
        bool owed = false;                  // ... on a frame that was due to draw it (every-n, on-demand)
    };
    std::vector<View> m_views;
    int m_movedFrames = 0;                  // every-n: frames of moving casters since they were last drawn
};

} // namespace shadowlab
