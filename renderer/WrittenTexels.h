#pragma once

#include <QRect>

#include <vector>

namespace shadowlab {

// Which texels of a map of tiles may hold anything but what a clear writes: per tile, the
// rectangles drawn since its last clear and their bounds. A pass then clears what it wrote
// before and what it is about to write (core/CasterTexels.h), not the whole tile: the bounds,
// or a moments map the pieces; a tile nothing was drawn into since its clear needs none. On llvmpipe a clear costs as much as
// drawing the seed's casters (docs/performance.md); a GPU clears faster, but writes and reads
// fewer texels either way.
class WrittenTexels {
public:
    // Contents unknown (a new texture): every tile counts as written.
    void reset(int size, int columns, int rows);
    // What to clear before drawing into `drawn` (map texels, within one tile; may be empty)
    // in `tile`: the bounding rectangle of the tile's written texels and `drawn`.
    QRect toClear(const QRect& tile, const QRect& drawn) const;
    // What is written within `tile`; empty: it reads cleared everywhere.
    QRect written(const QRect& tile) const;
    // The same for every tile, row by row.
    const std::vector<QRect>& writtenTiles() const { return m_tiles; }
    // After a clear of `rect` (one tile or part of it, or the whole map): tiles whose written
    // texels it covers read cleared.
    void cleared(const QRect& rect);
    // After a draw that may have written anywhere in `rect` (within one tile).
    void drew(const QRect& rect);

    // The same in pieces, for a pass whose casters lie apart (renderer/MomentsPass.h): what to
    // clear before drawing into `drawn` in `tile`, the rectangles drawn since the tile's last
    // clear and `drawn`, joined where they overlap (core/CasterTexels.h's joinOverlapping), at
    // most `most`. Once all are cleared, clearedPieces(tile).
    std::vector<QRect> piecesToClear(const QRect& tile, const std::vector<QRect>& drawn, std::size_t most) const;
    void clearedPieces(const QRect& tile);

private:
    int index(const QRect& rect) const;

    // Past it a tile's drawn rectangles are kept as their bounds.
    static constexpr std::size_t kMostPieces = 32;

    int m_size = 0;
    int m_columns = 1;
    std::vector<QRect> m_tiles;
    std::vector<std::vector<QRect>> m_pieces;   // per tile: what was drawn, its bounds m_tiles's
};

} // namespace shadowlab
