#include "WrittenTexels.h"

#include "CasterTexels.h"

namespace shadowlab {

void WrittenTexels::reset(int size, int columns, int rows)
{
    m_size = size;
    m_columns = columns;
    m_tiles.clear();
    m_pieces.clear();
    for (int row = 0; row < rows; ++row) {
        for (int column = 0; column < columns; ++column) {
            m_tiles.emplace_back(column * size, row * size, size, size);
            m_pieces.push_back({m_tiles.back()});
        }
    }
}

int WrittenTexels::index(const QRect& rect) const
{
    if (m_size <= 0 || rect.isEmpty())
        return -1;
    const int i = rect.x() / m_size + rect.y() / m_size * m_columns;
    return i >= 0 && i < int(m_tiles.size()) ? i : -1;
}

QRect WrittenTexels::written(const QRect& tile) const
{
    const int i = index(tile);
    return i < 0 ? tile : m_tiles[std::size_t(i)] & tile;
}

QRect WrittenTexels::toClear(const QRect& tile, const QRect& drawn) const
{
    return (written(tile) | drawn) & tile;
}

void WrittenTexels::cleared(const QRect& rect)
{
    for (std::size_t i = 0; i < m_tiles.size(); ++i) {
        if (rect.contains(m_tiles[i])) {
            m_tiles[i] = QRect();
            m_pieces[i].clear();
        }
    }
}

void WrittenTexels::drew(const QRect& rect)
{
    const int i = index(rect);
    if (i < 0)
        return;
    QRect& bounds = m_tiles[std::size_t(i)];
    std::vector<QRect>& pieces = m_pieces[std::size_t(i)];
    bounds |= rect;
    if (pieces.size() < kMostPieces)
        pieces.push_back(rect);
    else
        pieces.assign(1, bounds);
}

std::vector<QRect> WrittenTexels::piecesToClear(const QRect& tile, const std::vector<QRect>& drawn, std::size_t most) const
{
    const int i = index(tile);
    std::vector<QRect> rects = i < 0 ? std::vector<QRect>{tile} : m_pieces[std::size_t(i)];
    rects.insert(rects.end(), drawn.begin(), drawn.end());
    for (QRect& r : rects)
        r &= tile;
    return joinOverlapping(rects, most);
}

void WrittenTexels::clearedPieces(const QRect& tile)
{
    const int i = index(tile);
    if (i >= 0) {
        m_tiles[std::size_t(i)] = QRect();
        m_pieces[std::size_t(i)].clear();
    }
}

} // namespace shadowlab
