#pragma once

#include <cstddef>
#include <vector>

namespace shadowlab {

// `rects` with those that `overlap` joined into one (`join(a, b)` grows a by b), until none do;
// more than `most` left, or more than four times as many given (the joining is quadratic): all of
// them joined into one. For the shadow reach's columns (core/ShadowReach.cpp) and a pass's pieces
// around its casters (core/CasterTexels.h).
template <typename Rect, typename Overlap, typename Join>
std::vector<Rect> joinOverlapping(std::vector<Rect> rects, std::size_t most, Overlap overlap, Join join)
{
    for (bool joined = rects.size() <= 4 * most; joined;) {
        joined = false;
        for (std::size_t i = 0; i < rects.size() && !joined; ++i) {
            for (std::size_t j = i + 1; j < rects.size(); ++j) {
                if (overlap(rects[i], rects[j])) {
                    join(rects[i], rects[j]);
                    rects.erase(rects.begin() + std::ptrdiff_t(j));
                    joined = true;
                    break;
                }
            }
        }
    }
    if (rects.size() > most) {
        Rect all = rects.front();
        for (std::size_t i = 1; i < rects.size(); ++i)
            join(all, rects[i]);
        rects.assign(1, all);
    }
    return rects;
}

} // namespace shadowlab
