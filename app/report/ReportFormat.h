#pragma once

#include <QString>

// What the report's writers share: numbers as every format writes them.
namespace shadowlab::reportformat {

inline QString number(double v, int decimals = 4)
{
    return QString::number(v, 'f', decimals);
}

} // namespace shadowlab::reportformat
