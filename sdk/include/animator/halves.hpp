// Work split in two halves run at once, for a bake's passes over every model or sphere of a large
// scene, in the host and in plugins alike (C++ only, header-only): the machines we measure on
// have two cores, and a thread costs about 50 us to start.
#pragma once

#include <cstddef>
#include <exception>
#include <system_error>
#include <thread>

namespace ani {

// here() on this thread and there() on another at once (or after it, without a thread to be
// had), both done when it returns; an exception of either is thrown here then (here()'s first).
template <class Here, class There> void side_by_side(Here &&here, There &&there) {
    std::exception_ptr failed_there;
    std::thread other;
    try {
        other = std::thread([&] {
            try {
                there();
            } catch (...) {
                failed_there = std::current_exception();
            }
        });
    } catch (const std::system_error &) {
    }
    try {
        here();
    } catch (...) {
        if (other.joinable()) other.join();
        throw;
    }
    if (other.joinable())
        other.join();
    else
        there();
    if (failed_there) std::rethrow_exception(failed_there);
}

// From this many models or spheres, work on each is done in two halves at once (a thread costs
// about 50 us to start, a model or sphere 0.1 us or more: the gas lane's start of 100,000 spheres
// takes about 20 ms on one).
constexpr std::size_t kWorthTwoHalves = 4096;

// f(from, to) over [0, n): in two halves at once when `two` (and the machine has two cores).
template <class F> void in_halves(bool two, std::size_t n, F &&f) {
    if (!two || std::thread::hardware_concurrency() < 2) return f(std::size_t{0}, n);
    side_by_side([&] { f(std::size_t{0}, n / 2); }, [&] { f(n / 2, n); });
}

} // namespace ani
