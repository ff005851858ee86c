// The 3D view's frame budget (editor/frame_budget.hpp): slow frames lower the quality a step at a
// time, each step said once; frames within the budget change nothing; choosing starts over.
#include "editor/frame_budget.hpp"

#include <catch2/catch.hpp>

using namespace animator;

namespace {
// `count` frames of `seconds`; the lines said.
std::vector<std::string> frames(FrameBudget &budget, int count, double seconds) {
    std::vector<std::string> said;
    for (int i = 0; i < count; ++i)
        if (auto line = budget.frame(seconds)) said.push_back(*line);
    return said;
}
} // namespace

TEST_CASE("frame budget: frames within 1/60 s keep the chosen quality") {
    FrameBudget budget(1.0 / 60.0, 10);
    const ViewQuality chosen{true, 1024, 4};
    budget.choose(chosen);
    CHECK(frames(budget, 100, 0.015).empty());
    CHECK(budget.quality() == chosen);
}

TEST_CASE(
    "frame budget: slow frames turn anti-aliasing off, then reflections of other models, then "
    "take coarser levels of detail, then halve the shadow maps, a line each") {
    FrameBudget budget(1.0 / 60.0, 10);
    budget.choose({true, 1024, 4, 128});
    auto said = frames(budget, 10, 0.025);
    REQUIRE(said.size() == 1);
    CHECK_THAT(said[0], Catch::Contains("25.0 ms") && Catch::Contains("16.7 ms") &&
                            Catch::Contains("anti-aliasing off"));
    CHECK(budget.quality() == ViewQuality{true, 1024, 1, 128});
    said = frames(budget, 10, 0.025);
    REQUIRE(said.size() == 1);
    CHECK_THAT(said[0], Catch::Contains("reflections of other models off"));
    CHECK(budget.quality() == ViewQuality{true, 1024, 1, 0});
    // Surfaces within 2 pixels of the mesh's instead of half a pixel, mirrors and glass too.
    said = frames(budget, 10, 0.025);
    REQUIRE(said.size() == 1);
    CHECK_THAT(said[0], Catch::Contains("coarser levels of detail"));
    CHECK(budget.quality() == ViewQuality{true, 1024, 1, 0, 100, 2.0, true});
    said = frames(budget, 10, 0.025);
    REQUIRE(said.size() == 1);
    CHECK_THAT(said[0], Catch::Contains("512 texels"));
    CHECK(budget.quality() == ViewQuality{true, 512, 1, 0, 100, 2.0, true});
    // Then fewer pixels: 75%, then 50% of the view's along each side.
    said = frames(budget, 10, 0.025);
    REQUIRE(said.size() == 1);
    CHECK_THAT(said[0], Catch::Contains("75% resolution") && Catch::Contains("View > Resolution"));
    CHECK(budget.quality() == ViewQuality{true, 512, 1, 0, 75, 2.0, true});
    said = frames(budget, 10, 0.025);
    REQUIRE(said.size() == 1);
    CHECK_THAT(said[0], Catch::Contains("50% resolution"));
    CHECK(budget.quality() == ViewQuality{true, 512, 1, 0, 50, 2.0, true});
    // Nothing cheaper left that the user did not choose: nothing more is said.
    CHECK(frames(budget, 50, 0.025).empty());
    // A few slow frames among fast ones (the median) change nothing.
    budget.choose({true, 1024, 4});
    for (int i = 0; i < 30; ++i) CHECK_FALSE(budget.frame(i % 3 == 0 ? 0.05 : 0.01));
    CHECK(budget.quality() == ViewQuality{true, 1024, 4});
}

TEST_CASE(
    "frame budget: without anti-aliasing and reflections the first step is the levels of detail, "
    "and a pause starts a new window") {
    FrameBudget budget(1.0 / 60.0, 10);
    budget.choose({true, 1024, 1, 0});
    frames(budget, 9, 0.03);
    budget.pause(); // idle: those nine do not count
    CHECK(frames(budget, 9, 0.03).empty());
    const auto said = frames(budget, 1, 0.03);
    REQUIRE(said.size() == 1);
    CHECK(budget.quality() == ViewQuality{true, 1024, 1, 0, 100, 2.0, true});
}

TEST_CASE("frame budget: levels of detail already coarser than its own are kept, and whole "
          "meshes (detail 0) are not made coarse") {
    FrameBudget budget(1.0 / 60.0, 10);
    // Coarser than 2 pixels already, mirrors too: the step is passed over.
    budget.choose({true, 1024, 1, 0, 100, 3.0, true});
    REQUIRE(frames(budget, 10, 0.03).size() == 1);
    CHECK(budget.quality() == ViewQuality{true, 512, 1, 0, 100, 3.0, true});
    // Coarser, but mirrors whole: mirrors take levels, the pixels stay.
    budget.choose({true, 1024, 1, 0, 100, 3.0, false});
    REQUIRE(frames(budget, 10, 0.03).size() == 1);
    CHECK(budget.quality() == ViewQuality{true, 1024, 1, 0, 100, 3.0, true});
    // Detail 0 (every mesh whole, asked for): left so.
    budget.choose({true, 1024, 1, 0, 100, 0.0, false});
    REQUIRE(frames(budget, 10, 0.03).size() == 1);
    CHECK(budget.quality() == ViewQuality{true, 512, 1, 0, 100, 0.0, false});
}

TEST_CASE("frame budget: very slow frames are judged after a second of them, not a whole window") {
    FrameBudget budget(1.0 / 60.0, 30, 1.0);
    budget.choose({true, 1024, 4, 128, 100});
    // 0.3 s a frame: the fourth frame ends the first second (three are not enough).
    CHECK(frames(budget, 3, 0.3).empty());
    auto said = frames(budget, 1, 0.3);
    REQUIRE(said.size() == 1);
    CHECK_THAT(said[0], Catch::Contains("300.0 ms") && Catch::Contains("anti-aliasing off"));
    // A view the user chose at 50% is not lowered further: its levels of detail are the one
    // step left.
    budget.choose({false, 1024, 1, 0, 50});
    said = frames(budget, 40, 0.3);
    REQUIRE(said.size() == 1);
    CHECK_THAT(said[0], Catch::Contains("coarser levels of detail"));
    CHECK(budget.quality() == ViewQuality{false, 1024, 1, 0, 50, 2.0, true});
    // Two frames of a second each are too few to judge by (at least 3).
    budget.choose({true, 1024, 4, 128, 100});
    CHECK(frames(budget, 2, 1.0).empty());
    CHECK(frames(budget, 1, 1.0).size() == 1);
}
