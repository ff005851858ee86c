#include "isolated_child.hpp"

#include <cerrno>
#include <chrono>
#include <climits>
#include <csignal>
#include <cstddef>
#include <cstring>
#include <fstream>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <linux/audit.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

// The sanitizers reserve terabytes of address space up front, so no address-space limit can be
// set under them; the Lua and scene budgets still bound memory there.
#if defined(__SANITIZE_ADDRESS__)
#define ANIMATOR_NO_ADDRESS_LIMIT 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer) || __has_feature(thread_sanitizer)
#define ANIMATOR_NO_ADDRESS_LIMIT 1
#endif
#endif

#if defined(__x86_64__)
#define ANIMATOR_AUDIT_ARCH AUDIT_ARCH_X86_64
#elif defined(__aarch64__)
#define ANIMATOR_AUDIT_ARCH AUDIT_ARCH_AARCH64
#endif

namespace lua_scene {

namespace {

constexpr int kReplyFd = 3;
// The child's own exit codes for what went wrong before the work ran.
constexpr int kNoFilter = 125, kCallerGone = 123, kNoReplyFd = 124, kReplyLost = 122;

// The process's address space now, in bytes (0 if unknown), read before forking.
std::size_t address_space_in_use() {
    std::ifstream statm("/proc/self/statm");
    std::size_t pages = 0;
    if (!(statm >> pages)) return 0;
    return pages * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

// Refuses (EPERM) every system call but those that manage memory, read and write descriptors
// already open, tell the time and end the process. A system call of another architecture's
// numbering kills the process. Without a known architecture the filter is not installed.
void install_syscall_filter() {
#ifdef ANIMATOR_AUDIT_ARCH
    const long allowed[] = {
        SYS_read, SYS_write, SYS_writev, SYS_close, SYS_brk, SYS_mmap, SYS_munmap, SYS_mremap,
        SYS_mprotect, SYS_madvise, SYS_exit, SYS_exit_group, SYS_rt_sigreturn, SYS_rt_sigprocmask,
        SYS_futex, SYS_getpid, SYS_gettid, SYS_clock_gettime, SYS_gettimeofday, SYS_sched_yield,
        SYS_fstat, SYS_newfstatat, SYS_sigaltstack, // the last for the sanitizers
    };
    std::vector<sock_filter> program;
    program.push_back(BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, arch)));
    program.push_back(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, ANIMATOR_AUDIT_ARCH, 1, 0));
    program.push_back(BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_KILL_PROCESS));
    program.push_back(BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, nr)));
    for (long nr : allowed) {
        program.push_back(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, static_cast<uint32_t>(nr), 0, 1));
        program.push_back(BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW));
    }
    program.push_back(BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ERRNO | (EPERM & SECCOMP_RET_DATA)));
    sock_fprog filter{static_cast<unsigned short>(program.size()), program.data()};
    if (prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, &filter) != 0) _exit(kNoFilter); // fail closed
#endif
}

void set_limit(int resource, rlim_t value) {
    const rlimit limit{value, value};
    setrlimit(resource, &limit);
}

// In the child: from here on nothing of the caller's is reachable but memory.
[[noreturn]] void run_child(const std::function<std::string()> &work, const ChildLimits &limits, int reply_fd,
                            pid_t parent, std::size_t address_space) {
    if (reply_fd != kReplyFd) {
        if (dup2(reply_fd, kReplyFd) < 0) _exit(kNoReplyFd);
        close(reply_fd);
    }
    close(STDIN_FILENO);
    close(STDOUT_FILENO); // stderr stays, for a sanitizer's report
    close_range(kReplyFd + 1, ~0u, 0);

    std::signal(SIGXCPU, SIG_DFL);
    std::signal(SIGPIPE, SIG_DFL);
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(kCallerGone); // the caller is gone already

    const rlimit cpu{static_cast<rlim_t>(limits.cpu_seconds), static_cast<rlim_t>(limits.cpu_seconds) + 1};
    setrlimit(RLIMIT_CPU, &cpu); // the soft limit sends SIGXCPU, the hard one SIGKILL
    set_limit(RLIMIT_NOFILE, 0); // no new descriptor: no file, socket or pipe can be opened
    set_limit(RLIMIT_CORE, 0);
    set_limit(RLIMIT_NPROC, 0);
    set_limit(RLIMIT_MEMLOCK, 0);
#ifndef ANIMATOR_NO_ADDRESS_LIMIT
    if (address_space > 0) set_limit(RLIMIT_AS, address_space + limits.extra_address_space);
#else
    (void)address_space;
#endif
    prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0);
    install_syscall_filter();

    const std::string reply = work();
    for (std::size_t sent = 0; sent < reply.size();) {
        const ssize_t n = write(kReplyFd, reply.data() + sent, reply.size() - sent);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) _exit(kReplyLost);
        sent += static_cast<std::size_t>(n);
    }
    _exit(0); // no destructors and no atexit handlers of the caller's run here
}

