#pragma once

#include "Motion.h"

#include <assimp/matrix4x4.h>

#include <glm/mat4x4.hpp>

#include <QString>

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

struct aiNode;
struct aiScene;

namespace shadowlab {

// A node's placement from the root of the file's hierarchy over the clip, where it moves.
struct NodePose {
    std::vector<double> times;              // seconds, from 0, increasing
    std::vector<glm::dmat4> placements;     // root to node, at each time
    bool resampled = false;                 // more key times than kMaxMotionKeys: taken evenly instead
};

// Whether every placement of `pose` is its first (an animation that holds a node still).
bool holdsStill(const NodePose& pose);

// Assimp's matrix (row-major, float or double) as glm's (column-major, double).
glm::dmat4 toGlm(const aiMatrix4x4& a);

// The first animation of an Assimp scene as node placements over time, by Assimp's convention:
// positions and scales interpolated linearly, rotations by slerp, each held before its first key
// and after its last. Morph and mesh channels are not read.
class NodeAnimation {
public:
    NodeAnimation() = default;
    explicit NodeAnimation(const aiScene* scene);

    // Whether the first animation moves no node (none, no node channel, or a clip of length 0).
    bool empty() const { return m_channels.empty(); }
    // The clip's length in seconds: its duration, or its last key if that is later.
    double length() const { return m_length; }

    // The pose of `node`, given its parent's (null when the parent does not move); nullopt when
    // neither the node nor any ancestor has a channel.
    std::optional<NodePose> poseOf(const aiNode* node, const NodePose* parent) const;
    // The pose as a path over the clip (linear, pre and post the identity), whose key at each
    // time is the placement taken apart into position, rotation and scale.
    Motion motionOf(const NodePose& pose) const;

private:
    template <typename T>
    using Keys = std::vector<std::pair<double, T>>;     // (seconds, value), by time
    struct Channel {
        Keys<glm::dvec3> positions;
        Keys<glm::dquat> rotations;
        Keys<glm::dvec3> scales;
    };

    const Channel* channelOf(const aiNode* node) const;
    glm::dmat4 localAt(const aiNode* node, double t) const;
    glm::dmat4 placementAt(const aiNode* node, double t) const;
    std::vector<double> timesOf(const Channel& channel, const NodePose* parent, bool& resampled) const;

    double m_length = 0.0;
    std::map<std::string, Channel> m_channels;    // by node name
};

} // namespace shadowlab
