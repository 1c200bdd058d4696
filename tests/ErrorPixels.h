#pragma once

#include <QImage>

// Pixels of an error image (or a screenshot of one over a view) painted as false shadow: the
// magenta of AccuracyMeter's errorImage(), after blending over the greyed scene.
inline int falseShadowPixels(const QImage& image, int step = 1)
{
    int n = 0;
    for (int y = 0; y < image.height(); y += step)
        for (int x = 0; x < image.width(); x += step) {
            const QRgb c = image.pixel(x, y);
            n += qRed(c) > 180 && qBlue(c) > 150 && qGreen(c) < 100;
        }
    return n;
}
