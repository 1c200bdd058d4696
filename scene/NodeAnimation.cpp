#include "NodeAnimation.h"

#include "ModelImporter.h"

#include <assimp/scene.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace shadowlab {

namespace {

// Assimp's documented rate for a file that states none (mTicksPerSecond 0).
constexpr double kDefaultTicksPerSecond = 25.0;
// The longest gap between the keys of a turning node, or of one under a moving parent.
constexpr double kDenseKeySeconds = 1.0 / 30.0;

// The placement as position, rotation and scale (T·R·S). A mirror is kept as a negative x
// scale, so that it stays on one axis from key to key and the turns between keys stay short.
// The turn is the columns' directions made orthonormal (the longest column kept as it points,
// the next made square to it), the scale each column's length along its turned axis. A shear
// (a non-uniform scale under a turn, whose columns are not square) is not kept; a zero scale
// keeps whichever directions are left. Not finite numbers in, not finite numbers out.
MotionKey decomposed(const glm::dmat4& m)
{
    MotionKey key;
    key.position = glm::dvec3(m[3]);
    glm::dmat3 basis(m);
    const glm::dvec3 lengths(glm::length(basis[0]), glm::length(basis[1]), glm::length(basis[2]));
    if (!std::isfinite(lengths.x + lengths.y + lengths.z)) {
        key.scale = glm::dvec3(NAN);
        return key;
    }
    const double mirror = glm::determinant(basis) < 0.0 ? -1.0 : 1.0;
    basis[0] *= mirror;
    std::array<int, 3> order{0, 1, 2};
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return lengths[a] > lengths[b]; });
    const int i = order[0], j = order[1], k = order[2];
    glm::dmat3 turn(1.0);
    if (lengths[i] > 0.0) {
        const glm::dvec3 u = basis[i] / lengths[i];
        glm::dvec3 v = basis[j] - glm::dot(basis[j], u) * u;
        if (!(glm::length(v) > 1e-12 * lengths[i]))     // flat, or a line: any square direction will do
            v = glm::cross(u, std::abs(u.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0));
        v = glm::normalize(v);
        // The third axis completes a right-handed frame, whichever two columns came first.
        const bool cyclic = j == (i + 1) % 3;
        turn[i] = u;
        turn[j] = v;
        turn[k] = cyclic ? glm::cross(u, v) : glm::cross(v, u);
    }
    key.rotation = glm::normalize(glm::quat_cast(turn));
    key.scale = glm::dvec3(mirror * glm::dot(basis[0], turn[0]), glm::dot(basis[1], turn[1]), glm::dot(basis[2], turn[2]));
    return key;
}

// The keys' value at `t`: interpolated by `mix` between its neighbours, held outside them.
template <typename T, typename Mix>
T valueAt(const std::vector<std::pair<double, T>>& keys, double t, const Mix& mix)
{
    if (t <= keys.front().first)
        return keys.front().second;
    if (t >= keys.back().first)
        return keys.back().second;
    const auto next = std::upper_bound(keys.begin(), keys.end(), t, [](double time, const auto& key) { return time < key.first; });
    const auto& [t1, b] = *next;
    const auto& [t0, a] = *(next - 1);
    return mix(a, b, (t - t0) / (t1 - t0));
}

// A channel's keys in seconds, in time order; keys at no finite time are left out.
template <typename T, typename AiKey, typename Convert>
std::vector<std::pair<double, T>> readKeys(const AiKey* keys, unsigned count, double ticksPerSecond, const Convert& convert)
{
    std::vector<std::pair<double, T>> out;
    for (unsigned i = 0; i < count; ++i) {
        const double time = keys[i].mTime / ticksPerSecond;
        if (std::isfinite(time))
            out.emplace_back(time, convert(keys[i].mValue));
    }
    std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    return out;
}

glm::dvec3 toDvec3(const aiVector3D& v)
{
    return glm::dvec3(v.x, v.y, v.z);
}

