// The F1 overlay (issue 17, "Help"): every key and mouse action of the editor in one place, in
// the words of docs/manual.md (a test keeps the two in step: tests/session/help_test.cpp).
#pragma once

#include <optional>
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

// What a key other programs bind says here ("g: Blender's grab: choose Translate..."): the
// overlay's "Coming from Blender or Maya" rows; `key` as written there without backquotes
// ("g", "TAB"). Nothing for any other key.
std::optional<std::string> familiar_key_hint(const std::string &key);

// Draws the overlay while *open; F1, ESC or its Close button clear *open.
void draw_help_overlay(bool *open, float width, float height);

} // namespace animator
