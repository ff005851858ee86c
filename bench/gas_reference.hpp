// The reference gas: a compact event-driven program for elastic hard spheres in a box, written
// for animator-bench's `gas` section, which runs it beside physics.custom on the same gas so that
// the plugin's speed is measured against a minimal fast code in one run (docs/performance.md).
//
// What it does: spheres of one radius and any masses move in straight lines between events, in a
// box of six planes; a pair meets at the stable root of |dp + dv t|^2 = (2r)^2 and takes the
// elastic response of unequal masses along its centre line; a centre reaching a wall (lo + r or
// hi - r) reflects that velocity component. No gravity, friction or spin; restitution 1. Every
// event time is computed from the straight-line paths (no time step): the run is exact to
// rounding, as physics.custom is.
//
// How (the techniques of the fast event-driven codes: Rapaport, "The Art of Molecular Dynamics
// Simulation"; Lubachevsky, J. Comput. Phys. 94, 255 (1991); Smallenburg, "Efficient
// event-driven simulations of hard spheres", Eur. Phys. J. E 45, 22 (2022)):
// - the hot per-sphere data in one 64-byte record (position at the sphere's own local time,
//   velocity, local time, collision counter, next sphere in its cell); positions move lazily;
// - a cell list of cells at least 2r wide (padded with a layer of empty cells: no bounds tests);
//   crossing a cell face is an event, after which only the 9 cells newly in reach are scanned;
// - one event per sphere (its earliest pair collision, wall or cell crossing), made stale lazily
//   by per-sphere collision counters (a pair event predicted while the partner's counter was c is
//   stale once that counter moved on);
// - a calendar queue of the spheres' event times (Brown, Commun. ACM 31, 1220 (1988)), indexed by
//   sphere: buckets of time in unsorted lists, the current one in a small binary heap (physics.custom's
//   calendar_queue.hpp, which its gas lane uses too: the two are compared with the same queue);
// - nothing is allocated in the event loop.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace animator::bench::reference {

struct Gas {
    std::vector<std::array<double, 3>> position, velocity; // sphere centres (m), velocities (m/s)
    std::vector<double> mass;                              // kg, may differ per sphere
    double radius = 0.0;                                   // every sphere's
    std::array<double, 3> lo{}, hi{};                      // the box's inner walls (planes)
};

// A collision, for checking: spheres a and b, or sphere a and wall b = kWall + axis.
struct Collision {
    double time = 0.0;
    std::uint32_t a = 0, b = 0;
};
constexpr std::uint32_t kWall = 0xfffffff0u;

struct Result {
    std::uint64_t pair_collisions = 0, wall_collisions = 0, cell_crossings = 0;
    std::uint64_t predictions = 0;  // pair time-of-impact computations done
    std::uint64_t stale_events = 0; // events found stale when they came up (then predicted anew)
    double time = 0.0;              // the time reached
    Gas final_state;                // every sphere at `time`
};

// Runs the gas elastically from t = 0 to T. The spheres must start inside the box and apart.
// With `log`, every collision is appended to it in time order (for checks: it allocates).
Result run(const Gas &gas, double T, std::vector<Collision> *log = nullptr);

} // namespace animator::bench::reference
