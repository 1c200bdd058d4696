#include "ShadowCache.h"

#include <algorithm>
#include <limits>

namespace shadowlab {

QString toString(ViewCause cause)
{
    switch (cause) {
    case ViewCause::Cached:
        return QStringLiteral("cached");
    case ViewCause::Stale:
        return QStringLiteral("stale");
    case ViewCause::Unseen:
        return QStringLiteral("out of sight");
    case ViewCause::Casters:
        return QStringLiteral("caster moved");
    case ViewCause::Light:
        return QStringLiteral("light moved");
    case ViewCause::New:
        return QStringLiteral("new");
    }
    return {};
}

namespace {

QRect boundingRect(const std::vector<QRect>& rects)
{
    QRect all;
    for (const QRect& r : rects)
        all |= r;
    return all;
}

} // namespace

std::vector<QRect> mergedRects(std::vector<QRect> rects)
{
    rects.erase(std::remove_if(rects.begin(), rects.end(), [](const QRect& r) { return r.isEmpty(); }), rects.end());
    // Each merge scans the pairs again: past a few hundred (as many moving casters in one
    // view), their bounding rectangle stands for them.
    constexpr std::size_t kMostMerged = 256;
    if (rects.size() > kMostMerged)
        return {boundingRect(rects)};
    // Until no two overlap or touch: each merge leaves one fewer.
    for (bool merged = true; merged;) {
        merged = false;
        for (std::size_t a = 0; a < rects.size() && !merged; ++a) {
            for (std::size_t b = a + 1; b < rects.size(); ++b) {
                if (rects[a].adjusted(0, 0, 1, 1).intersects(rects[b])) {
                    rects[a] |= rects[b];
                    rects.erase(rects.begin() + std::ptrdiff_t(b));
                    merged = true;
                    break;
                }
            }
        }
    }
    return rects;
}

std::vector<QRect> fewRects(std::vector<QRect> rects, std::size_t most)
{
    const auto area = [](const QRect& r) { return qint64(r.width()) * r.height(); };
    rects = mergedRects(std::move(rects));
    // Pairs scanned for each merge: beyond a few dozen, one rectangle.
    if (rects.size() > 8 * std::max<std::size_t>(most, 1))
        return {boundingRect(rects)};
    while (rects.size() > std::max<std::size_t>(most, 1)) {
        std::size_t bestA = 0, bestB = 1;
        qint64 bestGrowth = std::numeric_limits<qint64>::max();
        for (std::size_t a = 0; a < rects.size(); ++a) {
            for (std::size_t b = a + 1; b < rects.size(); ++b) {
                const qint64 growth = area(rects[a] | rects[b]) - area(rects[a]) - area(rects[b]);
                if (growth < bestGrowth) {
                    bestGrowth = growth;
                    bestA = a;
                    bestB = b;
                }
            }
        }
        rects[bestA] |= rects[bestB];
        rects.erase(rects.begin() + std::ptrdiff_t(bestB));
        rects = mergedRects(std::move(rects));
    }
    return rects;
}

std::vector<ShadowCache::Decision> ShadowCache::decide(const Frame& frame)
{
    const std::size_t count = frame.wanted.size();
    const bool fresh = frame.fresh || m_views.size() != count;
    if (fresh) {
        m_views.assign(count, View{});
        m_movedFrames = 0;      // every-n counts from the frame that drew everything
    }
    const bool keeps = keepsViews(frame.policy);
    // Whether this frame draws the moving casters where they moved: always (static), every
    // n-th frame that they move or that a view stays stale (every-n), when asked (on-demand).
    bool movingDue = true;
    if (frame.policy == ShadowCachePolicy::EveryN) {
        const bool anyStale = std::any_of(m_views.begin(), m_views.end(), [](const View& v) { return v.stale; });
        if (!fresh && (frame.castersMoved || anyStale)) {
            movingDue = ++m_movedFrames >= frame.interval;
            if (movingDue)
                m_movedFrames = 0;
        }
    } else if (frame.policy == ShadowCachePolicy::OnDemand) {
        movingDue = frame.requested;
    }

    std::vector<Decision> decisions(count);
    for (std::size_t i = 0; i < count; ++i) {
        View& view = m_views[i];
        const std::optional<LightVolume>& wanted = frame.wanted[i];
        const std::vector<QRect> none;
        const std::vector<QRect>& now = i < frame.movingTexels.size() ? frame.movingTexels[i] : none;
        const bool touched = frame.castersMoved && (!now.empty() || !view.moving.empty());
        const bool allRead = i >= frame.readTexels.size();
        Decision& d = decisions[i];
        if (fresh || view.volume != wanted) {
            // A view that gains or loses its only casters as they move changes for them.
            const bool byCasters = !fresh && frame.castersMoved && view.volume.has_value() != wanted.has_value();
            d.cause = fresh ? frame.freshCause : byCasters ? ViewCause::Casters : ViewCause::Light;
            d.work = !wanted ? Work::Clear : keeps ? Work::Refresh : Work::Draw;
        } else if (wanted && keeps && (touched || view.stale || view.unseen)) {
            std::vector<QRect> both = view.moving;
            both.insert(both.end(), now.begin(), now.end());
            d.areas = mergedRects(std::move(both));
            const auto read = [&](const QRect& area) { return allRead || area.intersects(frame.readTexels[i]); };
            if (!std::any_of(d.areas.begin(), d.areas.end(), read)) {
                // Where moving casters were and are, no pixel of the frame reads: it stays
                // as it is until one does (the camera turns there, or a caster moves in),
                // and a redraw due now (every-n's frame, on-demand's request) is owed until then.
                d.work = Work::Keep;
                d.cause = ViewCause::Unseen;
                d.areas.clear();
                view.unseen = true;
                view.owed = view.owed || movingDue;
                continue;
            }
            const bool due = movingDue || view.owed;
            d.work = due ? Work::Restore : Work::Keep;
            d.cause = due ? ViewCause::Casters : ViewCause::Stale;
            view.stale = !due;
        } else {
            d.cause = view.stale ? ViewCause::Stale : ViewCause::Cached;
        }
    }
    return decisions;
}

void ShadowCache::done(std::size_t i, const Decision& decision, const std::optional<LightVolume>& volume, const std::vector<QRect>& moving)
{
    if (decision.work == Work::Keep || i >= m_views.size())
        return;
    View& view = m_views[i];
    view.volume = volume;
    view.moving = moving;
    view.stale = false;
    view.unseen = false;
    view.owed = false;
}

} // namespace shadowlab