// Waits for the child until `deadline`; then kills it. Returns its wait status.
int reap(pid_t pid, std::chrono::steady_clock::time_point deadline, bool &killed) {
    int status = 0;
    auto pause = std::chrono::microseconds(100);
    for (;;) {
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) return status;
        if (done < 0 && errno != EINTR) return 0; // not ours to wait for (SIGCHLD ignored)
        if (std::chrono::steady_clock::now() >= deadline && !killed) {
            kill(pid, SIGKILL);
            killed = true;
        }
        std::this_thread::sleep_for(pause);
        pause = std::min(pause * 2, std::chrono::microseconds(20000));
    }
}

} // namespace

ChildOutcome run_in_isolated_child(const std::function<std::string()> &work, const ChildLimits &limits) {
    ChildOutcome out;
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) {
        out.detail = std::string("cannot make a pipe: ") + std::strerror(errno);
        return out;
    }
    const std::size_t address_space = address_space_in_use();
    const pid_t parent = getpid();
    const pid_t pid = fork();
    if (pid < 0) {
        out.detail = std::string("cannot start a process: ") + std::strerror(errno);
        close(fds[0]);
        close(fds[1]);
        return out;
    }
    if (pid == 0) {
        close(fds[0]);
        run_child(work, limits, fds[1], parent, address_space);
    }
    close(fds[1]);

    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(limits.wall_seconds);
    bool timed_out = false, too_long = false;
    std::vector<char> buffer(1 << 16);
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            timed_out = true;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        const int ready = poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), INT_MAX)));
        if (ready < 0 && errno == EINTR) continue;
        if (ready == 0) {
            timed_out = true;
            break;
        }
        const ssize_t n = ready < 0 ? -1 : read(fds[0], buffer.data(), buffer.size());
        if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
        if (n <= 0) break; // the end of the reply (or a broken pipe: the status says why)
        out.reply.append(buffer.data(), static_cast<std::size_t>(n));
        if (out.reply.size() > limits.reply_bytes) {
            too_long = true;
            break;
        }
    }
    close(fds[0]);
    bool killed = false;
    if (timed_out || too_long) {
        kill(pid, SIGKILL);
        killed = true;
    }
    // A child that closed its pipe may still be running: it gets until the deadline.
    const int status = reap(pid, std::max(deadline, std::chrono::steady_clock::now()), killed);

    const std::string cpu = std::to_string(limits.cpu_seconds) + " s of processor time";
    if (timed_out) {
        out.end = ChildEnd::out_of_time;
        out.detail = "did not finish within " + std::to_string(limits.wall_seconds) + " s";
    } else if (too_long) {
        out.end = ChildEnd::crashed;
        out.detail = "replied with more than " + std::to_string(limits.reply_bytes >> 20) + " MiB";
    } else if (WIFSIGNALED(status) && (WTERMSIG(status) == SIGXCPU || (WTERMSIG(status) == SIGKILL && !killed))) {
        out.end = ChildEnd::out_of_time;
        out.detail = "used up its " + cpu;
    } else if (killed) {
        out.end = ChildEnd::out_of_time;
        out.detail = "did not end within " + std::to_string(limits.wall_seconds) + " s";
    } else if (WIFSIGNALED(status)) {
        out.end = ChildEnd::crashed;
        out.detail = "died of signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
    } else if (WIFEXITED(status) && WEXITSTATUS(status) == kNoFilter) {
        out.end = ChildEnd::crashed;
        out.detail = "could not install its system-call filter (this kernel refuses seccomp filters)";
    } else if (WIFEXITED(status) && WEXITSTATUS(status) != 0) {
        out.end = ChildEnd::crashed;
        out.detail = "exited with code " + std::to_string(WEXITSTATUS(status));
    } else {
        out.end = ChildEnd::replied;
        return out;
    }
    out.reply.clear();
    return out;
}

} // namespace lua_scene
