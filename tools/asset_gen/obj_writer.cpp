#include "obj_writer.hpp"

#include "file_io.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace animator::assetgen {

namespace {

// Nine significant digits round-trip a float exactly, which is all a renderer keeps. Values that
// are zero up to rounding (cos(pi/2) is 6e-17) print as 0, and -0 as 0, so the text stays tidy
// and does not depend on the sign of a rounding error.
std::string number(double x) {
    if (std::fabs(x) < 1e-12) x = 0.0;
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", x);
    return buf;
}

} // namespace

std::string to_obj(const Mesh &mesh, const std::string &comment) {
    std::ostringstream out;
    std::istringstream lines(comment);
    for (std::string line; std::getline(lines, line);) out << "# " << line << '\n';
    out << "# " << mesh.positions().size() << " positions, " << mesh.triangles().size()
        << " triangles\n";
    for (const auto &p : mesh.positions())
        out << "v " << number(p.x) << ' ' << number(p.y) << ' ' << number(p.z) << '\n';
    for (const auto &t : mesh.uvs()) out << "vt " << number(t.x) << ' ' << number(t.y) << '\n';
    for (const auto &n : mesh.normals())
        out << "vn " << number(n.x) << ' ' << number(n.y) << ' ' << number(n.z) << '\n';
    for (const auto &tri : mesh.triangles()) {
        out << 'f';
        for (const Corner &c : tri) out << ' ' << c.v + 1 << '/' << c.vt + 1 << '/' << c.vn + 1;
        out << '\n';
    }
    return out.str();
}

void write_obj(const std::filesystem::path &path, const Mesh &mesh, const std::string &comment) {
    write_bytes(path, to_obj(mesh, comment));
}

} // namespace animator::assetgen
