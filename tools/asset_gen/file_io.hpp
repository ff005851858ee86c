// Writing output files; failures throw so main() can report them and exit non-zero, which makes
// the build step fail instead of leaving a half-written asset folder behind silently.
#pragma once

#include <filesystem>
#include <string>

namespace animator::assetgen {

// Creates the parent folders as needed.
void write_bytes(const std::filesystem::path &path, const std::string &bytes);

} // namespace animator::assetgen
