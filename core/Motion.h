#pragma once

#include "Bounds.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <QString>

#include <vector>

namespace shadowlab {

// The longest cycle a motion may have, in seconds: within scene.time's range.
inline constexpr double kMaxMotionPeriod = 1e6;

// One key of a path: where an object is at `time` seconds, turned and scaled.
struct MotionKey {
    double time = 0.0;
    glm::dvec3 position{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 scale{1.0};

    bool operator==(const MotionKey&) const = default;
};

// How an object moves over time: its placement at time t is pre * K(t) * post, where K(t) is
// the motion's own transform and pre and post are fixed. A scene file's spin, orbit, swing and bob
// turn or shift the object's whole placement (post is it); a path places the object's origin
// at its keys (post is the shape's own turn and scale); a model's node animation keys its
// node's placement (pre is where the scene file put the model). Pure math in double: the
// renderer, the ray tracer and the tests read the same placement at the same instant.
struct Motion {
    enum class Kind {
        Spin,       // a whole turn about `axis` through `point` (the object's own origin) every `period`
        Orbit,      // the same about an axis through another point
        Swing,      // `amplitude` radians either way about the axis, there and back every `period`
        Bob,        // `amplitude` world units either way along `axis`, there and back every `period`
        Path,       // through `keys`, repeating after the last one
    };
    Kind kind = Kind::Spin;
    glm::dvec3 point{0.0};          // spin, orbit, swing: a point on the axis
    glm::dvec3 axis{0.0, 1.0, 0.0}; // unit; turns counter-clockwise seen from its tip
    double period = 1.0;            // seconds, > 0 (a path's is its last key's time, or 1 for one key)
    double amplitude = 0.0;         // swing: radians; bob: world units
    double start = 0.0;             // seconds into its cycle at time 0
    std::vector<MotionKey> keys;    // path: times from 0, increasing
    bool smooth = false;            // path: Catmull-Rom through the positions and scales; linear otherwise
    glm::dmat4 pre{1.0};
    glm::dmat4 post{1.0};

    // The object's placement (object to world) at time `t` seconds (`start` seconds into its
    // cycle at 0); periodic in t, defined for every finite t (negative too).
    glm::dmat4 at(double t) const;
    // How long one cycle takes: the clip a timeline shows for it.
    double length() const { return period; }
    // Bounds of `local` (object space) under at(t) for every t: a sampled sweep, grown by half
    // the largest step a corner takes between samples, so it holds between them too. Unpadded,
    // the samples alone: what the floor test reads, where half a step below a ground the object
    // stands on would cost the ground its place out of the map.
    Bounds sweptBounds(const Bounds& local, bool padded = true) const;

    bool operator==(const Motion&) const = default;
};

// The keys of a path's rotation, position and scale at `t` within [0, period] (no wrapping),
// linear or smooth as the motion says; `keys` not empty.
MotionKey pathKeyAt(const Motion& motion, double t);

// What is wrong with `motion` (a finite, positive period; a unit axis; keys that are finite,
// increasing from 0 with unit rotations), or an empty string.
QString motionProblem(const Motion& motion);

} // namespace shadowlab
