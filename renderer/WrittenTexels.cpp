#include "WrittenTexels.h"

namespace shadowlab {

void WrittenTexels::reset(int size, int columns, int rows)
{
    m_size = size;
    m_columns = columns;
    m_tiles.clear();
    for (int row = 0; row < rows; ++row) {
        for (int column = 0; column < columns; ++column)
            m_tiles.emplace_back(column * size, row * size, size, size);
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
    for (QRect& tile : m_tiles) {
        if (rect.contains(tile))
            tile = QRect();
    }
}

void WrittenTexels::drew(const QRect& rect)
{
    const int i = index(rect);
    if (i >= 0)
        m_tiles[std::size_t(i)] |= rect;
}

} // namespace shadowlab