// Assimp's rotation keys need not be of unit length; a zero one stays zero and is refused later.
glm::dquat toUnitQuat(const aiQuaternion& q)
{
    const glm::dquat r(q.w, q.x, q.y, q.z);
    const double length = glm::length(r);
    return length > 0.0 ? r / length : r;
}

} // namespace

glm::dmat4 toGlm(const aiMatrix4x4& a)
{
    glm::dmat4 m(1.0);
    for (int row = 0; row < 4; ++row) {
        for (int col = 0; col < 4; ++col)
            m[col][row] = a[unsigned(row)][unsigned(col)];
    }
    return m;
}

bool holdsStill(const NodePose& pose)
{
    const glm::dmat4& first = pose.placements.front();
    double size = 1.0;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r)
            size = std::max(size, std::abs(first[c][r]));
    }
    // Slerp and lerp between equal keys need not give them back to the last bit.
    for (const glm::dmat4& placement : pose.placements) {
        for (int c = 0; c < 4; ++c) {
            for (int r = 0; r < 4; ++r) {
                if (!(std::abs(placement[c][r] - first[c][r]) <= 1e-12 * size))
                    return false;
            }
        }
    }
    return true;
}

NodeAnimation::NodeAnimation(const aiScene* scene)
{
    if (!scene || scene->mNumAnimations == 0 || !scene->mAnimations[0])
        return;
    const aiAnimation* animation = scene->mAnimations[0];
    const double ticksPerSecond = animation->mTicksPerSecond > 0.0 && std::isfinite(animation->mTicksPerSecond)
        ? animation->mTicksPerSecond : kDefaultTicksPerSecond;
    double last = 0.0;
    for (unsigned c = 0; c < animation->mNumChannels; ++c) {
        const aiNodeAnim* source = animation->mChannels[c];
        if (!source)
            continue;
        Channel channel;
        channel.positions = readKeys<glm::dvec3>(source->mPositionKeys, source->mNumPositionKeys, ticksPerSecond,
                                                 [](const aiVector3D& v) { return toDvec3(v); });
        channel.rotations = readKeys<glm::dquat>(source->mRotationKeys, source->mNumRotationKeys, ticksPerSecond,
                                                 [](const aiQuaternion& q) { return toUnitQuat(q); });
        channel.scales = readKeys<glm::dvec3>(source->mScalingKeys, source->mNumScalingKeys, ticksPerSecond,
                                              [](const aiVector3D& v) { return toDvec3(v); });
        if (channel.positions.empty() && channel.rotations.empty() && channel.scales.empty())
            continue;
        for (const auto* keys : {&channel.positions, &channel.scales}) {
            if (!keys->empty())
                last = std::max(last, keys->back().first);
        }
        if (!channel.rotations.empty())
            last = std::max(last, channel.rotations.back().first);
        m_channels.emplace(source->mNodeName.C_Str(), std::move(channel));
    }
    const double duration = animation->mDuration / ticksPerSecond;
    m_length = std::max(std::isfinite(duration) ? duration : 0.0, last);
    if (!(m_length > 0.0))
        m_channels.clear();
}

const NodeAnimation::Channel* NodeAnimation::channelOf(const aiNode* node) const
{
    const auto found = m_channels.find(node->mName.C_Str());
    return found == m_channels.end() ? nullptr : &found->second;
}

// The node's own transform at `t`: its channel's keys, and its still transform's parts where
// the channel keys none.
glm::dmat4 NodeAnimation::localAt(const aiNode* node, double t) const
{
    const glm::dmat4 still = toGlm(node->mTransformation);
    const Channel* channel = channelOf(node);
    if (!channel)
        return still;
    const MotionKey rest = decomposed(still);
    const auto lerp = [](const glm::dvec3& a, const glm::dvec3& b, double u) { return glm::mix(a, b, u); };
    const auto slerp = [](const glm::dquat& a, const glm::dquat& b, double u) { return glm::slerp(a, b, u); };
    const glm::dvec3 position = channel->positions.empty() ? rest.position : valueAt(channel->positions, t, lerp);
    const glm::dquat rotation = channel->rotations.empty() ? rest.rotation : valueAt(channel->rotations, t, slerp);
    const glm::dvec3 scale = channel->scales.empty() ? rest.scale : valueAt(channel->scales, t, lerp);
    return glm::translate(glm::dmat4(1.0), position) * glm::mat4_cast(rotation) * glm::scale(glm::dmat4(1.0), scale);
}

