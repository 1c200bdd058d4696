#include "Motion.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

constexpr int kSweepSamples = 128;

// t within [0, period), for any finite t.
double wrapped(double t, double period)
{
    const double r = std::fmod(t, period);
    return r < 0.0 ? r + period : r;
}

glm::dmat4 turnAbout(const glm::dvec3& point, const glm::dvec3& axis, double radians)
{
    return glm::translate(glm::dmat4(1.0), point) * glm::rotate(glm::dmat4(1.0), radians, axis) * glm::translate(glm::dmat4(1.0), -point);
}

// Catmull-Rom through p1 and p2 with neighbours p0 and p3, at u in [0, 1].
glm::dvec3 catmullRom(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2, const glm::dvec3& p3, double u)
{
    const double u2 = u * u, u3 = u2 * u;
    return 0.5 * ((2.0 * p1) + (p2 - p0) * u + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * u2 + (3.0 * p1 - p0 - 3.0 * p2 + p3) * u3);
}

bool finite(const glm::dvec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

MotionKey pathKeyAt(const Motion& motion, double t)
{
    const std::vector<MotionKey>& keys = motion.keys;
    if (keys.size() == 1 || t <= keys.front().time)
        return keys.front();
    if (t >= keys.back().time)
        return keys.back();
    const auto next = std::upper_bound(keys.begin(), keys.end(), t, [](double time, const MotionKey& k) { return time < k.time; });
    const std::size_t i = std::size_t(next - keys.begin()) - 1;
    const MotionKey& a = keys[i];
    const MotionKey& b = keys[i + 1];
    const double u = (t - a.time) / (b.time - a.time);
    MotionKey key;
    key.time = t;
    key.rotation = glm::slerp(a.rotation, b.rotation, u);
    if (motion.smooth) {
        const MotionKey& before = i > 0 ? keys[i - 1] : a;
        const MotionKey& after = i + 2 < keys.size() ? keys[i + 2] : b;
        key.position = catmullRom(before.position, a.position, b.position, after.position, u);
        key.scale = catmullRom(before.scale, a.scale, b.scale, after.scale, u);
    } else {
        key.position = glm::mix(a.position, b.position, u);
        key.scale = glm::mix(a.scale, b.scale, u);
    }
    return key;
}

glm::dmat4 Motion::at(double t) const
{
    t += start;
    const double phase = wrapped(t, period) / period;   // [0, 1)
    const double wave = std::sin(glm::two_pi<double>() * phase);
    glm::dmat4 k(1.0);
    switch (kind) {
    case Kind::Spin:
    case Kind::Orbit:
        k = turnAbout(point, axis, glm::two_pi<double>() * phase);
        break;
    case Kind::Swing:
        k = turnAbout(point, axis, amplitude * wave);
        break;
    case Kind::Bob:
        k = glm::translate(glm::dmat4(1.0), axis * (amplitude * wave));
        break;
    case Kind::Path: {
        if (keys.empty())
            break;
        const MotionKey key = pathKeyAt(*this, keys.size() > 1 ? wrapped(t, period) : 0.0);
        k = glm::translate(glm::dmat4(1.0), key.position) * glm::mat4_cast(key.rotation) * glm::scale(glm::dmat4(1.0), key.scale);
        break;
    }
    }
    return pre * k * post;
}

Bounds Motion::sweptBounds(const Bounds& local, bool padded) const
{
    Bounds swept;
    if (local.isEmpty())
        return swept;
    const std::array<glm::dvec3, 8> corners = local.corners();
    std::array<glm::dvec3, 8> last{};
    double step = 0.0;
    // Every key of a path is a sample too, so a sharp turn at a key is not cut.
    std::vector<double> times;
    for (int s = 0; s <= kSweepSamples; ++s)
        times.push_back(period * double(s) / kSweepSamples);
    for (const MotionKey& key : keys)
        times.push_back(key.time);
    std::sort(times.begin(), times.end());
    for (std::size_t s = 0; s < times.size(); ++s) {
        const glm::dmat4 m = at(std::min(times[s], std::nextafter(period, 0.0)) - start);
        for (std::size_t c = 0; c < corners.size(); ++c) {
            const glm::dvec3 p(m * glm::dvec4(corners[c], 1.0));
            swept.extend(p);
            if (s > 0)
                step = std::max(step, glm::length(p - last[c]));
            last[c] = p;
        }
    }
    if (padded) {
        swept.min -= glm::dvec3(0.5 * step);
        swept.max += glm::dvec3(0.5 * step);
    }
    return swept;
}

QString motionProblem(const Motion& motion)
{
    if (!std::isfinite(motion.period) || !(motion.period > 0.0) || motion.period > kMaxMotionPeriod)
        return QStringLiteral("its period must be a number of seconds above 0, at most %1").arg(kMaxMotionPeriod);
    if (!finite(motion.point))
        return QStringLiteral("its point must be three finite numbers");
    if (!finite(motion.axis) || std::abs(glm::length(motion.axis) - 1.0) > 1e-6)
        return QStringLiteral("its axis must be a unit direction (three finite numbers of length 1)");
    if (!std::isfinite(motion.amplitude))
        return QStringLiteral("its amplitude must be a finite number");
    if (!std::isfinite(motion.start))
        return QStringLiteral("its start must be a finite number of seconds");
    if (motion.kind == Motion::Kind::Path) {
        if (motion.keys.empty())
            return QStringLiteral("a path needs at least one key");
        if (motion.keys.front().time != 0.0)
            return QStringLiteral("a path's first key must be at time 0");
        for (std::size_t i = 0; i < motion.keys.size(); ++i) {
            const MotionKey& k = motion.keys[i];
            if (!std::isfinite(k.time) || !finite(k.position) || !finite(k.scale)
                || !std::isfinite(k.rotation.w) || !std::isfinite(k.rotation.x) || !std::isfinite(k.rotation.y) || !std::isfinite(k.rotation.z))
                return QStringLiteral("key %1 must hold finite numbers").arg(i);
            if (std::abs(glm::length(k.rotation) - 1.0) > 1e-6)
                return QStringLiteral("key %1's rotation must be a unit quaternion").arg(i);
            if (i > 0 && !(k.time > motion.keys[i - 1].time))
                return QStringLiteral("key %1's time must be after key %2's (times increase)").arg(i).arg(i - 1);
        }
    }
    return {};
}

} // namespace shadowlab
