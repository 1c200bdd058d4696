#include "ShadowMetrics.h"

#include <cmath>

namespace shadowlab {

ErrorMetrics compareVisibility(const std::vector<float>& measured, const std::vector<float>& reference, const std::vector<bool>& counts)
{
    ErrorMetrics m;
    double absolute = 0.0, squared = 0.0;
    int falseShadow = 0, falseLight = 0;
    const std::size_t n = std::min({measured.size(), reference.size(), counts.size()});
    for (std::size_t i = 0; i < n; ++i) {
        if (!counts[i])
            continue;
        const double d = double(measured[i]) - double(reference[i]);
        ++m.pixels;
        absolute += std::abs(d);
        squared += d * d;
        falseShadow += d < -0.5;
        falseLight += d > 0.5;
    }
    if (m.pixels == 0)
        return m;
    m.falseShadow = double(falseShadow) / m.pixels;
    m.falseLight = double(falseLight) / m.pixels;
    m.misclassified = m.falseShadow + m.falseLight;
    m.mae = absolute / m.pixels;
    m.rmse = std::sqrt(squared / m.pixels);
    return m;
}

QImage errorImage(const QImage& frame, const std::vector<float>& measured, const std::vector<float>& reference, const std::vector<bool>& counts)
{
    QImage image = frame.convertToFormat(QImage::Format_RGB32);
    const int width = image.width();
    for (int y = 0; y < image.height(); ++y) {
        auto* row = reinterpret_cast<QRgb*>(image.scanLine(y));
        for (int x = 0; x < width; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
            const int grey = 40 + qGray(row[x]) * 3 / 5; // dimmed so the colours stand out
            QRgb out = qRgb(grey, grey, grey);
            if (i < counts.size() && counts[i]) {
                const double d = double(measured[i]) - double(reference[i]);
                if (d < -0.5)
                    out = qRgb(235, 40, 200);   // false shadow
                else if (d > 0.5)
                    out = qRgb(40, 220, 235);   // false light
            }
            row[x] = out;
        }
    }
    return image;
}

} // namespace shadowlab
