// The event-driven bake's broad phase (physics.md, "Where the code is"): the uniform grid that
// many free spheres are filed in, so that a body is tested only against its neighbours
// (for_candidates, a template, is in event_bake_detail.hpp). Relies on grid.hpp.
#include "event_bake_detail.hpp"

namespace physics_custom::bake {

// With many bodies, a grid over the region where they start and the obstacles are; free
// spheres that leave it, keyed bodies and meshes are tested against every body. With few,
// every body is tested against every other (the grid's crossings would cost more than they
// save).
void EventBake::build_broad_phase() {
    if (bodies_.empty() || options_.broad_phase == BroadPhase::kAllPairs ||
        (options_.broad_phase == BroadPhase::kAutomatic && bodies_.size() < kGridFrom))
        return;
    double widest = 0.0;
    Box region{bodies_[0].path.p, bodies_[0].path.p};
    for (const Body &b : bodies_) {
        if (!b.sphere) continue;
        widest = std::max(widest, 2.0 * b.radius);
        region.lo = glm::min(region.lo, b.path.p);
        region.hi = glm::max(region.hi, b.path.p);
    }
    if (!(widest > 0.0)) return;
    grid_ = grid_over(region, widest);
    for (size_t i = 0; i < bodies_.size(); ++i)
        if (bodies_[i].active) file(static_cast<int>(i), t_begin_);
}

// The grid over `centres` (where the spheres start) and the static models, for spheres at most
// `widest` across (the gas lane's too: bake_gas.cpp).
std::unique_ptr<UniformGrid> EventBake::grid_over(Box region, double widest) const {
    for (const Obstacle &o : obstacles_)
        for (const Box &box : o.boxes) {
            region.lo = glm::min(region.lo, box.lo);
            region.hi = glm::max(region.hi, box.hi);
        }
    // A little wider than the largest sphere, so rounding at a wall cannot hide a contact.
    const double cell = widest * (1.0 + 1e-6);
    region.lo -= glm::dvec3(cell);
    region.hi += glm::dvec3(cell);
    return std::make_unique<UniformGrid>(region, cell);
}

// Files an active body: a free sphere under its cell, any other among the bodies outside
// the grid.
void EventBake::file(int i, double t) {
    Body &b = bodies_[static_cast<size_t>(i)];
    if (grid_ && b.free_sphere()) {
        b.cell = grid_->cell_of(b.path.at(t - b.t0));
        b.in_grid = grid_->inside(b.cell);
        if (b.in_grid) {
            grid_->insert(static_cast<uint32_t>(i), b.cell);
            return;
        }
    }
    outside_.push_back(i);
}

void EventBake::unfile(int i) {
    Body &b = bodies_[static_cast<size_t>(i)];
    if (b.in_grid) {
        grid_->remove(static_cast<uint32_t>(i), b.cell);
        b.in_grid = false;
        return;
    }
    const auto at = std::find(outside_.begin(), outside_.end(), i);
    if (at != outside_.end()) outside_.erase(at);
}

} // namespace physics_custom::bake
