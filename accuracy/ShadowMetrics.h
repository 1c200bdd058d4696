#pragma once

#include <QColor>
#include <QImage>

#include <vector>

namespace shadowlab {

// How wrong a shadow term is against a reference, over the pixels that count (receivers facing
// the light). Shares are fractions of those pixels.
struct ErrorMetrics {
    int pixels = 0;
    double misclassified = 0.0;     // |V - V_ref| > 0.5
    double falseShadow = 0.0;       // V < V_ref - 0.5: acne, over-darkening
    double falseLight = 0.0;        // V > V_ref + 0.5: peter panning, light leaks
    double mae = 0.0;               // mean |V - V_ref|
    double rmse = 0.0;
};

// `counts[i]` says whether pixel i is measured. All vectors have one entry per pixel.
ErrorMetrics compareVisibility(const std::vector<float>& measured, const std::vector<float>& reference,
                               const std::vector<bool>& counts);

// The frame in grey with false shadow in magenta and false light in cyan, so both kinds of
// error read at a glance over the scene they belong to.
QImage errorImage(const QImage& frame, const std::vector<float>& measured, const std::vector<float>& reference,
                  const std::vector<bool>& counts);

// The frame in grey with every measured pixel's |V - V_ref| as a heat colour (errorHeatColour()):
// unlike errorImage(), which shows only pixels wrong by more than half, it shows a moiré of
// partial shadow over a lit floor, wrong by a tenth here and a third there.
QImage errorHeatImage(const QImage& frame, const std::vector<float>& measured, const std::vector<float>& reference,
                      const std::vector<bool>& counts);

// The heat colour of an error `e` in [0, 1]: clear below 0.02 (the frame's grey shows through),
// then dark violet through red and orange to pale yellow at 1, on a square-root scale so an
// error of 0.1 already reads.
QColor errorHeatColour(double e);

} // namespace shadowlab
