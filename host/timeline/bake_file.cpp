#include "timeline/bake_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <unordered_map>

namespace animator {

namespace {

constexpr char kMagic[8] = {'A', 'N', 'I', 'B', 'A', 'K', 'E', '\0'};
constexpr std::size_t kHeaderSize = 8 + 4 + 8; // magic, version, payload size
constexpr std::size_t kChecksumSize = 8;

// 64-bit FNV-1a: the fingerprints and the checksum (to tell files apart, not against an attacker).
std::uint64_t fnv1a(const std::uint8_t *p, std::size_t n,
                    std::uint64_t h = 14695981039346656037ull) {
    for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ull;
    return h;
}

// Little-endian numbers with explicit sizes; doubles as their IEEE 754 bits.
class Writer {
  public:
    std::vector<std::uint8_t> bytes;
    void u8(std::uint8_t v) { bytes.push_back(v); }
    void u32(std::uint32_t v) {
        for (int i = 0; i < 4; ++i) bytes.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    }
    void u64(std::uint64_t v) {
        for (int i = 0; i < 8; ++i) bytes.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    }
    void f64(double v) {
        std::uint64_t bits;
        std::memcpy(&bits, &v, 8);
        u64(bits);
    }
    void vec(const ani_vec3 &v) { vec(glm::dvec3(v.x, v.y, v.z)); }
    void vec(const glm::dvec3 &v) {
        for (int i = 0; i < 3; ++i) f64(v[i]);
    }
    void quat(const ani_quat &q) { quat(glm::dquat(q.w, q.x, q.y, q.z)); }
    void quat(const glm::dquat &q) {
        for (double x : {q.w, q.x, q.y, q.z}) f64(x);
    }
    void str(const std::string &s) {
        u32(static_cast<std::uint32_t>(s.size()));
        bytes.insert(bytes.end(), s.begin(), s.end());
    }
    std::uint64_t hash() const { return fnv1a(bytes.data(), bytes.size()); }
};

// Reads what Writer wrote; running past the end means the file is corrupt.
class Reader {
  public:
    Reader(const std::uint8_t *p, std::size_t n, const std::string &file)
        : p_(p), end_(p + n), file_(file) {}
    std::uint8_t u8() { return take(1)[0]; }
    std::uint32_t u32() {
        const std::uint8_t *b = take(4);
        std::uint32_t v = 0;
        for (int i = 0; i < 4; ++i) v |= static_cast<std::uint32_t>(b[i]) << (8 * i);
        return v;
    }
    std::uint64_t u64() {
        const std::uint8_t *b = take(8);
        std::uint64_t v = 0;
        for (int i = 0; i < 8; ++i) v |= static_cast<std::uint64_t>(b[i]) << (8 * i);
        return v;
    }
    double f64() {
        const std::uint64_t bits = u64();
        double v;
        std::memcpy(&v, &bits, 8);
        return v;
    }
    // (Braced lists are evaluated left to right; a function's arguments are not.)
    ani_vec3 vec() { return ani_vec3{f64(), f64(), f64()}; }
    glm::dvec3 dvec() {
        const ani_vec3 v = vec();
        return glm::dvec3(v.x, v.y, v.z);
    }
    ani_quat quat() { return ani_quat{f64(), f64(), f64(), f64()}; }
    glm::dquat dquat() {
        const ani_quat q = quat();
        return glm::dquat(q.w, q.x, q.y, q.z);
    }
    std::string str() {
        const std::uint32_t n = u32();
        const std::uint8_t *b = take(n);
        return std::string(b, b + n);
    }
    // A count of records of at least `record_bytes` each, checked against what is left.
    std::size_t count(std::size_t record_bytes) {
        const std::uint64_t n = u64();
        if (n > static_cast<std::uint64_t>(end_ - p_) / record_bytes)
            corrupt("a count larger than the file");
        return static_cast<std::size_t>(n);
    }
    bool at_end() const { return p_ == end_; }
    [[noreturn]] void corrupt(const std::string &what) const {
        throw BakeFileError(file_ + " is corrupt: " + what);
    }

