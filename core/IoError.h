#pragma once

#include <QString>

#include <stdexcept>

namespace shadowlab {

// A file or folder that cannot be read or written: names the path and what the system said.
class IoError : public std::runtime_error {
public:
    explicit IoError(const QString& message) : std::runtime_error(message.toStdString()) {}
};

} // namespace shadowlab
