#include "ProceduralTexture.h"

#include <glm/common.hpp>
#include <glm/gtc/noise.hpp>
#include <glm/vec2.hpp>

#include <cmath>

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

QRgb wood(int x, int y, int size)
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

} // namespace

QImage makeProceduralTexture(TextureKind kind, int size)
{
    QImage image(size, size, QImage::Format_RGBA8888);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x)
            image.setPixel(x, y, kind == TextureKind::Checker ? checker(x, y, size) : wood(x, y, size));
    }
    return image;
}

} // namespace shadowlab
