#include "ProceduralTexture.h"

#include <glm/common.hpp>
#include <glm/gtc/noise.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace shadowlab {

namespace {

QRgb rgb(glm::dvec3 c)
{
    c = glm::clamp(c, 0.0, 1.0) * 255.0;
    return qRgb(int(c.r + 0.5), int(c.g + 0.5), int(c.b + 0.5));
}

QRgb checker(int x, int y, int size)
{
    // Two squares per texture tile in each direction, with a faint grout line.
    const int cell = size / 2;
    const bool dark = ((x / cell) + (y / cell)) % 2 == 1;
    const int gx = x % cell, gy = y % cell;
    const bool grout = gx < 2 || gy < 2;
    const glm::dvec3 light(0.78, 0.76, 0.72), darker(0.55, 0.56, 0.58);
    return rgb((dark ? darker : light) * (grout ? 0.85 : 1.0));
}

QRgb woodTexel(int x, int y, int size)
{
    // Rings around a point off the texture, warped by Perlin noise (GLM's) so they wander.
    const glm::vec2 p(float(x) / float(size), float(y) / float(size));
    const float warp = glm::perlin(p * 4.0f) * 0.08f + glm::perlin(p * 17.0f) * 0.015f;
    const float r = glm::length(p - glm::vec2(-0.35f, 0.4f)) * 14.0f + warp * 14.0f;
    const float ring = 0.5f + 0.5f * std::sin(r * 6.2831853f);
    const float grain = 0.5f + 0.5f * glm::perlin(glm::vec2(p.x * 3.0f, p.y * 60.0f));
    const glm::dvec3 early(0.72, 0.50, 0.30), late(0.52, 0.33, 0.18);
    return rgb(glm::mix(early, late, double(ring) * 0.8 + double(grain) * 0.2));
}

// A reproducible hash to [0, 1) (PCG output permutation).
double random01(std::uint32_t seed, std::uint32_t i)
{
    const std::uint32_t state = (seed * 2654435761u ^ i) * 747796405u + 2891336453u;
    const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return double(((word >> 22u) ^ word) >> 8) / 16777216.0;
}

QRgb rgba(glm::dvec3 c, bool solid)
{
    c = glm::clamp(c, 0.0, 1.0) * 255.0;
    return qRgba(int(c.r + 0.5), int(c.g + 0.5), int(c.b + 0.5), solid ? 255 : 0);
}

} // namespace

QImage makeLeafTexture(int seed, int size)
{
    // Leaves along a stem from the bottom centre: each an almond between its base and tip,
    // widest a third of the way, with a darker midrib.
    struct Leaf {
        glm::dvec2 base, tip;
        double width;
    };
    std::vector<Leaf> leaves;
    const glm::dvec2 stemFoot(0.5, 1.0), stemTop(0.5, 0.12);
    const int count = 7;
    for (int i = 0; i < count; ++i) {
        const auto u = std::uint32_t(seed) * 16u + std::uint32_t(i) * 4u;
        const double along = 0.25 + 0.72 * double(i) / double(count - 1);
        const glm::dvec2 base = glm::mix(stemFoot, stemTop, along);
        const double side = i % 2 == 0 ? -1.0 : 1.0;
        const double angle = side * (0.55 + 0.5 * random01(7, u)) + (i == count - 1 ? -side * 0.55 : 0.0);
        const double length = 0.26 + 0.12 * random01(7, u + 1);
        const glm::dvec2 tip = base + length * glm::dvec2(std::sin(angle), -std::cos(angle));
        leaves.push_back({base, tip, length * (0.26 + 0.08 * random01(7, u + 2))});
    }
    const glm::dvec3 green(0.22, 0.42, 0.12), pale(0.42, 0.58, 0.20), rib(0.16, 0.30, 0.08);
    QImage image(size, size, QImage::Format_RGBA8888);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const glm::dvec2 p((x + 0.5) / size, (y + 0.5) / size);
            bool solid = false;
            glm::dvec3 colour = green;
            // The stem: a thin line from the foot to the last leaf.
            const glm::dvec2 stem = stemTop - stemFoot;
            const double ts = std::clamp(glm::dot(p - stemFoot, stem) / glm::dot(stem, stem), 0.0, 1.0);
            if (glm::length(p - (stemFoot + ts * stem)) < 0.012) {
                solid = true;
                colour = rib;
            }
            for (const Leaf& leaf : leaves) {
                const glm::dvec2 axis = leaf.tip - leaf.base;
                const double length = glm::length(axis);
                const glm::dvec2 dir = axis / length;
                const double t = glm::dot(p - leaf.base, dir) / length;
                const double across = std::abs(dir.x * (p.y - leaf.base.y) - dir.y * (p.x - leaf.base.x));
                if (t <= 0.0 || t >= 1.0)
                    continue;
                const double half = leaf.width * 0.5 * std::pow(std::sin(3.14159265 * std::pow(t, 0.75)), 0.8);
                if (across < half) {
                    solid = true;
                    colour = across < 0.006 ? rib : glm::mix(green, pale, across / std::max(half, 1e-9) * 0.6);
                }
            }
            image.setPixel(x, y, rgba(colour, solid));
        }
    }
    return image;
}

QImage makeTrellisTexture(int size)
{
    // Slats 45 degrees both ways, two of each per tile so the pattern repeats seamlessly.
    const double slat = 0.16;   // share of each period a slat covers
    QImage image(size, size, QImage::Format_RGBA8888);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const double u = (x + 0.5) / size * 2.0, v = (y + 0.5) / size * 2.0;
            const double a = u + v - std::floor(u + v), b = u - v - std::floor(u - v);
            const bool first = a < slat, second = b < slat;
            const QRgb wood = woodTexel(x, y, size);
            const glm::dvec3 c(qRed(wood) / 255.0, qGreen(wood) / 255.0, qBlue(wood) / 255.0);
            // The slat on top is a little lighter where they cross.
            image.setPixel(x, y, rgba(c * (first && second ? 1.1 : 1.0), first || second));
        }
    }
    return image;
}

QImage makeProceduralTexture(TextureKind kind, int size)
{
    QImage image(size, size, QImage::Format_RGBA8888);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x)
            image.setPixel(x, y, kind == TextureKind::Checker ? checker(x, y, size) : woodTexel(x, y, size));
    }
    return image;
}

} // namespace shadowlab