  private:
    const std::uint8_t *take(std::size_t n) {
        if (static_cast<std::size_t>(end_ - p_) < n) corrupt("its data ends early");
        const std::uint8_t *b = p_;
        p_ += n;
        return b;
    }
    const std::uint8_t *p_, *end_;
    std::string file_;
};

// The bytes of each record in the file, for Reader::count.
constexpr std::size_t kMotionBytes = 4 + 4 + 8 * 11, kRotationBytes = 1 + 4 + 8 * 28,
                      kCarriedBytes = 4 + 4 + 8 * 9, kEventBytes = 8 * 9, kOverlapBytes = 8 * 6;

// What a bake depends on. The document counts only as it bears on motion (a colour, a camera
// key or a light changes no bake), and each part is a hash of a canonical serialisation.
struct Fingerprint {
    std::string backend;
    std::vector<std::pair<std::string, ParamValue>> params; // the backend's, all of them
    std::uint64_t settings = 0, models = 0, keys = 0;
    std::vector<std::uint64_t> meshes; // per model: what the backend collides it with, 0 for none
};

std::uint64_t mesh_hash(const ani_mesh_view &v) {
    Writer w;
    w.u32(v.vertex_count);
    for (std::size_t i = 0; i < 3 * static_cast<std::size_t>(v.vertex_count); ++i)
        w.f64(v.positions[i]);
    w.u32(v.triangle_count);
    for (std::size_t i = 0; i < 3 * static_cast<std::size_t>(v.triangle_count); ++i)
        w.u32(v.triangles[i]);
    w.vec(v.bound_center);
    w.f64(v.bound_radius);
    w.u32(static_cast<std::uint32_t>(v.is_sphere));
    return w.hash() | 1; // never 0, which means no mesh
}

Fingerprint fingerprint_of(const Timeline &timeline) {
    const Document &doc = timeline.document();
    const Settings &s = doc.settings();
    Fingerprint f;
    f.backend = timeline.backend_id();
    f.params = timeline.backend_params();

    Writer settings; // the backend and its parameters are compared on their own
    settings.u64(static_cast<std::uint64_t>(s.max_time_ms));
    settings.f64(s.gravity);
    settings.u32(static_cast<std::uint32_t>(s.down_axis));
    settings.str(s.interpolation);
    const auto saved = s.params.find(s.interpolation);
    settings.u64(saved == s.params.end() ? 0 : saved->second.size());
    if (saved != s.params.end())
        for (const auto &[name, value] : saved->second) {
            settings.str(name);
            for (double x : value) settings.f64(x);
        }
    f.settings = settings.hash();

    Writer models; // the fields Timeline::affected_from counts as physics, and the rest shape
    models.u64(doc.models().size());
    for (const Model &m : doc.models()) {
        models.u32(static_cast<std::uint32_t>(m.parent));
        for (bool flag : {m.dynamics, m.gravity, m.rotates}) models.u8(flag);
        for (double x : {m.mass, m.restitution, m.friction}) models.f64(x);
        models.vec(m.initial_velocity);
        models.vec(m.angular_velocity);
        for (int c = 0; c < 3; ++c) models.vec(m.rest[c]);
    }
    f.models = models.hash();

    Writer keys; // every model's keys (not the camera's)
    keys.u64(doc.keyframes().size());
    for (const Keyframe &k : doc.keyframes()) {
        keys.u64(static_cast<std::uint64_t>(k.time_ms));
        for (const std::optional<ModelState> &state : k.states) {
            keys.u8(state.has_value());
            if (state)
                for (const glm::dvec3 *v :
                     {&state->center, &state->angles, &state->scale, &state->turn})
                    keys.vec(*v);
        }
    }
    f.keys = keys.hash();

    std::unordered_map<const ani_mesh_view *, std::uint64_t> seen; // models share views
    for (std::size_t m = 0; m < doc.models().size(); ++m) {
        const ani_mesh_view *v = timeline.mesh_view(static_cast<int>(m));
        if (v && !seen.count(v)) seen[v] = mesh_hash(*v);
        f.meshes.push_back(v ? seen[v] : 0);
    }
    return f;
}

std::string value_text(const ParamValue &v) {
    std::size_t n = 4;
    while (n > 1 && v[n - 1] == 0.0) --n;
    std::ostringstream out;
    out.precision(17);
    for (std::size_t i = 0; i < n; ++i) out << (i ? "," : "") << v[i];
    return out.str();
}

// Says what of `file` (the saved fingerprint) differs from `here`, the timeline's; "" when nothing.
std::string mismatch(const Fingerprint &file, const Fingerprint &here, const Timeline &timeline) {
    if (file.backend != here.backend)
        return "was baked with physics backend '" + file.backend + "', not '" + here.backend + "'";
    for (const auto &[name, value] : file.params) {
        auto it = std::find_if(here.params.begin(), here.params.end(),
                               [&](const auto &p) { return p.first == name; });
        if (it == here.params.end())
            return "was baked with " + file.backend + "'s parameter '" + name + "', which this " +
                   here.backend + " does not have";
        if (it->second != value)
            return "was baked with " + file.backend + "'s parameter '" + name +
                   "' = " + value_text(value) + ", not " + value_text(it->second);
    }
    if (file.params.size() != here.params.size())
        return "was baked with a " + file.backend + " of other parameters (" +
               std::to_string(file.params.size()) + ", not " + std::to_string(here.params.size()) +
               ")";
    const std::string another =
        "was baked from another document, or from this one before an edit that changes motion: ";
    if (file.meshes.size() != here.meshes.size())
        return another + "it had " + std::to_string(file.meshes.size()) + " models, this one has " +
               std::to_string(here.meshes.size());
    if (file.settings != here.settings)
        return another +
               "the settings that move models differ (max time, gravity, down axis, interpolation)";
    if (file.models != here.models)
        return another + "the models' physics differs (parent, dynamics, gravity, mass, "
                         "velocity, restitution, friction, rotation, rest shape)";
    if (file.keys != here.keys) return another + "the models' keyframes differ";
    for (std::size_t m = 0; m < file.meshes.size(); ++m) {
        if (file.meshes[m] == here.meshes[m]) continue;
        const std::string name = "'" + timeline.document().models()[m].name + "'";
        if (!file.meshes[m])
            return "was baked with no mesh for model " + name + ", which has one here";
        if (!here.meshes[m])
            return "was baked with a mesh for model " + name + ", which has none here";
        return "was baked with another mesh for model " + name +
               " (its file has changed, or another was found)";
    }
    return "";
}

void write_fingerprint(Writer &w, const Fingerprint &f) {
    w.str(f.backend);
    w.u64(f.params.size());
    for (const auto &[name, value] : f.params) {
        w.str(name);
        for (double x : value) w.f64(x);
    }
    for (std::uint64_t h : {f.settings, f.models, f.keys}) w.u64(h);
    w.u64(f.meshes.size());
    for (std::uint64_t h : f.meshes) w.u64(h);
}

Fingerprint read_fingerprint(Reader &r) {
    Fingerprint f;
    f.backend = r.str();
    for (std::size_t n = r.count(4 + 32); n > 0; --n) {
        std::string name = r.str();
        ParamValue value;
        for (double &x : value) x = r.f64();
        f.params.emplace_back(std::move(name), value);
    }
    f.settings = r.u64();
    f.models = r.u64();
    f.keys = r.u64();
    for (std::size_t n = r.count(8); n > 0; --n) f.meshes.push_back(r.u64());
    return f;
}

// Rotation segments are of three kinds: q0, w and alpha say it all (a steady turn, or a spin-up
// when alpha is not zero), or it is torque-free (`free`), or it swings about a hinge.
enum : std::uint8_t { kTurn = 0, kFree = 1, kHinge = 2 };

void write_rotation(Writer &w, const RotationSegment &s) {
    w.u8(s.free ? kFree : s.hinge ? kHinge : kTurn);
    w.u32(s.model);
    w.f64(s.t0);
    w.f64(s.t1);
    w.quat(s.q0);
    w.vec(s.w);
    w.vec(s.alpha);
    w.quat(s.principal);
    for (const glm::dvec3 *v : {&s.pivot, &s.axis, &s.moments}) w.vec(*v);
    for (double x : {s.omega2, s.angle0, s.rate0}) w.f64(x);
}

RotationSegment read_rotation(Reader &r) {
    RotationSegment s;
    const std::uint8_t kind = r.u8();
    s.model = r.u32();
    s.t0 = r.f64();
    s.t1 = r.f64();
    s.q0 = r.quat();
    s.w = r.vec();
    s.alpha = r.dvec();
    s.principal = r.dquat();
    for (glm::dvec3 *v : {&s.pivot, &s.axis, &s.moments}) *v = r.dvec();
    for (double *x : {&s.omega2, &s.angle0, &s.rate0}) *x = r.f64();
    // The closed forms are made again from the same numbers; what they would refuse is refused.
    if (kind == kFree) {
        const std::string why =
            ani::FreeRotation::refusal(s.moments, glm::dvec3(s.w.x, s.w.y, s.w.z));
        if (!why.empty()) r.corrupt("a free-rotation segment: " + why);
        s.free = free_rotation_of(s);
    } else if (kind == kHinge) {
        const std::string why = ani::Pendulum::refusal(s.omega2, s.angle0, s.rate0);
        if (!why.empty()) r.corrupt("a hinge segment: " + why);
        s.hinge = hinge_of(s);
    } else if (kind != kTurn) {
        r.corrupt("a rotation segment of unknown kind " + std::to_string(kind));
    }
    return s;
}

void write_state(Writer &w, const BakedState &b) {
    w.f64(b.until);
    for (const auto &list : b.segments) {
        w.u64(list.size());
        for (const ani_motion_segment &s : list) {
            w.u32(s.model);
            w.u32(static_cast<std::uint32_t>(s.motion));
            w.f64(s.t0);
            w.f64(s.t1);
            for (const ani_vec3 *v : {&s.p0, &s.v0, &s.a}) w.vec(*v);
        }
    }
    for (const auto &list : b.rotations) {
        w.u64(list.size());
        for (const RotationSegment &s : list) write_rotation(w, s);
    }
    for (const auto &list : b.carried) {
        w.u64(list.size());
        for (const ani_carried_segment &s : list) {
            w.u32(s.model);
            w.u32(s.carrier);
            w.f64(s.t0);
            w.f64(s.t1);
            w.vec(s.offset);
            w.quat(s.relative);
        }
    }
    w.u64(b.events.size());
    for (const ani_collision_event &e : b.events) {
        w.f64(e.t);
        w.u32(e.a);
        w.u32(e.b);
        w.vec(e.normal);
        w.vec(e.point);
        w.f64(e.speed);
    }
    w.u64(b.overlaps.size());
    for (const ani_overlap &o : b.overlaps) {
        w.f64(o.t);
        w.u32(o.a);
        w.u32(o.b);
        w.vec(o.normal);
        w.f64(o.depth);
    }
}

BakedState read_state(Reader &r, std::size_t models) {
    BakedState b;
    b.until = r.f64();
    b.segments.resize(models);
    b.rotations.resize(models);
    b.carried.resize(models);
    const auto check_model = [&](std::uint32_t m, std::size_t expected) {
        if (m != expected)
            r.corrupt("a segment of model " + std::to_string(m) + " in model " +
                      std::to_string(expected) + "'s list");
    };
    for (std::size_t m = 0; m < models; ++m) {
        b.segments[m].resize(r.count(kMotionBytes));
        for (ani_motion_segment &s : b.segments[m]) {
            s.model = r.u32();
            s.motion = static_cast<std::int32_t>(r.u32());
            s.t0 = r.f64();
            s.t1 = r.f64();
            for (ani_vec3 *v : {&s.p0, &s.v0, &s.a}) *v = r.vec();
            check_model(s.model, m);
            if (s.motion < ANI_MOTION_KEYED || s.motion > ANI_MOTION_CARRIED)
                r.corrupt("a motion of unknown kind");
        }
    }
    for (std::size_t m = 0; m < models; ++m) {
        for (std::size_t n = r.count(kRotationBytes); n > 0; --n) {
            b.rotations[m].push_back(read_rotation(r));
            check_model(b.rotations[m].back().model, m);
        }
    }
    for (std::size_t m = 0; m < models; ++m) {
        b.carried[m].resize(r.count(kCarriedBytes));
        for (ani_carried_segment &s : b.carried[m]) {
            s.model = r.u32();
            s.carrier = r.u32();
            s.t0 = r.f64();
            s.t1 = r.f64();
            s.offset = r.vec();
            s.relative = r.quat();
            check_model(s.model, m);
            if (s.carrier >= models || s.carrier == s.model)
                r.corrupt("a model carried by a model there is not");
        }
    }
    b.events.resize(r.count(kEventBytes));
    for (ani_collision_event &e : b.events) {
        e.t = r.f64();
        e.a = r.u32();
        e.b = r.u32();
        e.normal = r.vec();
        e.point = r.vec();
        e.speed = r.f64();
        if (e.a >= models || (e.b >= models && e.b != ANI_NO_MODEL))
            r.corrupt("a collision of a model there is not");
    }
    b.overlaps.resize(r.count(kOverlapBytes));
    for (ani_overlap &o : b.overlaps) {
        o.t = r.f64();
        o.a = r.u32();
        o.b = r.u32();
        o.normal = r.vec();
        o.depth = r.f64();
        if (o.a >= models || o.b >= models) r.corrupt("an overlap of a model there is not");
    }
    if (!r.at_end()) r.corrupt("bytes after its data");
    return b;
}

std::string seconds(double t) {
    std::ostringstream out;
    out.precision(17);
    out << t << " s";
    return out.str();
}

} // namespace

void save_bake(const Timeline &timeline, const std::filesystem::path &path) {
    Writer payload;
    write_fingerprint(payload, fingerprint_of(timeline));
    write_state(payload, timeline.baked_state());
    Writer file;
    file.bytes.assign(std::begin(kMagic), std::end(kMagic));
    file.u32(kBakeFormatVersion);
    file.u64(payload.bytes.size());
    file.bytes.insert(file.bytes.end(), payload.bytes.begin(), payload.bytes.end());
    file.u64(payload.hash());

    const std::filesystem::path partial =
        path.parent_path() / ("." + path.filename().string() + ".partial");
    std::ofstream out(partial, std::ios::binary);
    if (!out)
        throw BakeFileError(path.string() + ": cannot be written (" + std::strerror(errno) + ")");
    out.write(reinterpret_cast<const char *>(file.bytes.data()),
              static_cast<std::streamsize>(file.bytes.size()));
    out.close();
    std::error_code ec;
    if (!out) {
        std::filesystem::remove(partial, ec);
        throw BakeFileError(path.string() + ": writing failed");
    }
    std::filesystem::rename(partial, path, ec);
    if (ec) {
        std::filesystem::remove(partial, ec);
        throw BakeFileError(path.string() + ": cannot be written (" + ec.message() + ")");
    }
}

void load_bake(Timeline &timeline, const std::filesystem::path &path, double needed_until) {
    const std::string name = path.string();
    std::ifstream in(path, std::ios::binary);
    if (!in) throw BakeFileError(name + ": cannot be read (" + std::strerror(errno) + ")");
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                          std::istreambuf_iterator<char>());
    if (in.bad()) throw BakeFileError(name + ": reading failed");

