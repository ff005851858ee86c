// Golden images: compare a rendering with a stored PNG on both the largest and the mean per-pixel
// difference (Magnum's CompareImage), and on failure write the rendering and a difference image
// next to each other so a person can look.
#pragma once

#include "assets/image.hpp"

#include <filesystem>
#include <string>

namespace animator::test {

struct ImageDifference {
    double max = 0.0;  // the largest per-pixel difference, 0..255
    double mean = 0.0; // the mean per-pixel difference, 0..255
    double over = 0.0; // the fraction of pixels whose difference is above `threshold`
};

// Per pixel, the largest difference of its three channels. `diff`, when given, gets an image of
// those differences (amplified four times, so small ones show). The sizes must match.
ImageDifference compare_images(const Image &actual, const Image &expected, double threshold = 0.0,
                               Image *diff = nullptr);

// A rendering passes when at most `outliers` of its pixels differ by more than `max` and the mean
// per-pixel difference is at most `mean` (Magnum's max and mean thresholds, with Filament's
// allowance for a few pixels along edges that another CPU rasterises the other way).
struct Tolerance {
    double max;
    double outliers;
    double mean;
};

// Compares `actual` with tests/render/golden/<name>.png. Returns "" when within tolerance, else
// what differs and where the rendering and the difference image were written. With
// ANIMATOR_UPDATE_GOLDENS=1 in the environment it writes the golden instead (look at it!).
std::string check_golden(const std::string &name, const Image &actual, const Tolerance &tolerance);
// The same with the goldens in `golden_dir` and the failure images written to `out_dir`.
std::string check_golden(const std::string &name, const Image &actual, const Tolerance &tolerance,
                         const std::filesystem::path &golden_dir,
                         const std::filesystem::path &out_dir);

void write_png(const std::filesystem::path &file, const Image &image);

} // namespace animator::test
