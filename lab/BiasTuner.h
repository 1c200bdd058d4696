#pragma once

#include "AccuracyMeter.h"
#include "Settings.h"

#include <QSize>

#include <glm/vec3.hpp>

#include <optional>

#include <vector>

namespace shadowlab {

class Renderer;

// One bias setting the tuner tried, with its error summed over every light placement.
struct BiasCandidate {
    double slope = 0.0;
    double min = 0.0;
    double falseShadow = 0.0;   // mean share of measured pixels over the placements: acne
    double falseLight = 0.0;    // ... peter panning and leaks
    double misclassifiedPixels = 0.0;   // summed over the placements: the count its noise is known in (ErrorNoise.h)
    double misclassified() const { return falseShadow + falseLight; }
};

struct BiasTuning {
    BiasSpace space = BiasSpace::World;
    std::vector<glm::dvec3> placements;     // light positions tried (the current one first)
    std::vector<BiasCandidate> candidates;  // the whole grid, slope-major
    // The acne-against-leak trade-off: candidates no other beats on both false shadow and
    // false light, by increasing false shadow.
    std::vector<std::size_t> front;
    // The knee, a point of the front: fewest misclassified pixels; among points within the
    // error noise of the fewest, the smallest bias.
    std::size_t best = 0;
    // The settings as they were, measured the same way: the very candidate when the grid holds
    // them, so the table and "as set" quote one measurement. It is the mean over the light
    // placements at the tuner's size, not what one view at another size measures.
    BiasCandidate current;
    std::optional<std::size_t> currentCandidate;    // which candidate the current settings are, if any
    bool improves = false;                  // best misclassifies clearly fewer pixels than current
};

// Searches the bias (bias.slope x bias.min, in the unit of bias.space) that misclassifies the
// fewest pixels against the hard reference, over the current view and a spread of light
// directions around the current one (same distance and target), with everything else as set.
// Stepwise, so a window can run it between events: step() measures one candidate at one
// placement; the command line loops until done().
class BiasTuner {
public:
    BiasTuner(const Settings& settings, QSize size);

    int steps() const { return int(m_grid.size() * m_placements.size()); }
    int stepsDone() const { return m_step; }
    int placementCount() const { return int(m_placements.size()); }
    bool done() const { return m_step >= steps(); }
    // `renderer`'s context must be current. Throws like Renderer::render().
    void step(Renderer& renderer);
    BiasTuning result() const;

    // The grid searched for each unit (slope values, min values), for help texts.
    static std::pair<std::vector<double>, std::vector<double>> grid(BiasSpace space);

private:
    Settings m_settings;
    QSize m_size;
    std::vector<glm::dvec3> m_placements;
    std::vector<BiasCandidate> m_grid;      // the candidates, then the current settings when off the grid
    std::size_t m_candidates = 0;           // the grid's own points, first in m_grid
    std::size_t m_current = 0;              // the current settings' index in m_grid
    AccuracyMeter m_meter;
    int m_step = 0;
};

} // namespace shadowlab