// Root to `node` at `t`.
glm::dmat4 NodeAnimation::placementAt(const aiNode* node, double t) const
{
    glm::dmat4 placement(1.0);
    for (const aiNode* n = node; n; n = n->mParent)
        placement = localAt(n, t) * placement;
    return placement;
}

// Every time a key of the channel or of an ancestor's falls on, within the clip, and 0; at most
// kMaxMotionKeys of them, evenly spread when there would be more.
std::vector<double> NodeAnimation::timesOf(const Channel& channel, const NodePose* parent, bool& resampled) const
{
    std::vector<double> times{0.0};
    if (parent)
        times.insert(times.end(), parent->times.begin(), parent->times.end());
    const auto add = [&](const auto& keys) {
        for (const auto& key : keys)
            times.push_back(std::clamp(key.first, 0.0, m_length));
    };
    add(channel.positions);
    add(channel.rotations);
    add(channel.scales);
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    // A turn composed with an offset (a child of a turning node, or a node turning about a pivot
    // its parent puts aside) sweeps an arc, which keys far apart would cut as a chord: keys at
    // most kDenseKeySeconds apart keep it on the arc.
    if (parent || !channel.rotations.empty()) {
        std::vector<double> dense;
        for (std::size_t i = 0; i < times.size(); ++i) {
            dense.push_back(times[i]);
            if (i + 1 == times.size())
                break;
            const int steps = int(std::ceil((times[i + 1] - times[i]) / kDenseKeySeconds));
            for (int k = 1; k < steps && dense.size() <= kMaxMotionKeys; ++k)
                dense.push_back(times[i] + (times[i + 1] - times[i]) * k / steps);
        }
        times = std::move(dense);
    }
    resampled = times.size() > kMaxMotionKeys;
    if (resampled) {
        const double end = times.back();
        times.resize(kMaxMotionKeys);
        for (std::size_t i = 0; i < kMaxMotionKeys; ++i)
            times[i] = end * double(i) / double(kMaxMotionKeys - 1);
    }
    return times;
}

std::optional<NodePose> NodeAnimation::poseOf(const aiNode* node, const NodePose* parent) const
{
    const Channel* channel = channelOf(node);
    if (!channel && !parent)
        return std::nullopt;
    NodePose pose;
    if (!channel) {
        // Carried by its parent at the parent's times.
        pose = *parent;
        const glm::dmat4 local = toGlm(node->mTransformation);
        for (glm::dmat4& placement : pose.placements)
            placement = placement * local;
        return pose;
    }
    pose.times = timesOf(*channel, parent, pose.resampled);
    pose.resampled = pose.resampled || (parent && parent->resampled);
    const glm::dmat4 stillParent = node->mParent && !parent ? placementAt(node->mParent, 0.0) : glm::dmat4(1.0);
    pose.placements.reserve(pose.times.size());
    for (const double t : pose.times) {
        glm::dmat4 above = stillParent;
        if (parent) {
            const auto at = std::lower_bound(parent->times.begin(), parent->times.end(), t);
            above = at != parent->times.end() && *at == t ? parent->placements[std::size_t(at - parent->times.begin())]
                                                           : placementAt(node->mParent, t);
        }
        pose.placements.push_back(above * localAt(node, t));
    }
    return pose;
}

Motion NodeAnimation::motionOf(const NodePose& pose) const
{
    Motion motion;
    motion.kind = Motion::Kind::Path;
    motion.period = m_length;
    motion.keys.reserve(pose.times.size());
    for (std::size_t i = 0; i < pose.times.size(); ++i) {
        MotionKey key = decomposed(pose.placements[i]);
        key.time = pose.times[i];
        motion.keys.push_back(key);
    }
    return motion;
}

} // namespace shadowlab
