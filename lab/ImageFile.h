#pragma once

#include <QByteArray>

class QImage;

namespace shadowlab {

// The image as PNG bytes, for writeOutputFile(); throws OutputError(WriteFailed) if it cannot
// be encoded.
QByteArray encodePng(const QImage& image);

} // namespace shadowlab
