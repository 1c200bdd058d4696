#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <QImage>
#include <QSize>

#include <vector>

namespace shadowlab {

// What the measuring variant of the lit pass wrote, read back to the CPU, rows top to bottom.
struct VisibilityBuffer {
    // NotReceiving: an object that receives no shadow (a scene file's "receives": false).
    enum Mask : int { Background = 0, FacingLight = 1, FacingAway = 2, NotReceiving = 3 };

    QSize size;
    glm::dvec3 cameraPosition{0.0};             // positions below are relative to it
    std::vector<glm::vec4> positionVisibility;  // camera-relative xyz, shadow visibility in w
    std::vector<glm::vec4> normalMask;          // geometric normal xyz, Mask in w
    QImage image;                               // the shaded frame itself
    // The lit pass's light before the shadow term, per pixel: the frame is ambient + visibility
    // * direct (clamped by the display; the view's tints aside), so that it can be shaded again
    // with another visibility. The background's ambient is the clear colour.
    std::vector<glm::vec3> ambientLight;
    std::vector<glm::vec3> directLight;

    int pixelCount() const { return size.width() * size.height(); }
    Mask mask(int i) const { return Mask(int(normalMask[std::size_t(i)].w + 0.5f)); }
    glm::dvec3 worldPosition(int i) const { return cameraPosition + glm::dvec3(glm::vec3(positionVisibility[std::size_t(i)])); }
    glm::dvec3 normal(int i) const { return glm::dvec3(glm::vec3(normalMask[std::size_t(i)])); }
    float visibility(int i) const { return positionVisibility[std::size_t(i)].w; }
};

} // namespace shadowlab
