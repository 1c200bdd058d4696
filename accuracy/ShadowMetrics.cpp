#include "ShadowMetrics.h"

#include <algorithm>
#include <cmath>
#include <optional>

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

namespace {

// The frame dimmed to grey, and over it `colour(i)` for each measured pixel i that has one.
template <typename Colour>
QImage overGreyFrame(const QImage& frame, const std::vector<bool>& counts, Colour colour)
{
    QImage image = frame.convertToFormat(QImage::Format_RGB32);
    const int width = image.width();
    for (int y = 0; y < image.height(); ++y) {
        auto* row = reinterpret_cast<QRgb*>(image.scanLine(y));
        for (int x = 0; x < width; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
            const int grey = 40 + qGray(row[x]) * 3 / 5; // dimmed so the colours stand out
            row[x] = qRgb(grey, grey, grey);
            if (i < counts.size() && counts[i]) {
                if (const std::optional<QRgb> c = colour(i))
                    row[x] = *c;
            }
        }
    }
    return image;
}

} // namespace

QImage errorImage(const QImage& frame, const std::vector<float>& measured, const std::vector<float>& reference, const std::vector<bool>& counts)
{
    return overGreyFrame(frame, counts, [&](std::size_t i) -> std::optional<QRgb> {
        const double d = double(measured[i]) - double(reference[i]);
        if (d < -0.5)
            return qRgb(235, 40, 200);      // false shadow
        if (d > 0.5)
            return qRgb(40, 220, 235);      // false light
        return std::nullopt;
    });
}

QColor errorHeatColour(double e)
{
    // Stops of a perceptually ordered ramp (after matplotlib's inferno), by sqrt(e).
    static const QColor stops[] = {QColor(40, 11, 84), QColor(136, 34, 106), QColor(212, 72, 66), QColor(250, 153, 11), QColor(252, 255, 164)};
    const double t = std::sqrt(std::clamp(e, 0.0, 1.0)) * 4.0;
    const int i = std::min(3, int(t));
    const double f = t - i;
    const QColor& a = stops[i];
    const QColor& b = stops[i + 1];
    return QColor(int(std::lround(a.red() + f * (b.red() - a.red()))), int(std::lround(a.green() + f * (b.green() - a.green()))),
                  int(std::lround(a.blue() + f * (b.blue() - a.blue()))));
}

QImage errorHeatImage(const QImage& frame, const std::vector<float>& measured, const std::vector<float>& reference, const std::vector<bool>& counts)
{
    return overGreyFrame(frame, counts, [&](std::size_t i) -> std::optional<QRgb> {
        const double e = std::abs(double(measured[i]) - double(reference[i]));
        return e >= 0.02 ? std::optional(errorHeatColour(e).rgb()) : std::nullopt;
    });
}

} // namespace shadowlab
