#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <limits>

namespace shadowlab {

// Axis-aligned box in double precision; starts empty (min > max).
struct Bounds {
    glm::dvec3 min{std::numeric_limits<double>::infinity()};
    glm::dvec3 max{-std::numeric_limits<double>::infinity()};

    bool isEmpty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    void extend(const glm::dvec3& p);
    void extend(const Bounds& other);
    glm::dvec3 center() const { return (min + max) * 0.5; }
    std::array<glm::dvec3, 8> corners() const;
    Bounds transformed(const glm::dmat4& m) const;  // bounds of the 8 transformed corners
};

} // namespace shadowlab
