#include "BiasTuner.h"

#include "ErrorNoise.h"
#include "Measurement.h"
#include "Renderer.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

// Light directions around the current one: the same elevation turned about the vertical by
// 72° steps, and one steeper. Acne and leaks depend on the angle between light and receiver,
// so one direction alone would tune to its own slopes.
std::vector<glm::dvec3> spreadPlacements(const LightSettings& light)
{
    const glm::dvec3 offset = light.position - light.target;
    const double distance = glm::length(offset);
    const double elevation = std::asin(std::clamp(offset.y / distance, -1.0, 1.0));
    const double azimuth = std::atan2(offset.z, offset.x);
    std::vector<glm::dvec3> placements{light.position};
    const auto at = [&](double az, double el) {
        return light.target + distance * glm::dvec3(std::cos(el) * std::cos(az), std::sin(el), std::cos(el) * std::sin(az));
    };
    for (int i = 1; i < 5; ++i)
        placements.push_back(at(azimuth + glm::radians(72.0 * i), elevation));
    placements.push_back(at(azimuth + glm::radians(36.0), elevation + 0.5 * (glm::radians(89.0) - elevation)));
    return placements;
}

// The point of the front with the fewest misclassified pixels; of the points within the error
// noise of it (as good, as far as can be told), the smallest bias, which detaches contact
// shadows least. Always a point of the front, so "best" is a point on the curve shown.
std::size_t knee(const std::vector<BiasCandidate>& candidates, const std::vector<std::size_t>& front)
{
    const auto pixels = [&](std::size_t i) { return candidates[i].misclassifiedPixels; };
    const std::size_t fewest = *std::min_element(front.begin(), front.end(), [&](std::size_t a, std::size_t b) { return pixels(a) < pixels(b); });
    std::size_t best = fewest;
    for (const std::size_t i : front) {
        const BiasCandidate& c = candidates[i];
        const BiasCandidate& b = candidates[best];
        if (!clearlyFewer(pixels(fewest), pixels(i)) && std::pair(c.slope + c.min, c.slope) < std::pair(b.slope + b.min, b.slope))
            best = i;
    }
    return best;
}

} // namespace

std::pair<std::vector<double>, std::vector<double>> BiasTuner::grid(BiasSpace space)
{
    switch (space) {
    case BiasSpace::World:
        return {{0.0, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2}, {0.0, 0.0005, 0.001, 0.002, 0.005, 0.01, 0.02, 0.05}};
    case BiasSpace::Texel:
        return {{0.0, 0.5, 1.0, 2.0, 4.0, 8.0}, {0.0, 0.25, 0.5, 1.0, 2.0, 4.0}};
    case BiasSpace::Depth:
        break;
    }
    return {{0.0, 0.001, 0.002, 0.005, 0.01, 0.02, 0.05}, {0.0, 0.0001, 0.0005, 0.001, 0.002, 0.005}};
}

BiasTuner::BiasTuner(const Settings& settings, QSize size)
    : m_settings(settings), m_size(size), m_placements(spreadPlacements(settings.light)), m_meter(ReferenceOptions{false, 0.0, 1})
{
    const auto [slopes, mins] = grid(settings.bias.space);
    for (const double slope : slopes) {
        for (const double min : mins)
            m_grid.push_back({.slope = slope, .min = min});
    }
    m_candidates = m_grid.size();
    const auto same = [&](const BiasCandidate& c) { return c.slope == settings.bias.slope && c.min == settings.bias.min; };
    m_current = std::size_t(std::find_if(m_grid.begin(), m_grid.end(), same) - m_grid.begin());
    if (m_current == m_grid.size())
        m_grid.push_back({.slope = settings.bias.slope, .min = settings.bias.min});
}

void BiasTuner::step(Renderer& renderer)
{
    if (done())
        return;
    // Placement-major: every candidate at one placement shares its reference (the meter keeps a few).
    const std::size_t placement = std::size_t(m_step) / m_grid.size();
    BiasCandidate& c = m_grid[std::size_t(m_step) % m_grid.size()];
    Settings s = m_settings;
    s.light.position = m_placements[placement];
    s.bias.slope = c.slope;
    s.bias.min = c.min;
    const AccuracyResult r = measureAccuracy(m_meter, renderer, s, m_size);
    c.falseShadow += r.hard.falseShadow / double(m_placements.size());
    c.falseLight += r.hard.falseLight / double(m_placements.size());
    c.misclassifiedPixels += r.hard.misclassified * r.hard.pixels;
    ++m_step;
}

BiasTuning BiasTuner::result() const
{
    BiasTuning t;
    t.space = m_settings.bias.space;
    t.placements = m_placements;
    t.candidates.assign(m_grid.begin(), m_grid.begin() + std::ptrdiff_t(m_candidates));
    t.current = m_grid[m_current];
    if (m_current < m_candidates)
        t.currentCandidate = m_current;
    for (std::size_t i = 0; i < t.candidates.size(); ++i) {
        const BiasCandidate& a = t.candidates[i];
        // Dominated: another is no worse on both and better on one, or the same on both with
        // a smaller bias (the curve keeps one point per trade-off).
        const bool dominated = std::any_of(t.candidates.begin(), t.candidates.end(), [&](const BiasCandidate& b) {
            const bool noWorse = b.falseShadow <= a.falseShadow && b.falseLight <= a.falseLight;
            const bool better = b.falseShadow < a.falseShadow || b.falseLight < a.falseLight;
            const bool smallerTwin = b.falseShadow == a.falseShadow && b.falseLight == a.falseLight
                                  && std::pair(b.slope + b.min, b.slope) < std::pair(a.slope + a.min, a.slope);
            return noWorse && (better || smallerTwin);
        });
        if (!dominated)
            t.front.push_back(i);
    }
    std::sort(t.front.begin(), t.front.end(), [&](std::size_t a, std::size_t b) {
        return t.candidates[a].falseShadow < t.candidates[b].falseShadow;
    });
    t.best = knee(t.candidates, t.front);
    t.improves = clearlyFewer(t.candidates[t.best].misclassifiedPixels, t.current.misclassifiedPixels);
    return t;
}

} // namespace shadowlab