    // (An empty file has no bytes to compare: its data() may be null, which memcmp must not get.)
    const bool magic = !bytes.empty() &&
                       std::memcmp(bytes.data(), kMagic, std::min(bytes.size(), sizeof kMagic)) == 0;
    if (!magic)
        throw BakeFileError(name + ": not a bake file (it does not begin with ANIBAKE)");
    if (bytes.size() < kHeaderSize)
        throw BakeFileError(name + " is truncated: " + std::to_string(bytes.size()) +
                            " bytes, not even a whole header");
    Reader header(bytes.data() + sizeof kMagic, kHeaderSize - sizeof kMagic, name);
    const std::uint32_t version = header.u32();
    if (version != kBakeFormatVersion)
        throw BakeFileError(name + ": format version " + std::to_string(version) +
                            ", and this animator reads version " +
                            std::to_string(kBakeFormatVersion) +
                            " (bake it again with this animator)");
    const std::uint64_t payload_size = header.u64();
    const std::uint64_t room = bytes.size() - kHeaderSize; // for the payload and the checksum
    if (room < kChecksumSize || payload_size != room - kChecksumSize) {
        const bool shorter = room < kChecksumSize || payload_size > room - kChecksumSize;
        throw BakeFileError(
            name + (shorter ? " is truncated: " : " is corrupt: ") + std::to_string(bytes.size()) +
            " bytes, and its header says " + std::to_string(payload_size) + " bytes of data and " +
            std::to_string(kHeaderSize + kChecksumSize) + " of header and checksum");
    }
    const std::uint8_t *payload = bytes.data() + kHeaderSize;
    Reader checksum(payload + payload_size, kChecksumSize, name);
    if (checksum.u64() != fnv1a(payload, payload_size))
        throw BakeFileError(name + " is corrupt: its checksum does not match its contents");

    Reader r(payload, payload_size, name);
    const Fingerprint saved = read_fingerprint(r);
    const std::string differs = mismatch(saved, fingerprint_of(timeline), timeline);
    if (!differs.empty()) throw BakeFileError(name + " " + differs);
    BakedState state = read_state(r, saved.meshes.size());
    if (state.until < needed_until)
        throw BakeFileError(name + " holds a bake to " + seconds(state.until) + ", and " +
                            seconds(needed_until) +
                            " is needed (bake to there or further: animator bake --until)");
    timeline.restore(std::move(state));
}

} // namespace animator
