// The .ani format's text layer (docs/ani-format.md): lines of words and quoted strings.
#pragma once

#include <animator/document_builder.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace ani_format {

constexpr int kVersion = 2; // the newest this reads; a writer writes the oldest that holds the document
constexpr const char *kMagic = "animator-ani";

// What a file may hold, so that no file, however hostile, costs the reader more than about a
// hundred MiB (docs/ani-format.md, "Limits"). A line is read into memory whole. The document
// holds a state for every model at every keyframe, so a file of a few megabytes naming
// thousands of models and thousands of keyframes would otherwise need gigabytes.
constexpr std::size_t kMaxLineBytes = std::size_t{1} << 20;   // 1 MiB
constexpr std::size_t kMaxModelStates = std::size_t{1} << 20; // keyframes x max(models, 1)
constexpr std::size_t kMaxParams = std::size_t{1} << 16;      // param lines in settings

// Empty when a document of this size is within the limits above, else what is too large.
std::string size_beyond_limits(std::size_t models, std::size_t keyframes, std::size_t params);

// A line split into tokens: bare words, and "quoted strings" with \" \\ \n escapes.
struct Token {
    std::string text;
    bool quoted = false;
};

// Returns false and sets `error` for an unterminated string or a bad escape.
bool tokenize(const std::string &line, std::vector<Token> &tokens, std::string &error);
// The token form of a string: always quoted, escaped.
std::string quote(const std::string &s);
// Shortest text of a double that reads back as the same double.
std::string number(double x);

// Reads `path`; on failure returns false with "path:line: what was expected" in `error`.
// `host` (may be null) offers the assets extension, used to report an unknown mesh at its line.
bool read_ani(const char *path, const ani_host *host, ani::OwnedDocument &doc, std::string &error);
// Writes atomically; on failure returns false with the reason, and any old file is intact.
bool write_ani(const char *path, const ani_document_view &doc, std::string &error);

} // namespace ani_format
