#pragma once

#include "AccuracyMeter.h"
#include "Settings.h"

#include <QSize>

#include <glm/vec3.hpp>

#include <vector>

namespace shadowlab {

class Renderer;

// One bias setting the tuner tried, with its error summed over every light placement.
struct BiasCandidate {
    double slope = 0.0;
    double min = 0.0;
    double falseShadow = 0.0;   // mean share of measured pixels over the placements: acne
    double falseLight = 0.0;    // ... peter panning and leaks
    double misclassified() const { return falseShadow + falseLight; }
};

struct BiasTuning {
    BiasSpace space = BiasSpace::World;
    std::vector<glm::dvec3> placements;     // light positions tried (the current one first)
    std::vector<BiasCandidate> candidates;  // the whole grid, slope-major
    // The acne-against-leak trade-off: candidates no other beats on both false shadow and
    // false light, by increasing false shadow.
    std::vector<std::size_t> front;
    std::size_t best = 0;                   // the knee: fewest misclassified, smaller bias on a tie
    BiasCandidate current;                  // the settings as they were, measured the same way
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
    std::vector<BiasCandidate> m_grid;      // the candidates, then the current settings last
    AccuracyMeter m_meter;
    int m_step = 0;
};

} // namespace shadowlab
