// The editor's View settings (anti-aliasing, shadows, reflections of other models): how the 3D view is drawn, not part of
// any animation. Kept beside the recent files list, in $XDG_STATE_HOME/animator/view
// (~/.local/state/animator/view without it), one "name value" line each.
#pragma once

#include <filesystem>
#include <string>

namespace animator {

struct ViewSettings {
    int msaa = 4;        // samples per pixel of the 3D view, 1, 2, 4 or 8 (1: no anti-aliasing)
    bool shadows = true; // shadow maps from the scene's lights
    // Reflective and transparent models show the models around them (a cube map each, drawn
    // every frame: render/reflection_probes.hpp); off: the skybox only.
    bool reflections = true;
    // The share of the view's pixels drawn along each axis, in percent (kResolutions): below
    // 100 the scene is drawn smaller and stretched onto the view, with fewer pixels to shade.
    int resolution = 100;
    bool operator==(const ViewSettings &o) const {
        return msaa == o.msaa && shadows == o.shadows && reflections == o.reflections &&
               resolution == o.resolution;
    }
    bool operator!=(const ViewSettings &o) const { return !(*this == o); }
};

// The resolutions the View menu offers, in percent of the view's pixels along each axis, from
// the highest down (the frame budget lowers a view through them in this order).
constexpr int kResolutions[] = {100, 75, 50};
bool valid_resolution(int percent);

// Where the View settings are kept; empty without XDG_STATE_HOME or HOME.
std::filesystem::path view_settings_path();

// The settings in `file`; the defaults for a missing file or a line it does not understand
// (`warning` then says which, once).
ViewSettings load_view_settings(const std::filesystem::path &file, std::string *warning = nullptr);
// Writes them atomically (write_state_file: a failure leaves the old file whole), making the
// folder; false with `error` set when it cannot.
bool save_view_settings(const std::filesystem::path &file, const ViewSettings &settings,
                        std::string *error = nullptr);

} // namespace animator
