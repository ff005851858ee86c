#include "assets/mesh_format_scan.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <vector>

namespace animator {

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

std::size_t type_size(const std::string &type) {
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" || type == "float32")
        return 4;
    if (type == "double" || type == "float64") return 8;
    return 0;
}

// A PLY header: each element's count times the fewest bytes one instance can take (binary: its
// properties' sizes, a list's count alone; ASCII: a character and a separator per property)
// must fit in what follows the header, and no element may pass kMaxMeshElements.
std::string ply_beyond_limits(const std::string &name, const std::string &bytes) {
    const auto end = bytes.find("end_header");
    if (bytes.compare(0, 3, "ply") != 0 || end == std::string::npos)
        return name + ": not a PLY file (no 'ply' ... 'end_header' header)";
    // The header is checked line by line before assimp sees it: its PLY reader was seen to
    // read past the file on a mangled header (docs/fuzzing.md), so only the standard's
    // keywords, one format line and known property types pass.
    std::istringstream header(bytes.substr(0, end));
    std::string line;
    bool binary = false;
    int formats = 0, line_number = 0;
    const auto known_type = [](const std::string &t) {
        static const char *types[] = {"char", "uchar", "short", "ushort", "int", "uint", "float", "double",
                                      "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64"};
        for (const char *k : types)
            if (t == k) return true;
        return false;
    };
    const auto bad = [&](const std::string &what) {
        return name + ": line " + std::to_string(line_number) + ": " + what + " in the PLY header";
    };
    struct Element {
        std::string name;
        unsigned long long count = 0;
        std::size_t min_bytes = 0;
    };
    std::vector<Element> elements;
    while (std::getline(header, line)) {
        ++line_number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream words(line);
        std::string word;
        words >> word;
        if (line_number == 1) {
            if (line != "ply") return bad("'ply' expected on the first line");
            continue;
        }
        if (word == "format") {
            std::string kind, version, extra;
            words >> kind >> version >> extra;
            if (++formats > 1) return bad("a second format line");
            if (kind != "ascii" && kind != "binary_little_endian" && kind != "binary_big_endian")
                return bad("an unknown format '" + kind + "' (ascii, binary_little_endian or binary_big_endian expected)");
            if (version != "1.0" || !extra.empty()) return bad("format version 1.0 expected");
            binary = kind.rfind("binary", 0) == 0;
        } else if (word == "comment" || word == "obj_info" || word.empty()) {
            continue;
        } else if (word != "element" && word != "property") {
            return bad("an unknown keyword '" + word.substr(0, 32) + "'");
        } else if (formats == 0) {
            return bad("'" + word + "' before the format line");
        } else if (word == "property") {
            std::string type, more;
            words >> type;
            if (type == "list") {
                std::string count_type, item_type;
                words >> count_type >> item_type;
                if (!known_type(count_type) || !known_type(item_type)) return bad("an unknown list type");
            } else if (!known_type(type)) {
                return bad("an unknown property type '" + type.substr(0, 32) + "'");
            }
            if (!(words >> more)) return bad("a property without a name");
            if (elements.empty()) return bad("a property before any element");
        }
        if (word == "element") {
            Element e;
            std::string count;
            words >> e.name >> count;
            if (count.empty() || count.find_first_not_of("0123456789") != std::string::npos || count.size() > 18)
                return name + ": PLY element '" + e.name + "' has no valid count ('" + count + "')";
            e.count = std::stoull(count);
            if (e.count > kMaxMeshElements)
                return name + ": PLY element '" + e.name + "' has " + count + " instances; at most " +
                       std::to_string(kMaxMeshElements) + " are read";
            elements.push_back(e);
        } else if (word == "property" && !elements.empty()) {
            std::string type;
            words >> type;
            if (type == "list") words >> type; // the count's type: the least a list takes
            elements.back().min_bytes += binary ? std::max<std::size_t>(type_size(type), 1) : 2;
        }
    }
    const std::size_t body = bytes.size() - std::min(bytes.size(), end + std::strlen("end_header"));
    unsigned long long needed = 0;
    for (const Element &e : elements) needed += e.count * std::max<std::size_t>(e.min_bytes, 1);
    if (needed > body)
        return name + ": the PLY header promises at least " + std::to_string(needed) + " bytes of data; the file has " +
               std::to_string(body);
    return "";
}

// The string after `"key"` and a colon, from `at`; false when what follows is not a string.
bool string_value(const std::string &text, std::size_t at, std::string &value) {
    while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at]))) ++at;
    if (at >= text.size() || text[at] != ':') return false;
    ++at;
    while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at]))) ++at;
    if (at >= text.size() || text[at] != '"') return false;
    const auto close = text.find('"', at + 1);
    if (close == std::string::npos) return false;
    value = text.substr(at + 1, close - at - 1);
    return true;
}

