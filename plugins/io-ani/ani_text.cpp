#include "ani_text.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace ani_format {

bool tokenize(const std::string &line, std::vector<Token> &tokens, std::string &error) {
    tokens.clear();
    if (line.find('\0') != std::string::npos) {
        // C strings stop at a NUL: a name or a number would mean one thing here and another
        // to everything the document's C strings reach.
        error = "a NUL byte; an .ani file is text";
        return false;
    }
    size_t i = 0;
    while (i < line.size()) {
        const char c = line[i];
        if (c == ' ' || c == '\t' || c == '\r') {
            ++i;
        } else if (c == '#') {
            break; // a comment runs to the end of the line
        } else if (c == '"') {
            Token t;
            t.quoted = true;
            ++i;
            bool closed = false;
            while (i < line.size()) {
                char d = line[i++];
                if (d == '"') {
                    closed = true;
                    break;
                }
                if (d == '\\') {
                    if (i >= line.size()) break;
                    const char e = line[i++];
                    if (e == 'n') d = '\n';
                    else if (e == '"' || e == '\\') d = e;
                    else {
                        error = std::string("unknown escape '\\") + e + "' in a string";
                        return false;
                    }
                }
                t.text.push_back(d);
            }
            if (!closed) {
                error = "a string is not closed with '\"'";
                return false;
            }
            tokens.push_back(std::move(t));
        } else {
            Token t;
            while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r' &&
                   line[i] != '"' && line[i] != '#')
                t.text.push_back(line[i++]);
            tokens.push_back(std::move(t));
        }
    }
    return true;
}

std::string size_beyond_limits(std::size_t models, std::size_t keyframes, std::size_t params) {
    if (params > kMaxParams)
        return std::to_string(params) + " parameter values; a file holds at most " +
               std::to_string(kMaxParams);
    // A keyframe without models still costs its own record, hence max(models, 1).
    const std::size_t per_keyframe = models > 0 ? models : 1;
    if (models > kMaxModelStates || keyframes > kMaxModelStates / per_keyframe)
        return std::to_string(models) + " models and " + std::to_string(keyframes) +
               " keyframes; a file holds at most " + std::to_string(kMaxModelStates) +
               " model states (keyframes x models)";
    return "";
}

std::string quote(const std::string &s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out.push_back('\\');
        if (c == '\n') {
            out += "\\n";
            continue;
        }
        out.push_back(c);
    }
    return out + "\"";
}

std::string number(double x) {
    char buf[64];
    for (int precision = 15; precision <= 17; ++precision) {
        (void)std::snprintf(buf, sizeof buf, "%.*g", precision, x);
        if (std::strtod(buf, nullptr) == x) break;
    }
    return buf;
}

} // namespace ani_format
