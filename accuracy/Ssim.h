#pragma once

#include <vector>

namespace shadowlab {

// A grey image of values in [0, 1] (the dynamic range L of SSIM is 1), rows top to bottom.
// Floats: their rounding is far below SSIM's constants, and a 4K frame's local moments take
// half the memory.
struct GreyImage {
    int width = 0;
    int height = 0;
    std::vector<float> values;      // width * height
};

// The structural similarity index of Wang, Bovik, Sheikh and Simoncelli, "Image Quality
// Assessment: From Error Visibility to Structural Similarity" (IEEE TIP 13(4), 2004): for each
// 11 x 11 window, weighted by a circular Gaussian of sigma 1.5 normalised to sum 1,
//     SSIM = (2 mu_a mu_b + C1)(2 sigma_ab + C2) / ((mu_a² + mu_b² + C1)(sigma_a² + sigma_b² + C2)),
// C1 = (0.01 L)², C2 = (0.03 L)², and the mean over every window that lies wholly inside the
// image (the paper's MSSIM). 1 for identical images, lower as structure differs. An image
// narrower or lower than 11 pixels gets the largest odd window that fits it, its Gaussian cut
// there and normalised again. Images of different sizes, or empty ones, give 0.
double meanSsim(const GreyImage& a, const GreyImage& b);

} // namespace shadowlab
