// Shared by the tests: where the build put things, temporary folders, and running the real
// `animator` executable.
#pragma once

#include "document/document.hpp"

#include <filesystem>
#include <random>
#include <string>

namespace animator::test {

std::filesystem::path bin_dir();
std::filesystem::path source_dir();
// A fresh, empty folder for one test, under the build tree (its name and the process id: the
// cases ctest runs in parallel each have their own).
std::filesystem::path fresh_dir(const std::string &name);

struct CommandResult {
    int exit_code = -1;
    std::string out; // stdout and stderr together
};
// Runs `animator ARGS` with the given environment prefix (e.g. "ANIMATOR_PLUGIN_PATH=x").
CommandResult run_animator(const std::string &args, const std::string &env = "");

std::string read_file(const std::filesystem::path &path);
void write_file(const std::filesystem::path &path, const std::string &text);

// How many times `needle` occurs in `text` (overlapping occurrences too).
size_t count_in(const std::string &text, const std::string &needle);

// A document of `models` models and `keyframes` keyframes with random but valid content.
Document random_document(std::mt19937 &rng, int models, int keyframes);

} // namespace animator::test
