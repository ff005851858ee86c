#include "editor/model_edits.hpp"

#include "editor/free_view.hpp"
#include "render/frustum.hpp"
#include "render/scene_math.hpp"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>

namespace fs = std::filesystem;

namespace animator {

std::string mesh_reference(const fs::path &file, const fs::path &document, bool saved_there) {
    std::error_code ec;
    const fs::path absolute = fs::weakly_canonical(fs::absolute(file, ec), ec);
    if (saved_there && !document.empty()) {
        const fs::path folder = fs::weakly_canonical(fs::absolute(document, ec).parent_path(), ec);
        const fs::path relative = absolute.lexically_relative(folder);
        if (!relative.empty() && *relative.begin() != ".." && relative.is_relative()) return relative.generic_string();
    }
    return absolute.generic_string();
}

std::string name_from_mesh(const std::string &mesh) {
    const std::string stem = fs::path(mesh).stem().string();
    return stem.empty() ? "model" : stem;
}

double copy_distance(const Document &doc, const std::vector<std::shared_ptr<const Mesh>> &meshes,
                     const std::vector<glm::dmat4> &world, int model) {
    std::vector<Sphere> spheres;
    for (int m : with_descendants(doc, {model})) {
        const auto i = static_cast<size_t>(m);
        if (i >= meshes.size() || i >= world.size() || !meshes[i]) continue;
        Sphere s;
        transform_bounding_sphere(world[i], meshes[i]->bound_center, meshes[i]->bound_radius, s.center, s.radius);
        spheres.push_back(s);
    }
    if (spheres.empty()) return 1.0;
    // A sphere around them all: about their mean center, out to the farthest one's edge.
    glm::dvec3 center(0.0);
    for (const Sphere &s : spheres) center += s.center;
    center /= static_cast<double>(spheres.size());
    double radius = 0.0;
    for (const Sphere &s : spheres) radius = std::max(radius, glm::length(s.center - center) + s.radius);
    return radius > 0.0 ? 2.0 * radius : 1.0;
}

std::vector<ModelCopy> plan_copies(const Document &doc, const std::vector<std::shared_ptr<const Mesh>> &meshes,
                                   const std::vector<glm::dmat4> &world, const std::set<int> &selected) {
    const std::set<int> copied = with_descendants(doc, selected);
    std::vector<ModelCopy> copies;
    std::set<std::string> names;
    for (int m : copied) {
        const Model &model = doc.models()[static_cast<size_t>(m)];
        ModelCopy c;
        c.original = m;
        c.name = unique_model_name(doc, model.name, names);
        names.insert(c.name);
        if (model.parent < 0 || !copied.count(model.parent)) {
            const glm::dvec3 shift(copy_distance(doc, meshes, world, m), 0.0, 0.0);
            if (model.parent < 0 || static_cast<size_t>(model.parent) >= world.size()) {
                c.offset = shift;
            } else {
                // The world's +x in the parent's frame (its rotation and scale undone).
                const glm::dmat3 parent(world[static_cast<size_t>(model.parent)]);
                c.offset = glm::inverse(parent) * shift;
            }
        }
        copies.push_back(c);
    }
    return copies;
}

std::string deletion_phrase(const Document &doc, const std::set<int> &selected, const std::set<int> &deleted) {
    const auto n_selected = selected.size();
    const auto under = deleted.size() - std::min(deleted.size(), n_selected);
    std::string out = n_selected == 1 ? "'" + doc.models()[static_cast<size_t>(*selected.begin())].name + "'"
                                      : std::to_string(n_selected) + " models";
    if (under == 1) out += " and the model under " + std::string(n_selected == 1 ? "it" : "them");
    else if (under > 1) out += " and the " + std::to_string(under) + " models under " + (n_selected == 1 ? "it" : "them");
    return out;
}

} // namespace animator
