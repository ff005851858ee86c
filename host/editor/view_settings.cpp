#include "editor/view_settings.hpp"

#include "editor/state_folder.hpp"
#include "render/framebuffer.hpp"

#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace animator {

fs::path view_settings_path() { return state_path("view"); }

bool valid_resolution(int percent) {
    for (const int r : kResolutions)
        if (r == percent) return true;
    return false;
}

ViewSettings load_view_settings(const fs::path &file, std::string *warning) {
    ViewSettings s;
    std::error_code ec;
    if (file.empty() || !fs::exists(file, ec)) return s;
    std::ifstream in(file);
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        std::istringstream words(line);
        std::string name;
        int value = 0;
        if (!(words >> name)) continue;
        const bool read = static_cast<bool>(words >> value);
        if (read && name == "msaa" && valid_sample_count(value)) {
            s.msaa = value;
        } else if (read && name == "shadows" && (value == 0 || value == 1)) {
            s.shadows = value == 1;
        } else if (read && name == "reflections" && (value == 0 || value == 1)) {
            s.reflections = value == 1;
        } else if (read && name == "resolution" && valid_resolution(value)) {
            s.resolution = value;
        } else if (warning && warning->empty()) {
            *warning = file.string() + ":" + std::to_string(number) + ": '" + line +
                       "' is not a View setting (msaa " + sample_counts_text() +
                       ", shadows 0 or 1, reflections 0 or 1, resolution 100, 75 or 50); ignored";
        }
    }
    return s;
}

bool save_view_settings(const fs::path &file, const ViewSettings &settings, std::string *error) {
    if (file.empty()) return true;
    const std::string text = "msaa " + std::to_string(settings.msaa) + "\nshadows " + (settings.shadows ? "1" : "0") +
                             "\nreflections " + (settings.reflections ? "1" : "0") + "\nresolution " +
                             std::to_string(settings.resolution) + "\n";
    std::string why;
    if (write_state_file(file, text, &why)) return true;
    if (error) *error = "cannot write the View settings " + file.string() + ": " + why;
    return false;
}

} // namespace animator
