#pragma once

#include "FrameStats.h"
#include "RasteriserTuning.h"
#include "SampleStats.h"

#include <QString>

#include <deque>

namespace shadowlab {

// The last N frames' wall times of one view, for a status bar whose numbers do not jump with
// every frame on a loaded machine: medians and the p10–p90 spread, and the shadow pass only over
// the frames that ran it (a reused map costs nothing and says nothing about the pass).
class FrameTimeHistory {
public:
    explicit FrameTimeHistory(int capacity = 30) : m_capacity(capacity) {}

    void add(const FrameStats& stats);
    void clear() { m_frames.clear(); }
    int size() const { return int(m_frames.size()); }
    int capacity() const { return m_capacity; }
    void setCapacity(int capacity);

    struct Summary {
        SampleStats shadow;     // count 0: no frame of the window ran the shadow pass
        SampleStats lit;
        SampleStats frame;
        // The frames that ran the shadow pass, and those that reused the map: the pass adds
        // up with the first, while `frame` is the median over both.
        SampleStats frameWithShadow;
        SampleStats frameWithoutShadow;
    };
    Summary summary() const;

    // "shadow 3.1 · lit 8.2 · frame 12.0 ms · median of 30"; with `cpuTime` (a software
    // renderer) "ms CPU": the figures are the CPU's, not a GPU's. When only some frames ran
    // the shadow pass it says in how many ("shadow 11.6 in 3 of 30"), as its median is then
    // of other frames than the frame's.
    static QString text(const Summary& summary, bool cpuTime, bool shadowsOn = true);
    // What the frames were, in a sentence for a tooltip: which ran the pass, and what those cost.
    static QString explanation(const Summary& summary, bool shadowsOn = true);

private:
    struct Sample {
        bool shadowRendered;
        double shadow, lit, frame;
    };
    int m_capacity;
    std::deque<Sample> m_frames;
};

} // namespace shadowlab
