#pragma once

#include "FrameStats.h"
#include "VirtualPages.h"

#include <QColor>
#include <QPointF>
#include <QRect>
#include <QRectF>
#include <QString>

#include <functional>
#include <optional>
#include <vector>

class QPainter;

namespace shadowlab {

class Renderer;

// What the depth pane shows of a virtual map's pool (shadow.virtual): the page each slot holds
// and its level, this frame's counts, and the page table of one level.
struct VirtualPoolFacts {
    struct Slot {
        int slot = 0;
        VirtualPage page;
    };
    int poolSide = 0;                   // slots per side of the pool (the map)
    int levels = 1;
    std::vector<Slot> resident;
    VirtualMapStats counts;             // the last frame's
    std::vector<glm::ivec2> windows;    // each level's window origin, in pages of its grid
    std::optional<int> pointerSlot;     // the slot under the pointer, if one holds a page
    int tableLevel = -1;                // the level whose page table is shown: the pointer's, else the finest resident
};

// The pool of `renderer`'s last frame, with the slot under `pointer` (map coordinates of the
// pool, [0, 1]² y up) when given; nullopt when the last frame drew no virtual map.
std::optional<VirtualPoolFacts> virtualPoolFacts(const Renderer& renderer, const std::optional<QPointF>& pointer = std::nullopt);

// The slot whose square holds `uv` (map coordinates of the pool), or nullopt outside the pool.
std::optional<int> poolSlotAt(int poolSide, QPointF uv);

// The tint of a level, as the lit pass's shadow.show_cascades draws it (viewTint).
QColor levelTint(int level);

// "312 of 900 slots resident · 305 requested · 2 drawn this frame", and what was coarsened.
QString virtualPoolSummary(const VirtualPoolFacts& facts);
// "slot 17: level 3, page 41, 38", for the texel read-out.
QString virtualSlotText(const VirtualPoolFacts& facts, int slot);

// Over the pool's picture in `area` (logical pixels, y down; `toPixel` maps pool coordinates
// there): each resident slot tinted by its level, the pointer's outlined, the counts at the top
// and, in a corner, the page table of facts.tableLevel with the pointer's page marked.
void paintVirtualPool(QPainter& painter, const QRect& area, const std::function<QPointF(QPointF)>& toPixel, const VirtualPoolFacts& facts);

} // namespace shadowlab
