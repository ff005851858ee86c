// A timeline's bake in a file (docs/bake-format.md), so that the machines of a render farm
// share one bake instead of each baking its own: `animator bake FILE --save FILE.bake`, then
// `animator render FILE --bake FILE.bake` on each. The file holds a fingerprint of what the bake
// depends on (the document's motion, the backend and its parameters, the meshes collided with),
// and a bake is used only by a timeline whose fingerprint is the same.
#pragma once

#include "timeline/timeline.hpp"

#include <cstdint>
#include <filesystem>
#include <stdexcept>

namespace animator {

// A bake file that cannot be written or read, or that does not fit the timeline: the message
// starts with the file's path and says what does not match.
struct BakeFileError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

inline constexpr std::uint32_t kBakeFormatVersion = 2; // 2: carried segments (ABI 1.8)

// Writes the timeline's bake to `path`, through `.NAME.partial` beside it, renamed when whole (a
// failure part way leaves an earlier file as it was). Throws BakeFileError.
void save_bake(const Timeline &timeline, const std::filesystem::path &path);

// Gives `timeline` (its document, backend, parameters and meshes set) the bake in `path` in place
// of baking. Throws BakeFileError, leaving the timeline as it was, for a file that is not a bake,
// of another format version, truncated or corrupt, made for another document (or this one before
// an edit that changes motion), another backend, other parameters or other meshes, or that ends
// before `needed_until` seconds.
void load_bake(Timeline &timeline, const std::filesystem::path &path, double needed_until);

} // namespace animator
