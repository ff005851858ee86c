#include "editor/output_dialogs.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace fs = std::filesystem;

namespace animator {

namespace {

constexpr const char *kRenderPopup = "Render";
constexpr const char *kExportPopup = "Export";

bool escape_pressed() {
    return ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
}

// Every control says what it does (and its key) when the pointer rests on it, disabled or not.
void tip(const char *text) {
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", text);
}

// The folder beside the document, and its stem ("untitled" with the working folder when it has
// no file yet).
fs::path document_folder(const fs::path &document) {
    std::error_code ec;
    if (document.empty()) return fs::current_path(ec);
    return fs::absolute(document, ec).parent_path();
}
std::string document_stem(const fs::path &document) {
    return document.empty() ? "untitled" : document.stem().string();
}

// A path typed in a dialog: a relative one is taken from the animation's folder (where the
// defaults are), not from the folder the editor was started in.
fs::path typed_path(const std::string &text, const fs::path &document) {
    const fs::path p(text);
    return p.is_absolute() ? p : document_folder(document) / p;
}

std::string seconds_text(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f s", s);
    return text;
}

// A path as the status line shows it: relative to the document's folder when inside it (one
// line, where the Outliner below keeps its place), else whole.
std::string shown_path(const fs::path &path, const fs::path &document) {
    std::error_code ec;
    const fs::path folder = document_folder(document);
    const fs::path absolute = fs::absolute(path, ec).lexically_normal();
    const fs::path relative = absolute.lexically_relative(folder);
    if (ec || relative.empty() || *relative.begin() == "..") return path.string();
    return relative.string();
}

void replace_all(std::string &text, const std::string &from, const std::string &to) {
    if (from.empty()) return;
    for (std::size_t at = 0; (at = text.find(from, at)) != std::string::npos; at += to.size())
        text.replace(at, from.size(), to);
}

} // namespace

OutputDialogs::~OutputDialogs() {
    if (!busy()) return;
    const int done = job_.frames_done(), total = job_.frames_total();
    job_.cancel();
    // Panels, which says things on the status line, is going away with this: straight to stdout.
    std::cout << "animator: " << (running_ == Kind::Render ? "render" : "export")
              << " cancelled (the editor closed";
    if (running_ == Kind::Render)
        std::cout << "; " << done << " of " << total << " frames drawn, left in "
                  << request_.out.string();
    std::cout << ")" << std::endl;
}

void OutputDialogs::draw(EditorSession &session) {
    if (running_ != Kind::None) follow_job();
    if (open_ != Kind::None && running_ == Kind::None &&
        !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel)) {
        // Filled again for another document; for the same one the last choices stay.
        const bool other = document_path_ != session.path() || out_.empty();
        document_path_ = session.path();
        const fs::path folder = document_folder(document_path_);
        const std::string stem = document_stem(document_path_);
        if (other) {
            out_ = (folder / (stem + "_render")).string() + "/";
            video_path_ = (folder / (stem + ".mp4")).string();
            trace_path_ = (folder / (stem + "_trace.csv")).string();
            soundtrack_path_ = (folder / (stem + "_soundtrack.wav")).string();
            gltf_path_ = (folder / (stem + ".glb")).string();
            from_ = 0.0;
            to_ = session.max_time();
        }
        to_ = std::min(to_, session.max_time());
        if (!find_ffmpeg()) video_ = false;
        ImGui::OpenPopup(open_ == Kind::Render ? kRenderPopup : kExportPopup);
        open_ = Kind::None;
        close_popup_ = false;
    } else if (open_ != Kind::None && running_ != Kind::None) {
        say_(std::string("a ") + (running_ == Kind::Render ? "render" : "export") +
                 " is running: wait for it or cancel it",
             true);
        open_ = Kind::None;
    }
    // A running job's dialog comes back if another dialog (the quit question) took its place.
    const char *running_popup = running_ == Kind::Render ? kRenderPopup : kExportPopup;
    if (running_ != Kind::None &&
        !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel))
        ImGui::OpenPopup(running_popup);

    if (ImGui::BeginPopupModal(kRenderPopup, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        if (close_popup_) {
            ImGui::CloseCurrentPopup();
            close_popup_ = false;
        } else if (running_ == Kind::Render)
            progress();
        else if (running_ == Kind::None)
            render_form(session);
        else
            ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
    if (ImGui::BeginPopupModal(kExportPopup, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        if (close_popup_) {
            ImGui::CloseCurrentPopup();
            close_popup_ = false;
        } else if (running_ == Kind::Export)
            progress();
        else if (running_ == Kind::None)
            export_form(session);
        else
            ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
}

void OutputDialogs::render_form(EditorSession &session) {
    const double max_time = session.max_time();
    const std::optional<fs::path> ffmpeg = find_ffmpeg();
    ImGui::Text("Render %s as it is now (unsaved changes included)",
                document_stem(session.path()).c_str());
    int kind = video_ ? 1 : 0;
    ImGui::RadioButton("Frames (PNG)", &kind, 0);
    tip("Write one PNG file a frame, frame_00000.png, ... into the folder below.");
    ImGui::SameLine();
    ImGui::BeginDisabled(!ffmpeg);
    ImGui::RadioButton("Video (.mp4)", &kind, 1);
    ImGui::EndDisabled();
    tip(ffmpeg ? "Also put the frames and the soundtrack together into an .mp4 video with ffmpeg\n"
                 "(the frames and soundtrack.wav stay in the folder below)."
               : "Needs ffmpeg, which is not installed (on Debian: sudo apt-get install ffmpeg).");
    if (!ffmpeg) {
        ImGui::SameLine();
        ImGui::TextDisabled("(needs ffmpeg, not installed)");
    }
    video_ = kind == 1 && ffmpeg;

    ImGui::SetNextItemWidth(200.0f);
    ImGui::InputInt2("Size (px)", size_);
    tip("The width and height of every frame in pixels (1 to 16384 each).");
    ImGui::SetNextItemWidth(200.0f);
    ImGui::InputDouble("Frames per second", &fps_, 1.0, 10.0, "%.3f");
    tip("How many frames a second of animation gets (0.001 to 1000).");
    ImGui::SetNextItemWidth(200.0f);
    ImGui::InputDouble("From (s)", &from_, 0.1, 1.0, "%.3f");
    tip("The first frame's time in seconds.");
    ImGui::SetNextItemWidth(200.0f);
    ImGui::InputDouble("To (s)", &to_, 0.1, 1.0, "%.3f");
    tip("The last frame's time in seconds (at most the animation's max time).");
    ImGui::SetNextItemWidth(420.0f);
    ImGui::InputText("Frames folder", &out_);
    tip("The folder the PNG frames go into (made when missing; frames already there are "
        "replaced).\n"
        "A relative path is taken from the animation's folder.");
    if (video_) {
        ImGui::SetNextItemWidth(420.0f);
        ImGui::InputText("Video file", &video_path_);
        tip("The .mp4 file to write (replaced only when complete). A relative path is taken from "
            "the\n"
            "animation's folder.");
    }

    std::string problem;
    if (size_[0] < 1 || size_[1] < 1 || size_[0] > 16384 || size_[1] > 16384)
        problem = "the size must be 1 to 16384 pixels each way";
    else if (!(fps_ >= 0.001 && fps_ <= 1000.0))
        problem = "frames per second must be 0.001 to 1000";
    else if (!(from_ >= 0.0 && from_ <= to_))
        problem = "From must be at least 0 and at most To";
    else if (to_ > max_time)
        problem = "To must be at most the max time, " + seconds_text(max_time);
    else if (out_.empty())
        problem = "name the folder for the frames";
    else if (video_ && video_path_.empty())
        problem = "name the video file";
    const int count = problem.empty() ? render_frame_count(from_, to_, fps_) : 0;
    if (!problem.empty())
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", problem.c_str());
    else
        ImGui::Text("%d frame%s of %dx%d", count, count == 1 ? "" : "s", size_[0], size_[1]);

    ImGui::BeginDisabled(!problem.empty());
    const bool go = ImGui::Button("Render");
    ImGui::EndDisabled();
    tip("Start rendering: the dialog shows how far it is, Cancel (ESC) stops it.");
    ImGui::SameLine();
    const bool close = ImGui::Button("Close") || escape_pressed();
    tip("Close this dialog without rendering (ESC).");
    if (close) {
        ImGui::CloseCurrentPopup();
        return;
    }
    if (!go || !problem.empty()) return;
    request_ = {};
    request_.out = typed_path(out_, session.path());
    if (video_) request_.video = typed_path(video_path_, session.path());
    request_.width = size_[0];
    request_.height = size_[1];
    request_.fps = fps_;
    request_.from = from_;
    request_.to = to_;
    // The arguments name the snapshot, made in start(): filled in there.
    start(session, Kind::Render, {{"the frames", request_.out, {}}});
}

void OutputDialogs::export_form(EditorSession &session) {
    ImGui::Text("Export what %s computes, as it is now (unsaved changes included)",
                document_stem(session.path()).c_str());
    ImGui::Checkbox("Trace (CSV)", &trace_);
    tip("Every model's position, angles, scale and velocity, every 1/60 s and at every keyframe:\n"
        "t,model,x,y,z,rx,ry,rz,sx,sy,sz,vx,vy,vz,qw,qx,qy,qz,wx,wy,wz (the same file as `animator bake --trace`).");
    ImGui::SameLine(160.0f);
    ImGui::SetNextItemWidth(420.0f);
    ImGui::InputText("##trace path", &trace_path_);
    tip("The CSV file to write the trace to (a relative path is taken from the animation's "
        "folder).");
    ImGui::Checkbox("Soundtrack (WAV)", &soundtrack_);
    tip("Every collision and moving sound mixed at its time into a 16-bit stereo WAV file\n"
        "(the same file as `animator soundtrack`).");
    ImGui::SameLine(160.0f);
    ImGui::SetNextItemWidth(420.0f);
    ImGui::InputText("##soundtrack path", &soundtrack_path_);
    tip("The WAV file to write the soundtrack to (a relative path is taken from the animation's "
        "folder).");
    ImGui::Checkbox("glTF (.glb)", &gltf_);
    tip("The models, materials, camera, lights and motion as glTF 2.0 for Blender, game engines and\n"
        "web viewers: free flight and bounces exact (the same file as `animator export`, docs/export.md).");
    ImGui::SameLine(160.0f);
    ImGui::SetNextItemWidth(420.0f);
    ImGui::InputText("##gltf path", &gltf_path_);
    tip("The glTF file to write: .glb (binary) or .gltf (text). A relative path is taken from the\n"
        "animation's folder.");
    ImGui::TextDisabled("The animation itself (.ani) is saved with Export (x).");

    std::string problem;
    const std::string gltf_extension = fs::path(gltf_path_).extension().string();
    if (!trace_ && !soundtrack_ && !gltf_)
        problem = "tick what to export";
    else if ((trace_ && trace_path_.empty()) || (soundtrack_ && soundtrack_path_.empty()) ||
             (gltf_ && gltf_path_.empty()))
        problem = "name the file to write";
    else if (gltf_ && gltf_extension != ".glb" && gltf_extension != ".gltf")
        problem = "the glTF file's name ends in .glb or .gltf";
    if (!problem.empty())
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", problem.c_str());
    ImGui::BeginDisabled(!problem.empty());
    const bool go = ImGui::Button("Export");
    ImGui::EndDisabled();
    tip("Write the ticked files; Cancel (ESC) stops it.");
    ImGui::SameLine();
    const bool close = ImGui::Button("Close") || escape_pressed();
    tip("Close this dialog without exporting (ESC).");
    if (close) {
        ImGui::CloseCurrentPopup();
        return;
    }
    if (!go || !problem.empty()) return;
    std::vector<Step> steps;
    if (trace_) steps.push_back({"the trace", typed_path(trace_path_, session.path()), {}});
    if (soundtrack_)
        steps.push_back({"the soundtrack", typed_path(soundtrack_path_, session.path()), {}});
    if (gltf_) steps.push_back({"the glTF file", typed_path(gltf_path_, session.path()), {}});
    start(session, Kind::Export, steps);
}

bool OutputDialogs::start(EditorSession &session, Kind kind, std::vector<Step> steps) {
    try {
        snapshot_ = std::make_unique<JobSnapshot>(env_.plugins, env_.assets, session.document(),
                                                  session.path());
    } catch (const std::exception &e) {
        say_(std::string(kind == Kind::Render ? "render" : "export") +
                 " could not start: " + e.what(),
             true);
        return false;
    }
    snapshot_for_ = session.path();
    for (Step &s : steps) {
        if (kind == Kind::Render)
            s.arguments = render_arguments(request_, snapshot_->file());
        else if (s.what == "the trace")
            s.arguments = trace_arguments(s.path, snapshot_->file());
        else if (s.what == "the glTF file")
            s.arguments = gltf_arguments(s.path, snapshot_->file());
        else
            s.arguments = soundtrack_arguments(s.path, snapshot_->file());
    }
    running_ = kind;
    written_.clear();
    steps_ = std::move(steps);
    if (!start_next_step()) return false;
    std::cout << "animator: " << (kind == Kind::Render ? "render" : "export") << " started"
              << std::endl;
    return true;
}

bool OutputDialogs::start_next_step() {
    step_ = steps_.front();
    steps_.erase(steps_.begin());
    std::string error;
    if (!job_.start(OutputJob::self_executable(), step_.arguments, &error)) {
        end(std::string(running_ == Kind::Render ? "render" : "export") +
                " could not start: " + error,
            true);
        return false;
    }
    return true;
}

void OutputDialogs::follow_job() {
    if (job_.poll() || job_.state() == OutputJob::State::Cancelled) return;
    const bool render = running_ == Kind::Render;
    if (job_.state() != OutputJob::State::Succeeded) {
        std::string message = std::string(render ? "render" : "export") + " failed";
        if (!render) message += " writing " + step_.what;
        end(message + ": " + child_error(), true);
        return;
    }
    written_.push_back(step_.path);
    if (!steps_.empty()) {
        start_next_step();
        return;
    }
    if (render) {
        const int n = job_.frames_total();
        std::string message = "render finished (" + std::to_string(n) + " frame" +
                              (n == 1 ? "" : "s") + ") in " +
                              shown_path(request_.out, snapshot_for_);
        if (!request_.video.empty())
            message += ", and the video " + shown_path(request_.video, snapshot_for_);
        end(message, false);
    } else {
        std::string message = "exported";
        for (std::size_t i = 0; i < written_.size(); ++i)
            message += (i == 0 ? " " : " and ") + shown_path(written_[i], snapshot_for_);
        end(message, false);
    }
}

void OutputDialogs::progress() {
    const bool render = running_ == Kind::Render;
    const int done = job_.frames_done(), total = job_.frames_total();
    if (render) {
        ImGui::Text("Rendering into %s", request_.out.string().c_str());
        std::string overlay;
        if (total == 0)
            overlay = "baking the physics ...";
        else if (done == total && !request_.video.empty())
            overlay = "making the video with ffmpeg ...";
        else
            overlay = "frame " + std::to_string(done) + " of " + std::to_string(total);
        ImGui::ProgressBar(total > 0 ? static_cast<float>(done) / static_cast<float>(total) : 0.0f,
                           ImVec2(420.0f, 0.0f), overlay.c_str());
    } else {
        const std::size_t count = written_.size() + 1 + steps_.size();
        ImGui::Text("Writing %s: %s", step_.what.c_str(), step_.path.string().c_str());
        const std::string overlay =
            "file " + std::to_string(written_.size() + 1) + " of " + std::to_string(count) +
            (step_.what == "the soundtrack" ? " (baking and mixing)" : " (baking)");
        ImGui::ProgressBar(static_cast<float>(written_.size()) / static_cast<float>(count),
                           ImVec2(420.0f, 0.0f), overlay.c_str());
    }
    tip("How far the job has come. It runs apart from the editor, on the animation as it was when "
        "it started.");
    ImGui::Text("elapsed %s", seconds_text(job_.elapsed_seconds()).c_str());
    if (ImGui::Button("Cancel") || escape_pressed()) cancel();
    tip("Stop now (ESC); what was written so far stays as it is.");
}

void OutputDialogs::cancel() {
    if (!job_.running()) return;
    const int done = job_.frames_done(), total = job_.frames_total();
    job_.cancel();
    if (running_ == Kind::Render) {
        end("render cancelled (" + std::to_string(done) + " of " + std::to_string(total) +
                " frames); the frames written are left in " +
                shown_path(request_.out, snapshot_for_),
            false);
    } else {
        std::string message = "export cancelled while writing " + step_.what + " (not written)";
        for (std::size_t i = 0; i < written_.size(); ++i)
            message += (i == 0 ? "; written: " : ", ") + shown_path(written_[i], snapshot_for_);
        end(message, false);
    }
}

void OutputDialogs::end(const std::string &message, bool error) {
    running_ = Kind::None;
    close_popup_ = true;
    steps_.clear();
    say_(message, error);
    snapshot_.reset();
}

std::string OutputDialogs::child_error() const {
    std::string text = job_.error_text();
    if (text.empty())
        text =
            "it stopped with exit status " + std::to_string(job_.exit_code()) + " and said nothing";
    if (snapshot_)
        replace_all(text, snapshot_->file().string(),
                    snapshot_for_.empty() ? "the untitled animation" : snapshot_for_.string());
    // Its lines start "animator: " (the command line's voice): the status line says it once.
    replace_all(text, "\nanimator: ", "\n");
    if (text.rfind("animator: ", 0) == 0) text.erase(0, 10);
    std::replace(text.begin(), text.end(), '\n', ' ');
    return text;
}

} // namespace animator
