#include "image_compare.hpp"

#include "support.hpp"

#include <stb_image_write.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>

namespace animator::test {

ImageDifference compare_images(const Image &actual, const Image &expected, double threshold,
                               Image *diff) {
    ImageDifference d;
    const size_t pixels = static_cast<size_t>(actual.width) * static_cast<size_t>(actual.height);
    if (diff) {
        diff->width = actual.width;
        diff->height = actual.height;
        diff->rgb.assign(pixels * 3, 0);
    }
    double total = 0.0;
    size_t over = 0;
    for (size_t p = 0; p < pixels; ++p) {
        int worst = 0;
        for (size_t c = 0; c < 3; ++c)
            worst = std::max(worst,
                             std::abs(int(actual.rgb[p * 3 + c]) - int(expected.rgb[p * 3 + c])));
        d.max = std::max(d.max, double(worst));
        total += worst;
        over += worst > threshold;
        if (diff)
            for (size_t c = 0; c < 3; ++c)
                diff->rgb[p * 3 + c] = static_cast<std::uint8_t>(std::min(255, worst * 4));
    }
    d.mean = pixels ? total / double(pixels) : 0.0;
    d.over = pixels ? double(over) / double(pixels) : 0.0;
    return d;
}

void write_png(const std::filesystem::path &file, const Image &image) {
    std::filesystem::create_directories(file.parent_path());
    if (!stbi_write_png(file.c_str(), image.width, image.height, 3, image.rgb.data(),
                        image.width * 3))
        throw std::runtime_error(file.string() + ": cannot be written");
}

std::string check_golden(const std::string &name, const Image &actual, const Tolerance &tolerance) {
    return check_golden(name, actual, tolerance, source_dir() / "tests/render/golden",
                        std::filesystem::path(ANIMATOR_TEST_TMP_DIR) / "render_golden");
}

std::string check_golden(const std::string &name, const Image &actual, const Tolerance &tolerance,
                         const std::filesystem::path &golden_dir,
                         const std::filesystem::path &out_dir) {
    const auto golden = golden_dir / (name + ".png");
    const char *update = std::getenv("ANIMATOR_UPDATE_GOLDENS");
    if (update && std::string(update) == "1") {
        write_png(golden, actual);
        return "";
    }
    const auto actual_file = out_dir / (name + ".actual.png");
    const auto diff_file = out_dir / (name + ".diff.png");
    if (!std::filesystem::exists(golden)) {
        write_png(actual_file, actual);
        return "no golden image " + golden.string() + "; the rendering is in " +
               actual_file.string() + " (look at it, then run with ANIMATOR_UPDATE_GOLDENS=1)";
    }
    const Image expected = load_image(golden);
    if (expected.width != actual.width || expected.height != actual.height) {
        write_png(actual_file, actual);
        return golden.string() + " is " + std::to_string(expected.width) + "x" +
               std::to_string(expected.height) + ", the rendering " + std::to_string(actual.width) +
               "x" + std::to_string(actual.height) + " (" + actual_file.string() + ")";
    }
    Image diff;
    const ImageDifference d = compare_images(actual, expected, tolerance.max, &diff);
    if (d.over <= tolerance.outliers && d.mean <= tolerance.mean) return "";
    write_png(actual_file, actual);
    write_png(diff_file, diff);
    std::ostringstream out;
    out << name << ": " << d.over * 100.0 << "% of the pixels differ by more than " << tolerance.max
        << " (tolerance " << tolerance.outliers * 100.0 << "%), the largest by " << d.max
        << "; mean difference " << d.mean << " (tolerance " << tolerance.mean << "); rendering "
        << actual_file.string() << ", difference " << diff_file.string();
    return out.str();
}

} // namespace animator::test
