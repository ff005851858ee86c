#include "assets/asset_paths.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace animator {

namespace {

const char *folder_of(ani_asset_kind kind) {
    switch (kind) {
    case ANI_ASSET_MESH: return "meshes";
    case ANI_ASSET_TEXTURE: return "textures";
    case ANI_ASSET_SKYBOX: return "skyboxes";
    case ANI_ASSET_SOUND: return "sounds";
    }
    return "";
}

std::vector<std::string> extensions_of(ani_asset_kind kind) {
    switch (kind) {
    case ANI_ASSET_MESH: return {".obj"};
    case ANI_ASSET_TEXTURE: return {".png", ".bmp"};
    case ANI_ASSET_SKYBOX: return {""};
    case ANI_ASSET_SOUND: return {".wav"};
    }
    return {};
}

bool exists_as(ani_asset_kind kind, const fs::path &p) {
    std::error_code ec;
    return kind == ANI_ASSET_SKYBOX ? fs::is_directory(p, ec) : fs::is_regular_file(p, ec);
}

void copy_out(const std::string &text, char *out, size_t size) {
    if (!out || size == 0) return;
    const size_t n = std::min(text.size(), size - 1);
    std::memcpy(out, text.data(), n);
    out[n] = '\0';
}

} // namespace

std::vector<fs::path> AssetPaths::default_roots() {
    std::vector<fs::path> roots;
    if (const char *env = std::getenv("ANIMATOR_ASSET_PATH")) {
        std::istringstream parts(env);
        std::string part;
        while (std::getline(parts, part, ':'))
            if (!part.empty()) roots.emplace_back(part);
    }
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) roots.push_back(exe.parent_path().parent_path() / "assets");
    roots.emplace_back(ANIMATOR_SOURCE_ASSET_DIR);
    return roots;
}

std::vector<fs::path> AssetPaths::candidates(ani_asset_kind kind, const std::string &id,
                                             const fs::path &document) const {
    std::vector<fs::path> out;
    if (id.empty()) return out;
    // An id that already names its file ("plane.obj", as the course's ray-tracer scenes write
    // meshes) is that file in each asset folder, not "plane.obj.obj".
    const std::vector<std::string> extensions = extensions_of(kind);
    const bool has_extension = std::any_of(extensions.begin(), extensions.end(), [&](const std::string &ext) {
        return !ext.empty() && id.size() > ext.size() && id.compare(id.size() - ext.size(), ext.size(), ext) == 0;
    });
    // A path relative to the document that names it (meshes only, as the scene format says), and
    // an id without its extension beside it (a course puppet's gr.mesh('luffy-face') with its
    // luffy-face.obj next to the scene).
    if (kind == ANI_ASSET_MESH) {
        const fs::path relative = document.empty() ? fs::path(id) : document.parent_path() / id;
        out.push_back(relative);
        if (!has_extension)
            for (const std::string &ext : extensions) out.push_back(fs::path(relative.string() + ext));
    }
    for (const fs::path &root : roots_) {
        if (has_extension) out.push_back(root / folder_of(kind) / id);
        else
            for (const std::string &ext : extensions) out.push_back(root / folder_of(kind) / (id + ext));
    }
    return out;
}

std::vector<std::string> AssetPaths::list(ani_asset_kind kind) const {
    std::set<std::string> ids;
    const auto extensions = extensions_of(kind);
    for (const fs::path &root : roots_) {
        std::error_code ec;
        for (fs::directory_iterator it(root / folder_of(kind), ec), end; !ec && it != end; it.increment(ec)) {
            const fs::path &p = it->path();
            const std::string ext = kind == ANI_ASSET_SKYBOX ? "" : p.extension().string();
            if (std::find(extensions.begin(), extensions.end(), ext) != extensions.end() && exists_as(kind, p))
                ids.insert(p.stem().string());
        }
    }
    return {ids.begin(), ids.end()};
}

std::optional<fs::path> AssetPaths::resolve(ani_asset_kind kind, const std::string &id,
                                            const fs::path &document) const {
    for (const fs::path &p : candidates(kind, id, document))
        if (exists_as(kind, p)) return p;
    return std::nullopt;
}

std::string AssetPaths::searched(ani_asset_kind kind, const std::string &id, const fs::path &document) const {
    std::string out = "looked for";
    bool first = true;
    for (const fs::path &p : candidates(kind, id, document)) {
        out += (first ? " " : ", ") + p.string();
        first = false;
    }
    if (first) out += " nothing (the name is empty)";
    return out;
}

int32_t AssetPaths::resolve_for_plugin(const ani_host *host, int32_t kind, const char *id,
                                       const char *relative_to, char *out, size_t out_size) {
    if (!host || !host->get_extension || !id || kind < ANI_ASSET_MESH || kind > ANI_ASSET_SOUND) {
        copy_out("invalid asset query", out, out_size);
        return 0;
    }
    const auto *ext = static_cast<const Extension *>(host->get_extension(host, ANI_EXT_ASSETS));
    if (!ext) {
        copy_out("the host has no asset folders", out, out_size);
        return 0;
    }
    const AssetPaths &self = *ext->owner;
    const auto k = static_cast<ani_asset_kind>(kind);
    const fs::path document = relative_to ? fs::path(relative_to) : fs::path();
    if (auto found = self.resolve(k, id, document)) {
        copy_out(found->string(), out, out_size);
        return 1;
    }
    copy_out(self.searched(k, id, document), out, out_size);
    return 0;
}

} // namespace animator
