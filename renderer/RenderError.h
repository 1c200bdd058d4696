#pragma once

#include <QString>

#include <stdexcept>

namespace shadowlab {

// A GL-side failure the user can act on: a shader that does not compile (file and driver log),
// a framebuffer that is incomplete, a texture the driver cannot allocate.
class RenderError : public std::runtime_error {
public:
    explicit RenderError(const QString& message) : std::runtime_error(message.toStdString()) {}
};

} // namespace shadowlab
