// Running untrusted work in a child process, as browsers isolate web content: whatever the work
// does (an endless call inside a C library, a memory bomb, a bug we have not found that corrupts
// memory), the calling process only ever sees bytes on a pipe, a time-out or a dead child.
//
// The child is forked, closes every inherited descriptor but stderr and the pipe, can open no
// file, has limits on processor time and address space, and (on x86-64 and AArch64) a seccomp
// filter that refuses every system call but memory, reading, writing and exiting.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace lua_scene {

// The sanitizers slow memory-heavy code down several times (a scene that fills its Lua memory
// budget takes 1 s of processor time normally, 6 s under ASan): their builds allow 4 times more.
#if defined(__SANITIZE_ADDRESS__)
constexpr int kChildCpuSeconds = 20;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr int kChildCpuSeconds = 20;
#else
constexpr int kChildCpuSeconds = 5;
#endif
#else
constexpr int kChildCpuSeconds = 5;
#endif

struct ChildLimits {
    int cpu_seconds = kChildCpuSeconds;         // processor time; then SIGXCPU ends the child
    int wall_seconds = 60;                      // a hang guard only: the child cannot block
    std::size_t extra_address_space = 1u << 30; // above what the process had when it forked
    std::size_t reply_bytes = 512u << 20;       // a larger reply ends the child
};

enum class ChildEnd {
    replied,        // exited normally; `reply` holds what the work returned
    out_of_time,    // used up its processor time or its wall time
    crashed,        // died of another signal or exited with a failure
    cannot_start,   // no pipe or no process could be made
};

struct ChildOutcome {
    ChildEnd end = ChildEnd::cannot_start;
    std::string reply;
    std::string detail; // for anything but `replied`: what happened, in words
};

// Runs `work` in a child process under `limits` and returns what it returned. `work` must not
// throw and must not rely on any other thread of the caller (the child has only this one).
ChildOutcome run_in_isolated_child(const std::function<std::string()> &work, const ChildLimits &limits);

} // namespace lua_scene
