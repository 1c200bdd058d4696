#include "VirtualPoolPicture.h"

#include "Renderer.h"
#include "ShaderConstants.h"

#include <QFontMetrics>
#include <QImage>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

const QColor kTextColour(226, 228, 234);
const QColor kPlateColour(0, 0, 0, 160);

// Text on a dark plate at `at` (its baseline's left), kept inside `area`.
void plateText(QPainter& painter, const QRect& area, QPointF at, const QString& text)
{
    const QFontMetrics metrics(painter.font());
    const QString shown = metrics.elidedText(text, Qt::ElideRight, std::max(0, area.width() - 16));
    const double x = std::min(at.x(), double(area.right()) - 8 - metrics.horizontalAdvance(shown));
    painter.setPen(Qt::NoPen);
    painter.setBrush(kPlateColour);
    painter.drawRoundedRect(QRectF(x - 3, at.y() - metrics.ascent() - 2, metrics.horizontalAdvance(shown) + 6, metrics.height() + 3), 3, 3);
    painter.setBrush(Qt::NoBrush);
    painter.setPen(kTextColour);
    painter.drawText(QPointF(x, at.y()), shown);
}

const VirtualPoolFacts::Slot* slotEntry(const VirtualPoolFacts& facts, int slot)
{
    const auto it = std::find_if(facts.resident.begin(), facts.resident.end(), [&](const VirtualPoolFacts::Slot& s) { return s.slot == slot; });
    return it == facts.resident.end() ? nullptr : &*it;
}

// The page table of one level: a texel per page of its window, resident ones in its tint.
QImage pageTableImage(const VirtualPoolFacts& facts, int level)
{
    QImage table(kVirtualLevelPages, kVirtualLevelPages, QImage::Format_ARGB32_Premultiplied);
    table.fill(QColor(28, 30, 38));
    if (level < 0 || level >= int(facts.windows.size()))
        return table;
    const glm::ivec2 window = facts.windows[std::size_t(level)];
    const QColor tint = levelTint(level);
    const VirtualPoolFacts::Slot* pointer = facts.pointerSlot ? slotEntry(facts, *facts.pointerSlot) : nullptr;
    for (const VirtualPoolFacts::Slot& s : facts.resident) {
        const int x = s.page.x - window.x, y = s.page.y - window.y;
        if (s.page.level != level || x < 0 || y < 0 || x >= kVirtualLevelPages || y >= kVirtualLevelPages)
            continue;
        table.setPixelColor(x, kVirtualLevelPages - 1 - y, pointer && pointer->slot == s.slot ? QColor(Qt::white) : tint);
    }
    return table;
}

// A swatch of each level's tint with its resident pages, on one plate: the key to the slots'
// colours.
void drawLevelSwatches(QPainter& painter, const QRect& area, QPointF at, const VirtualPoolFacts& facts)
{
    std::vector<int> perLevel(std::size_t(std::max(facts.levels, 1)), 0);
    for (const VirtualPoolFacts::Slot& s : facts.resident) {
        if (s.page.level >= 0 && s.page.level < int(perLevel.size()))
            ++perLevel[std::size_t(s.page.level)];
    }
    const QFontMetrics metrics(painter.font());
    QString key = QStringLiteral("pages per level:");
    double width = metrics.horizontalAdvance(key);
    std::vector<std::pair<int, QString>> entries;
    for (std::size_t level = 0; level < perLevel.size(); ++level) {
        if (perLevel[level] == 0)
            continue;
        entries.emplace_back(int(level), QStringLiteral("%1: %2").arg(level).arg(perLevel[level]));
        width += 16 + metrics.horizontalAdvance(entries.back().second);
    }
    if (entries.empty())
        return;
    width = std::min(width, double(area.right()) - 8 - at.x());
    painter.setPen(Qt::NoPen);
    painter.setBrush(kPlateColour);
    painter.drawRoundedRect(QRectF(at.x() - 3, at.y() - metrics.ascent() - 2, width + 6, metrics.height() + 3), 3, 3);
    painter.setPen(kTextColour);
    painter.drawText(at, key);
    double x = at.x() + metrics.horizontalAdvance(key) + 6;
    for (const auto& [level, text] : entries) {
        if (x + 10 + metrics.horizontalAdvance(text) > area.right() - 8)
            break;
        painter.fillRect(QRectF(x, at.y() - metrics.ascent() + 1, 8, 8), levelTint(level));
        painter.setPen(kTextColour);
        painter.drawText(QPointF(x + 10, at.y()), text);
        x += 16 + metrics.horizontalAdvance(text);
    }
}

} // namespace

std::optional<VirtualPoolFacts> virtualPoolFacts(const Renderer& renderer, const std::optional<QPointF>& pointer)
{
    const VirtualShadowMap* map = renderer.virtualMap();
    if (!map || !renderer.lastFrame().virtualMap || !map->currentLayout())
        return std::nullopt;
    VirtualPoolFacts facts;
    facts.poolSide = map->cache().poolSide();
    facts.levels = map->currentLayout()->levels;
    facts.counts = renderer.lastFrame().virtualPages;
    facts.windows = map->windows();
    for (const auto& [page, slot] : map->cache().residentPages())
        facts.resident.push_back({slot, page});
    std::sort(facts.resident.begin(), facts.resident.end(), [](const auto& a, const auto& b) { return a.slot < b.slot; });
    if (pointer) {
        if (const std::optional<int> slot = poolSlotAt(facts.poolSide, *pointer); slot && slotEntry(facts, *slot))
            facts.pointerSlot = slot;
    }
    if (facts.pointerSlot) {
        facts.tableLevel = slotEntry(facts, *facts.pointerSlot)->page.level;
    } else if (!facts.resident.empty()) {
        facts.tableLevel = std::min_element(facts.resident.begin(), facts.resident.end(), [](const auto& a, const auto& b) {
                               return a.page.level < b.page.level;
                           })->page.level;
    }
    return facts;
}

