// The .ani format's text layer (docs/ani-format.md): lines of words and quoted strings.
#pragma once

#include <animator/document_builder.hpp>

#include <string>
#include <vector>

namespace ani_format {

constexpr int kVersion = 1;
constexpr const char *kMagic = "animator-ani";

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
