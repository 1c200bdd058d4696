#include "ImageFile.h"

#include "OutputFile.h"

#include <QBuffer>
#include <QImage>

namespace shadowlab {

QByteArray encodePng(const QImage& image)
{
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    if (image.isNull() || !image.save(&buffer, "PNG"))
        throw OutputError(OutputError::Kind::WriteFailed,
                          QStringLiteral("the %1x%2 image could not be encoded as PNG").arg(image.width()).arg(image.height()));
    return bytes;
}

} // namespace shadowlab
