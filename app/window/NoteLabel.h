#pragma once

#include <QString>

class QLabel;

namespace shadowlab {

// A small, wrapping, muted label for the explanatory notes under the accuracy dock's panels.
QLabel* noteLabel(const QString& objectName);

} // namespace shadowlab
