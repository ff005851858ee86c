// animator-bench: what the sections share. Each section measures, prints a table and writes
// one CSV (docs/performance.md explains every column).
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace animator::bench {

struct Options {
    bool quick = false;              // a seconds-long smoke run
    std::string only;                // one section, or all
    std::filesystem::path out;       // where the CSVs go
    int runs = 5;                    // timed runs per point; the median is reported
    std::vector<int> sizes;          // the gas's numbers of balls, instead of its own
    std::vector<std::string> backends; // the gas's backends (and reference), instead of all
};

// Seconds since `start`.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

inline double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// A CSV file: a header, then rows of fields (numbers in full precision).
class Csv {
  public:
    Csv(const std::filesystem::path &path, const std::vector<std::string> &columns);
    Csv &operator<<(const std::string &field);
    Csv &operator<<(double value);
    void end_row();

  private:
    std::ofstream out_;
    bool first_ = true;
};

std::string num(double value); // %.17g, for CSV fields
std::string fmt(double value); // 3 significant digits, for tables

// The process's resident memory now and at its peak (MB), from /proc/self/status.
double resident_mb();

// Runs `work` in a forked child (so that its peak memory is its own); `work` returns numbers
// that come back. `peak_mb` gets the child's peak resident memory. Returns empty if it failed.
std::vector<double> in_child(const std::function<std::vector<double>()> &work, double &peak_mb);

void run_exact(const Options &o);    // time against error on physics.md's exact scenes
void run_gas(const Options &o);      // a gas of N spheres in a box: scaling
void run_mesh(const Options &o);     // mesh against mesh: the BVH against brute force
void run_long(const Options &o);     // 300000 s of a ball in a box
void run_skip(const Options &o);     // what the scenes did not need
void run_rest(const Options &o);     // time against error on contacts that last (issue 19)

} // namespace animator::bench
