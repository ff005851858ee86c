#include "editor/transform_panel.hpp"

#include <imgui.h>

namespace animator {

bool TransformPanel::draw(EditorSession &session, std::string &error) {
    const int last = session.last_selected();
    if (last < 0 || !session.selection().count(last)) return false;
    const bool open = ImGui::CollapsingHeader("Transform", ImGuiTreeNodeFlags_DefaultOpen);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Where the selected models are at the current time: typing or dragging a number keys them\n"
                          "there (also what the gizmo's handles change). Click to fold.");
    if (!open) return false;
    std::vector<ModelState> states;
    for (int m : session.selection()) states.push_back(session.state_at_time(m));
    const std::array<bool, 3> mixed = transform_mixed(states);
    // What the rows show follows the time, a drag, an undo: not while a row is held or typed.
    if (!draft_) shown_ = transform_values(session.state_at_time(last));
    TransformValues values = draft_ ? *draft_ : *shown_;

    static const char *const kLabels[3] = {"Position (m)", "Rotation (deg)", "Scale"};
    static const char *const kTips[3] = {
        "The center's x, y, z in its parent's frame (the world's for a model at the root).",
        "The Euler angles about x, then y, then z, in degrees (the gizmo's rings turn them one by one).",
        "The scale along the model's own x, y, z (> 0)."};
    const float speeds[3] = {0.01f, 0.5f, 0.01f};
    const double scale_min = 0.001, scale_max = 1000.0;
    bool active = false, commit = false;
    for (int row = 0; row < 3; ++row) {
        glm::dvec3 &v = values.row(row);
        double xyz[3] = {v.x, v.y, v.z};
        const bool held = draft_.has_value();
        const char *format = mixed[static_cast<size_t>(row)] && !held ? "(mixed)" : "%.3f";
        const bool changed = ImGui::DragScalarN(
            mixed[static_cast<size_t>(row)] && !held ? (std::string(kLabels[row]) + " (mixed)###" + kLabels[row]).c_str()
                                                     : kLabels[row],
            ImGuiDataType_Double, xyz, 3, speeds[row], row == 2 ? &scale_min : nullptr,
            row == 2 ? &scale_max : nullptr, format, row == 2 ? ImGuiSliderFlags_AlwaysClamp : 0);
        if (changed) v = glm::dvec3(xyz[0], xyz[1], xyz[2]);
        if (ImGui::IsItemActive()) active = true;
        // One gesture, one edit: a drag when let go, a typed number when entered.
        if ((changed && !ImGui::IsItemActive()) || ImGui::IsItemDeactivatedAfterEdit()) commit = true;
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s\nA change keys every selected model at the current time (a new keyframe if there "
                              "is none); u undoes it.\nDrag a number, or CTRL+click or double-click it to type one.",
                              kTips[row]);
    }
    if (active) draft_ = values;
    if (!commit) {
        if (!active) draft_.reset();
        return false;
    }
    draft_.reset();
    std::vector<std::pair<int, ModelState>> keyed;
    for (int m : session.selection()) {
        const ModelState before = session.state_at_time(m);
        const ModelState after = with_edited_components(before, *shown_, values);
        if (!(after == before)) keyed.emplace_back(m, after);
    }
    if (keyed.empty()) return false;
    return session.key_states(keyed, &error);
}

} // namespace animator
