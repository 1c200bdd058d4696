#pragma once

#include <QString>

#include <stdexcept>

namespace shadowlab {

// The ray tracer (Embree) could not start or build its scene.
class TraceError : public std::runtime_error {
public:
    explicit TraceError(const QString& message) : std::runtime_error(message.toStdString()) {}
};

} // namespace shadowlab