// glTF's JSON (all of a .gltf, the first chunk of a .glb): every "uri" must be a data: URI (the
// file holds everything), and every "count" at most kMaxMeshElements.
std::string gltf_beyond_limits(const std::string &name, const std::string &bytes) {
    for (std::size_t at = bytes.find("\"uri\""); at != std::string::npos; at = bytes.find("\"uri\"", at + 5)) {
        std::string uri;
        if (string_value(bytes, at + 5, uri) && uri.rfind("data:", 0) != 0)
            return name + ": the glTF names the file '" + uri.substr(0, 200) +
                   "'; only a self-contained glTF is read (a .glb, or a .gltf with its buffers in data: URIs)";
    }
    for (std::size_t at = bytes.find("\"count\""); at != std::string::npos; at = bytes.find("\"count\"", at + 7)) {
        std::size_t p = at + 7;
        while (p < bytes.size() && (std::isspace(static_cast<unsigned char>(bytes[p])) || bytes[p] == ':')) ++p;
        std::size_t digits = 0;
        unsigned long long value = 0;
        while (p < bytes.size() && std::isdigit(static_cast<unsigned char>(bytes[p])) && digits < 19) {
            value = value * 10 + static_cast<unsigned>(bytes[p] - '0');
            ++p;
            ++digits;
        }
        if (digits >= 19 || value > kMaxMeshElements)
            return name + ": a glTF accessor has more than " + std::to_string(kMaxMeshElements) + " elements";
    }
    return "";
}

} // namespace

MeshFormat mesh_format_of(const std::string &path) {
    const auto dot = path.rfind('.');
    const auto slash = path.find_last_of("/\\");
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return MeshFormat::Obj;
    const std::string ext = lower(path.substr(dot));
    if (ext == ".ply") return MeshFormat::Ply;
    if (ext == ".stl") return MeshFormat::Stl;
    if (ext == ".glb") return MeshFormat::Glb;
    if (ext == ".gltf") return MeshFormat::Gltf;
    return MeshFormat::Obj;
}

const char *assimp_name_of(MeshFormat format) {
    switch (format) {
    case MeshFormat::Obj: return "mesh.obj";
    case MeshFormat::Ply: return "mesh.ply";
    case MeshFormat::Stl: return "mesh.stl";
    case MeshFormat::Glb: return "mesh.glb";
    case MeshFormat::Gltf: return "mesh.gltf";
    }
    return "mesh.obj";
}

std::string mesh_beyond_limits(const std::string &name, MeshFormat format, const std::string &bytes) {
    switch (format) {
    case MeshFormat::Obj: return "";
    case MeshFormat::Ply: return ply_beyond_limits(name, bytes);
    case MeshFormat::Stl: return ""; // 50 bytes a triangle: the size limit bounds it
    case MeshFormat::Glb:
    case MeshFormat::Gltf: return gltf_beyond_limits(name, bytes);
    }
    return "";
}

} // namespace animator
