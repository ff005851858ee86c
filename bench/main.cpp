// animator-bench [--quick] [--only SECTION] [--out DIR] [--runs N]: the benchmark of the physics
// backends (docs/performance.md). Sections: exact, gas, mesh, long, skip.
#include "bench.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <iostream>
#include <sstream>

namespace animator::bench {

Csv::Csv(const std::filesystem::path &path, const std::vector<std::string> &columns)
    : out_(path) {
    if (!out_) throw std::runtime_error(path.string() + ": cannot be written");
    for (const std::string &c : columns) *this << c;
    end_row();
}

Csv &Csv::operator<<(const std::string &field) {
    if (!first_) out_ << ",";
    if (field.find_first_of(",\"\n") == std::string::npos) {
        out_ << field;
    } else {
        out_ << '"';
        for (char c : field) out_ << (c == '"' ? "\"\"" : std::string(1, c));
        out_ << '"';
    }
    first_ = false;
    return *this;
}

Csv &Csv::operator<<(double value) {
    return *this << num(value);
}

void Csv::end_row() {
    out_ << "\n";
    out_.flush();
    first_ = true;
}

std::string num(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

std::string fmt(double value) {
    char text[40];
    if (value != 0.0 && (std::abs(value) < 1e-3 || std::abs(value) >= 1e6))
        std::snprintf(text, sizeof text, "%.2e", value);
    else
        std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

double resident_mb() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
    return 0.0;
}

std::vector<double> in_child(const std::function<std::vector<double>()> &work, double &peak_mb) {
    std::cout.flush();
    std::fflush(nullptr);
    int fds[2];
    if (pipe(fds) != 0) return {};
    const pid_t pid = fork();
    if (pid < 0) return {};
    if (pid == 0) {
        close(fds[0]);
        int status = 0;
        try {
            const std::vector<double> values = work();
            const size_t bytes = values.size() * sizeof(double);
            if (write(fds[1], values.data(), bytes) != static_cast<ssize_t>(bytes)) status = 1;
        } catch (const std::exception &e) {
            std::cerr << "animator-bench: " << e.what() << "\n";
            status = 1;
        }
        close(fds[1]);
        std::fflush(nullptr);
        _exit(status);
    }
    close(fds[1]);
    std::vector<double> values;
    double v = 0.0;
    while (read(fds[0], &v, sizeof v) == static_cast<ssize_t>(sizeof v)) values.push_back(v);
    close(fds[0]);
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    peak_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return {};
    return values;
}

} // namespace animator::bench

namespace {

int usage(const char *message) {
    if (message) std::cerr << "animator-bench: " << message << "\n";
    std::cerr << "usage: animator-bench [--quick] [--only exact|rest|gas|mesh|long|skip] [--out DIR] "
                 "[--runs N] [--sizes N,N,...] [--backends reference,physics.custom,physics.bullet]\n";
    return 2;
}

} // namespace

int main(int argc, char **argv) {
    using namespace animator::bench;
    Options o;
    o.out = std::filesystem::path(ANIMATOR_SOURCE_DIR) / "docs/bench";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool has_value = i + 1 < argc;
        if (a == "--quick") {
            o.quick = true;
        } else if (a == "--only" && has_value) {
            o.only = argv[++i];
        } else if (a == "--out" && has_value) {
            o.out = argv[++i];
        } else if (a == "--runs" && has_value) {
            o.runs = std::atoi(argv[++i]);
            if (o.runs < 1) return usage("--runs needs a positive number");
        } else if (a == "--sizes" && has_value) {
            std::stringstream list(argv[++i]);
            for (std::string n; std::getline(list, n, ',');) {
                const int size = std::atoi(n.c_str());
                if (size < 2) return usage("--sizes needs numbers of balls of 2 or more");
                o.sizes.push_back(size);
            }
        } else if (a == "--backends" && has_value) {
            std::stringstream list(argv[++i]);
            for (std::string b; std::getline(list, b, ',');) o.backends.push_back(b);
        } else if (a == "--help" || a == "-h") {
            usage(nullptr);
            return 0;
        } else {
            return usage(("unknown argument " + a).c_str());
        }
    }
    const std::vector<std::pair<std::string, void (*)(const Options &)>> sections = {
        {"exact", run_exact}, {"rest", run_rest}, {"gas", run_gas},
        {"mesh", run_mesh},   {"long", run_long}, {"skip", run_skip}};
    bool found = o.only.empty();
    for (const auto &s : sections) found = found || s.first == o.only;
    if (!found) return usage(("no section " + o.only).c_str());
    std::error_code ec;
    std::filesystem::create_directories(o.out, ec);
    std::cout << "animator-bench" << (o.quick ? " --quick" : "") << ": " << o.runs
              << " timed runs per point, medians; CSVs in " << o.out.string() << "\n";
    try {
        for (const auto &s : sections) {
            if (!o.only.empty() && s.first != o.only) continue;
            const auto start = std::chrono::steady_clock::now();
            std::cout << "\n== " << s.first << " ==\n";
            s.second(o);
            std::cout << "(" << s.first << ": " << fmt(seconds_since(start)) << " s)\n";
        }
    } catch (const std::exception &e) {
        std::cerr << "animator-bench: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
