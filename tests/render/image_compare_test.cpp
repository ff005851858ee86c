// The golden-image comparison itself: what it measures and what it writes on a failure.
#include "image_compare.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

using namespace animator;
using namespace animator::test;

namespace {
Image flat(int w, int h, std::uint8_t value) {
    Image i;
    i.width = w;
    i.height = h;
    i.rgb.assign(static_cast<size_t>(w * h * 3), value);
    return i;
}
} // namespace

TEST_CASE("image comparison measures the largest and mean per-pixel difference and the pixels over "
          "a threshold") {
    Image a = flat(4, 2, 100), b = flat(4, 2, 100);
    CHECK(compare_images(a, b).max == 0.0);
    b.rgb[1] = 140;  // pixel 0, green: 40
    b.rgb[5] = 90;   // pixel 1, blue: 10
    b.rgb[23] = 108; // pixel 7, blue: 8
    Image diff;
    const ImageDifference d = compare_images(a, b, 9.0, &diff);
    CHECK(d.max == 40.0);
    CHECK(d.mean == Approx((40.0 + 10.0 + 8.0) / 8.0));
    CHECK(d.over == Approx(2.0 / 8.0)); // 40 and 10 are above 9, 8 is not
    REQUIRE(diff.rgb.size() == a.rgb.size());
    CHECK(diff.rgb[0] == 160); // amplified four times
    CHECK(diff.rgb[3] == 40);
    CHECK(diff.rgb[6] == 0);
}

TEST_CASE("a golden failure writes the rendering and the difference image") {
    const auto goldens = test::fresh_dir("image_compare_goldens");
    const auto out = test::fresh_dir("image_compare_out");
    const Image actual = flat(8, 8, 200);
    const std::string missing = check_golden("absent", actual, {1.0, 0.0, 1.0}, goldens, out);
    CHECK_THAT(missing, Catch::Contains("no golden image"));
    CHECK(std::filesystem::exists(out / "absent.actual.png"));

    write_png(goldens / "grey.png", flat(8, 8, 100));
    CHECK(check_golden("grey", flat(8, 8, 101), {1.0, 0.0, 1.0}, goldens, out).empty());
    CHECK_FALSE(std::filesystem::exists(out / "grey.diff.png")); // nothing written on a pass
    Image one_off = flat(8, 8, 100);
    one_off.rgb[0] = 255; // one pixel of 64 far off: within 2% outliers, not within 1%
    CHECK(check_golden("grey", one_off, {8.0, 0.02, 4.0}, goldens, out).empty());
    CHECK_FALSE(check_golden("grey", one_off, {8.0, 0.01, 4.0}, goldens, out).empty());
    // A small difference everywhere fails on the mean.
    CHECK_THAT(check_golden("grey", flat(8, 8, 104), {8.0, 0.0, 3.0}, goldens, out),
               Catch::Contains("mean difference 4"));
    const std::string problem = check_golden("grey", actual, {16.0, 0.01, 1.5}, goldens, out);
    CHECK_THAT(problem, Catch::Contains("100% of the pixels differ by more than 16") &&
                            Catch::Contains("the largest by 100") &&
                            Catch::Contains("grey.diff.png"));
    REQUIRE(std::filesystem::exists(out / "grey.diff.png"));
    CHECK(load_image(out / "grey.diff.png").rgb[0] == 255);
    CHECK(load_image(out / "grey.actual.png").rgb[0] == 200);
}
