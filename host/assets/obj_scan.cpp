#include "assets/obj_scan.hpp"

namespace animator {

namespace {

// Where assimp's OBJ reader ends a statement (IOStreamBuffer, IsLineEnd): a NUL, a form feed or
// a carriage return ends one as a newline does, so counting newlines alone would let a file
// hide thousands of statements on one line.
bool line_end(char c) {
    return c == '\n' || c == '\r' || c == '\0' || c == '\f';
}
bool blank(char c) {
    return c == ' ' || c == '\t' || c == '\v';
}

// One statement: its first word and how many words it has, up to a '#' comment.
struct Statement {
    std::string keyword;
    std::size_t words = 0;
    std::size_t line = 0; // of its first character, counting newlines as an editor does
};

class StatementReader {
  public:
    explicit StatementReader(const std::string &text) : text_(text) {}

    bool next(Statement &s) {
        if (at_ >= text_.size()) return false;
        s = Statement{};
        s.line = line_;
        bool in_word = false, comment = false;
        while (at_ < text_.size()) {
            const char c = text_[at_];
            // A backslash right before the end of a line continues the statement on the next
            // one, as assimp reads it.
            if (c == '\\' && at_ + 1 < text_.size() && line_end(text_[at_ + 1])) {
                skip_to_next_newline();
                in_word = false;
                continue;
            }
            if (line_end(c)) {
                step();
                break;
            }
            if (c == '#') comment = true;
            if (!comment && !blank(c)) {
                if (!in_word) ++s.words;
                if (s.words == 1) s.keyword.push_back(c);
                in_word = true;
            } else {
                in_word = false;
            }
            step();
        }
        return true;
    }

  private:
    void step() {
        if (text_[at_] == '\n') ++line_;
        ++at_;
    }
    void skip_to_next_newline() {
        while (at_ < text_.size() && text_[at_] != '\n') ++at_;
        if (at_ < text_.size()) step();
    }

    const std::string &text_;
    std::size_t at_ = 0;
    std::size_t line_ = 1;
};

} // namespace

std::string obj_beyond_limits(const std::string &name, const std::string &text) {
    std::size_t parts = 0, work = 0;
    StatementReader reader(text);
    Statement s;
    while (reader.next(s)) {
        auto fail = [&](const std::string &what) {
            return name + ":" + std::to_string(s.line) + ": " + what;
        };
        // assimp reads a statement by its first character: any word starting with 'f' is a
        // face (and 'l' and 'p' lines and points), with 'o' an object, with 'g' a group.
        const char first = s.keyword.empty() ? ' ' : s.keyword[0];
        if (first == 'f' || first == 'l' || first == 'p') {
            const std::size_t corners = s.words - 1;
            if (corners > kMaxPolygonCorners)
                return fail("a face of " + std::to_string(corners) + " corners; at most " +
                            std::to_string(kMaxPolygonCorners) + " are read");
            work += corners * corners;
            if (work > kMaxTriangulationWork)
                return fail("the faces so far would take too long to triangulate (the sum of their "
                            "squared corner counts passes " +
                            std::to_string(kMaxTriangulationWork) + "); split the large polygons");
        } else if (first == 'o' || first == 'g' || s.keyword == "usemtl") {
            if (++parts > kMaxObjParts)
                return fail("more than " + std::to_string(kMaxObjParts) +
                            " objects, groups and material changes ('o', 'g', 'usemtl')");
        }
    }
    return "";
}

} // namespace animator