std::optional<int> poolSlotAt(int poolSide, QPointF uv)
{
    if (poolSide <= 0 || !(uv.x() >= 0.0 && uv.x() < 1.0 && uv.y() >= 0.0 && uv.y() < 1.0))
        return std::nullopt;
    const int column = std::min(int(std::floor(uv.x() * poolSide)), poolSide - 1);
    const int row = std::min(int(std::floor(uv.y() * poolSide)), poolSide - 1);
    return row * poolSide + column;
}

QColor levelTint(int level)
{
    // shaders/shadow_lookup.glsl's viewTint, level by level round its colours.
    if (level < 0)
        return QColor(Qt::white);
    const Rgb& tint = kViewTints[std::size_t(level) % kViewTints.size()];
    return QColor::fromRgbF(tint[0], tint[1], tint[2]);
}

QString virtualPoolSummary(const VirtualPoolFacts& facts)
{
    const VirtualMapStats& c = facts.counts;
    QString text = QStringLiteral("%1 of %2 slots resident · %3 requested · %4 drawn this frame")
                       .arg(int(facts.resident.size()))
                       .arg(facts.poolSide * facts.poolSide)
                       .arg(c.requested)
                       .arg(c.drawn);
    if (c.coarsened > 0)
        text += QStringLiteral(" · %1 coarsened by up to %2 level%3").arg(c.coarsened).arg(c.levelsCoarsened).arg(c.levelsCoarsened == 1 ? "" : "s");
    if (c.overflow > 0)
        text += QStringLiteral(" · %1 read lit (pool too small)").arg(c.overflow);
    return text;
}

QString virtualSlotText(const VirtualPoolFacts& facts, int slot)
{
    const VirtualPoolFacts::Slot* s = slotEntry(facts, slot);
    if (!s)
        return QStringLiteral("slot %1: free").arg(slot);
    return QStringLiteral("slot %1: level %2, page %3, %4").arg(slot).arg(s->page.level).arg(s->page.x).arg(s->page.y);
}

void paintVirtualPool(QPainter& painter, const QRect& area, const std::function<QPointF(QPointF)>& toPixel, const VirtualPoolFacts& facts)
{
    if (facts.poolSide <= 0)
        return;
    painter.save();
    painter.setClipRect(area);
    const double side = facts.poolSide;
    const auto slotRect = [&](int slot) {
        const double column = slot % facts.poolSide, row = slot / facts.poolSide;
        return QRectF(toPixel({column / side, (row + 1.0) / side}), toPixel({(column + 1.0) / side, row / side})).normalized();
    };
    // Each page's slot in its level's tint, so the pool reads as levels at a glance.
    for (const VirtualPoolFacts::Slot& s : facts.resident) {
        QColor tint = levelTint(s.page.level);
        tint.setAlpha(90);
        painter.fillRect(slotRect(s.slot), tint);
    }
    if (facts.pointerSlot) {
        painter.setPen(QPen(Qt::white, 1.5));
        painter.setBrush(Qt::NoBrush);
        painter.drawRect(slotRect(*facts.pointerSlot));
    }
    const QFontMetrics metrics(painter.font());
    // Text and the table inside the pool where it is on screen, or the pane where it reaches past.
    const QRect pool = QRectF(toPixel({0.0, 1.0}), toPixel({1.0, 0.0})).normalized().toAlignedRect().intersected(area);
    const QRect frame = pool.width() > 120 && pool.height() > 120 ? pool : area;
    const QPointF counts(frame.left() + 6, frame.top() + 6 + metrics.ascent());
    plateText(painter, area, counts, QStringLiteral("virtual pool · ") + virtualPoolSummary(facts));
    drawLevelSwatches(painter, area, counts + QPointF(0.0, metrics.height() + 6), facts);
    // The page table of one level in the upper right corner under the counts (slots fill the
    // pool from the bottom), a texel per page of its window.
    const int top = frame.top() + 6 + 3 * (metrics.height() + 6);
    const int inset = std::min(frame.width() / 3, frame.bottom() - 8 - top);
    if (inset >= 48 && facts.tableLevel >= 0) {
        const QRect table(frame.right() - 8 - inset, top, inset, inset);
        painter.setRenderHint(QPainter::SmoothPixmapTransform, false);
        painter.drawImage(table, pageTableImage(facts, facts.tableLevel));
        painter.setPen(QPen(kTextColour, 1.0));
        painter.setBrush(Qt::NoBrush);
        painter.drawRect(table);
        const int pages = int(std::count_if(facts.resident.begin(), facts.resident.end(), [&](const auto& s) { return s.page.level == facts.tableLevel; }));
        plateText(painter, area, QPointF(std::max(table.left() - 60, frame.left() + 6), table.top() - 6),
                  QStringLiteral("level %1's page table: %2 resident%3").arg(facts.tableLevel).arg(pages).arg(facts.pointerSlot ? QString() : QStringLiteral(" (the finest)")));
    }
    painter.restore();
}

} // namespace shadowlab
