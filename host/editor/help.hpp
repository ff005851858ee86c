// The F1 overlay (issue 17, "Help"): every key and mouse action of the editor in one place, in
// the words of docs/manual.md (a test keeps the two in step: tests/session/help_test.cpp).
#pragma once

#include <string>
#include <vector>

namespace animator {

struct HelpRow {
    std::string keys;   // as the manual's tables write them: "`u`, CTRL+Z", "Alt + left drag"
    std::string action;
};

struct HelpSection {
    std::string title;
    std::vector<HelpRow> rows;
};

const std::vector<HelpSection> &help_sections();

// Draws the overlay while *open; F1, ESC or its Close button clear *open.
void draw_help_overlay(bool *open, float width, float height);

} // namespace animator
