#pragma once

namespace shadowlab {

// How far apart two errors must be to differ. An error is a count of pixels: misclassified
// ones, or MAE times the pixels measured (the error as fully wrong pixels). A sub-texel move of
// camera or light slides the pixels along every shadow edge in or out of error, so a count n
// scatters by about √n, as a Poisson count does; and below a few pixels nothing is resolved.
// A count n is therefore n ± max(3, 2√n) pixels, and one error is below another only when their
// bands do not overlap, as one time is below another only when its p90 is below the other's p10.
double errorNoisePixels(double count);

// `count`'s band lies wholly below `other`'s.
bool clearlyFewer(double count, double other);

} // namespace shadowlab
