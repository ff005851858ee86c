#include "editor/transform_panel.hpp"

#include "editor/joint_clamp.hpp"

#include <imgui.h>

namespace animator {

bool TransformPanel::draw(EditorSession &session, std::string &error, std::string &note) {
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
    // A model with a joint range shows its angles read signed, as its range is (joint_clamp.hpp).
    const Model &model = session.document().models()[static_cast<size_t>(last)];
    if (!draft_) {
        shown_ = transform_values(session.state_at_time(last));
        if (model.joint)
            for (int i = 0; i < 3; ++i) shown_->rotation[i] = signed_degrees(shown_->rotation[i]);
    }
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
        if (ImGui::IsItemHovered()) {
            const std::string joint = row == 1 && model.joint
                                          ? "\nRead signed (-180..180]; a turn stops at the joint's range: " +
                                                joint_range_text(*model.joint) + "."
                                          : "";
            ImGui::SetTooltip("%s%s\nA change keys every selected model at the current time (a new keyframe if there "
                              "is none); u undoes it.\nDrag a number, or CTRL+click or double-click it to type one.",
                              kTips[row], joint.c_str());
        }
    }
    // What the scene file fixed of the model, read only (docs/manual.md, "Joints").
    if (model.joint) {
        ImGui::TextDisabled("Joint: %s", joint_range_text(*model.joint).c_str());
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("The joint's range from the scene file (a course puppet's gr.joint), degrees read signed:\n"
                              "a turn by the gizmo, a drag or the Rotation fields stops at its ends (min = max holds\n"
                              "that angle still). Read only.");
    }
    if (model.rest != glm::dmat3(1.0)) {
        ImGui::TextDisabled("Shape: sheared (fixed, from the scene file)");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("The mesh is drawn and collides under a fixed shape the scene file gave it (a course node\n"
                              "scaled unevenly after it was turned), beneath its Position, Rotation and Scale. Read only.");
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
        ModelState after = with_edited_components(before, *shown_, values);
        // A turn stops at the model's joint range, and says so (an angle not edited is left).
        const Model &turned = session.document().models()[static_cast<size_t>(m)];
        const JointClamp clamp = clamp_to_joint(turned, before, after);
        after = clamp.state;
        if (const std::string said = joint_stop_text(turned, clamp); !said.empty())
            note += (note.empty() ? "" : "; ") + said;
        if (!(after == before)) keyed.emplace_back(m, after);
    }
    if (keyed.empty()) return false;
    return session.key_states(keyed, &error);
}

} // namespace animator
