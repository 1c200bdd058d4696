#include "Bounds.h"

#include <glm/common.hpp>

namespace shadowlab {

void Bounds::extend(const glm::dvec3& p)
{
    min = glm::min(min, p);
    max = glm::max(max, p);
}

void Bounds::extend(const Bounds& other)
{
    if (other.isEmpty())
        return;
    extend(other.min);
    extend(other.max);
}

std::array<glm::dvec3, 8> Bounds::corners() const
{
    std::array<glm::dvec3, 8> c;
    for (int i = 0; i < 8; ++i)
        c[i] = glm::dvec3((i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z);
    return c;
}

Bounds Bounds::transformed(const glm::dmat4& m) const
{
    Bounds result;
    if (isEmpty())
        return result;
    for (const glm::dvec3& c : corners())
        result.extend(glm::dvec3(m * glm::dvec4(c, 1.0)));
    return result;
}

} // namespace shadowlab
