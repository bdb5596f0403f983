// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair-curves serve: running the program itself as a child process for one request
// (doc/editor_api.md, "Why a child process"). The child gets the request's scratch directory as
// its working directory, /dev/null as stdin, its stdout and stderr on pipes, an address-space cap
// (RLIMIT_AS) and a CPU-time cap (RLIMIT_CPU), and is SIGKILLed at a wall-clock deadline. So a
// crash, a runaway solve or a solve that eats memory ends in the child; the server only reads two
// pipes (both polled, so that a child filling one of them while the server waits on the other
// cannot deadlock) and reaps the child in every case (waitpid, also after SIGKILL).
//
// Between fork and exec the child calls only async-signal-safe functions (the server has other
// threads, any of which may hold a lock of malloc): the argument vector and the paths are made
// before the fork.

#ifndef FAIR_CURVES_SERVE_CHILD_PROCESS_H
#define FAIR_CURVES_SERVE_CHILD_PROCESS_H

#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstring>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fair_curves {
namespace serve {

/// The caps of one child (doc/editor_api.md, "Caps").
struct Child_limits {
  double wall_seconds = 20;                          ///< SIGKILL after this wall-clock time
  unsigned long long address_space = 4ull << 30;     ///< RLIMIT_AS, bytes
  /// stdout + stderr captured at most (more: killed); also RLIMIT_FSIZE of every file the child
  /// writes and the cap on what the server reads back from its scratch directory.
  std::size_t max_output = std::size_t(64) << 20;
};

/// What became of a child.
struct Child_result {
  bool started = false;       ///< fork succeeded (otherwise `error` says why)
  int exit_code = -1;         ///< exit status when it exited normally, else -1
  int signal = 0;             ///< the signal that ended it (SIGKILL after a timeout too)
  bool timed_out = false;     ///< killed at the wall-clock deadline
  bool output_overflow = false;  ///< killed because it wrote more than max_output
  bool client_gone = false;   ///< killed because the client closed its connection (no answer)
  std::string out, err;       ///< what it wrote on stdout and stderr
  std::string error;          ///< why it could not be started
};

/// The children alive now, so that a stopping server can kill them (Child_registry::kill_all).
class Child_registry {
 public:
  static Child_registry& instance() {
    static Child_registry r;
    return r;
  }
  void add(pid_t pid) {
    std::lock_guard<std::mutex> lock(mutex_);
    pids_.insert(pid);
  }
  void remove(pid_t pid) {
    std::lock_guard<std::mutex> lock(mutex_);
    pids_.erase(pid);
  }
  /// SIGKILL to every child still running (their runners reap them).
  void kill_all() {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const pid_t pid : pids_) ::kill(pid, SIGKILL);
  }

 private:
  std::mutex mutex_;
  std::set<pid_t> pids_;
};

/// A counting semaphore of the solves that run at once (children and fresh in-process kappa
/// solves; review finding 3): more solves than cores only make every one of them slower, up to
/// the wall-clock cap. A solve waits for a slot until its own deadline (the wait counts against
/// the solve's time cap).
class Solve_slots {
 public:
  explicit Solve_slots(int count) : count_(count), free_(count) {}
  int count() const { return count_; }
  /// A slot, waiting until `deadline`; false when none became free in time or the server stops.
  bool acquire(std::chrono::steady_clock::time_point deadline) {
    std::unique_lock<std::mutex> lock(mutex_);
    if (!cv_.wait_until(lock, deadline, [&] { return free_ > 0 || stopping_; })) return false;
    if (stopping_) return false;
    --free_;
    return true;
  }
  void release() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      ++free_;
    }
    cv_.notify_one();
  }
  /// Every waiting solve gives up (the server stops).
  void stop() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    cv_.notify_all();
  }

 private:
  const int count_;
  int free_;
  bool stopping_ = false;
  std::mutex mutex_;
  std::condition_variable cv_;
};

/// A slot of Solve_slots held for a scope.
class Solve_slot {
 public:
  Solve_slot(Solve_slots& slots, std::chrono::steady_clock::time_point deadline)
      : slots_(slots), held_(slots.acquire(deadline)) {}
  ~Solve_slot() {
    if (held_) slots_.release();
  }
  Solve_slot(const Solve_slot&) = delete;
  Solve_slot& operator=(const Solve_slot&) = delete;
  explicit operator bool() const { return held_; }

 private:
  Solve_slots& slots_;
  bool held_;
};

namespace detail {

inline void close_fd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

/// In the child, between fork and exec: async-signal-safe calls only; any failure is _exit(127).
[[noreturn]] inline void exec_child(const char* program, char* const* argv, const char* cwd, int out_fd, int err_fd,
                                    const Child_limits& limits) {
  const int null_fd = ::open("/dev/null", O_RDONLY);
  if (null_fd < 0 || ::dup2(null_fd, 0) < 0 || ::dup2(out_fd, 1) < 0 || ::dup2(err_fd, 2) < 0) ::_exit(127);
  // Every other descriptor of the server (its listening socket, the clients' connections, the
  // pipes of other children) closed: the child must not keep a client's connection open.
#ifdef SYS_close_range
  if (::syscall(SYS_close_range, 3u, ~0u, 0u) != 0)
#endif
  {
    struct rlimit files;
    const long top = ::getrlimit(RLIMIT_NOFILE, &files) == 0 && files.rlim_cur != RLIM_INFINITY
                         ? static_cast<long>(files.rlim_cur) : 65536;
    for (long fd = 3; fd < top; ++fd) ::close(static_cast<int>(fd));
  }
  if (::chdir(cwd) != 0) ::_exit(127);
  struct rlimit as;
  as.rlim_cur = as.rlim_max = static_cast<rlim_t>(limits.address_space);
  // RLIMIT_CPU in whole seconds, one more than the wall-clock cap: the wall clock normally
  // decides; the CPU cap is the OS's own backstop (SIGKILL at the hard limit).
  struct rlimit cpu;
  cpu.rlim_cur = static_cast<rlim_t>(limits.wall_seconds) + 1;
  cpu.rlim_max = cpu.rlim_cur + 1;
  // RLIMIT_FSIZE: no file of the child (a --profile CSV, an export) beyond the output cap
  // (SIGXFSZ); RLIMIT_CORE 0: a crashing child writes no core into the scratch directory
  // (review finding 5).
  struct rlimit fsize;
  fsize.rlim_cur = fsize.rlim_max = static_cast<rlim_t>(limits.max_output);
  struct rlimit core;
  core.rlim_cur = core.rlim_max = 0;
  if (::setrlimit(RLIMIT_AS, &as) != 0 || ::setrlimit(RLIMIT_CPU, &cpu) != 0 || ::setrlimit(RLIMIT_FSIZE, &fsize) != 0 ||
      ::setrlimit(RLIMIT_CORE, &core) != 0)
    ::_exit(127);
  // Default dispositions for the child (the server ignores SIGPIPE; exec keeps ignored signals).
  ::signal(SIGPIPE, SIG_DFL);
  ::signal(SIGXFSZ, SIG_DFL);
  ::execv(program, argv);
  ::_exit(127);
}

} // namespace detail

/// Runs `program` with `args` (args[0] is the program's name) in `cwd` under `limits`.
/// `client_fd` (>= 0): the connection of the request; when its peer closes it (POLLRDHUP,
/// POLLHUP, POLLERR; not POLLIN, which a pipelined next request raises) the child is killed and
/// `client_gone` set, so that an abandoned request does not solve on (review finding 3).
inline Child_result run_child(const std::string& program, const std::vector<std::string>& args,
                              const std::string& cwd, const Child_limits& limits, int client_fd = -1) {
  Child_result r;
  // Everything the child needs is made before the fork.
  std::vector<std::string> arg_copy = args;
  std::vector<char*> argv;
  for (std::string& a : arg_copy) argv.push_back(&a[0]);
  argv.push_back(nullptr);
  int out_pipe[2] = {-1, -1}, err_pipe[2] = {-1, -1};
  if (::pipe2(out_pipe, O_CLOEXEC) != 0 || ::pipe2(err_pipe, O_CLOEXEC) != 0) {
    r.error = std::string("cannot make a pipe: ") + std::strerror(errno);
    detail::close_fd(out_pipe[0]);
    detail::close_fd(out_pipe[1]);
    return r;
  }
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid < 0) {
    r.error = std::string("cannot start the solver process: ") + std::strerror(errno);
    for (int* fd : {&out_pipe[0], &out_pipe[1], &err_pipe[0], &err_pipe[1]}) detail::close_fd(*fd);
    return r;
  }
  if (pid == 0) detail::exec_child(program.c_str(), argv.data(), cwd.c_str(), out_pipe[1], err_pipe[1], limits);
  r.started = true;
  int fds[2] = {out_pipe[0], err_pipe[0]};
  bool killed = false, reaped = false;
  // From here on an exception (bad_alloc of a sink or of the registry) must not leave the child
  // running unreaped (review finding 12): the guard kills, reaps and unregisters it.
  struct Guard {
    pid_t pid;
    int* fds;
    int* write_ends;
    bool& reaped;
    ~Guard() {
      for (int k = 0; k < 2; ++k) {
        detail::close_fd(fds[k]);
        detail::close_fd(write_ends[k]);
      }
      if (!reaped) {
        ::kill(pid, SIGKILL);
        int status;
        while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
      }
      Child_registry::instance().remove(pid);
    }
  };
  int write_ends[2] = {out_pipe[1], err_pipe[1]};
  const Guard guard{pid, fds, write_ends, reaped};
  Child_registry::instance().add(pid);
  detail::close_fd(write_ends[0]);
  detail::close_fd(write_ends[1]);
  std::string* sinks[2] = {&r.out, &r.err};
  const auto deadline = start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                    std::chrono::duration<double>(limits.wall_seconds));
  auto kill_child = [&]() {
    if (!killed) ::kill(pid, SIGKILL);
    killed = true;
  };
  char buffer[65536];
  while (fds[0] >= 0 || fds[1] >= 0) {
    const auto now = std::chrono::steady_clock::now();
    if (now >= deadline) {
      r.timed_out = true;
      kill_child();
      break;
    }
    const long long ms = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now).count() + 1;
    pollfd p[3];
    nfds_t n = 0;
    int which[3];
    for (int k = 0; k < 2; ++k)
      if (fds[k] >= 0) {
        p[n].fd = fds[k];
        p[n].events = POLLIN;
        p[n].revents = 0;
        which[n++] = k;
      }
    if (client_fd >= 0) {
      p[n].fd = client_fd;
      p[n].events = POLLRDHUP;
      p[n].revents = 0;
      which[n++] = -1;
    }
    const int ready = ::poll(p, n, static_cast<int>(ms > 1000000 ? 1000000 : ms));
    if (ready < 0) {
      if (errno == EINTR) continue;
      kill_child();
      break;
    }
    for (nfds_t i = 0; i < n; ++i) {
      if (!p[i].revents) continue;
      if (which[i] < 0) {
        if (p[i].revents & (POLLRDHUP | POLLHUP | POLLERR | POLLNVAL)) {
          r.client_gone = true;
          kill_child();
        }
        continue;
      }
      const int k = which[i];
      const ssize_t got = ::read(fds[k], buffer, sizeof buffer);
      if (got > 0) {
        sinks[k]->append(buffer, static_cast<std::size_t>(got));
        if (r.out.size() + r.err.size() > limits.max_output) {
          r.output_overflow = true;
          kill_child();
        }
      } else if (got == 0 || (errno != EINTR && errno != EAGAIN)) {
        detail::close_fd(fds[k]);
      }
    }
    if (r.output_overflow || r.client_gone) break;
  }
  detail::close_fd(fds[0]);
  detail::close_fd(fds[1]);
  // Reap: the pipes are closed, so the child is exiting (or closed them and runs on: wait up to
  // the deadline, then kill it).
  int status = 0;
  for (;;) {
    const pid_t w = ::waitpid(pid, &status, killed ? 0 : WNOHANG);
    if (w == pid) {
      reaped = true;
      break;
    }
    if (w < 0 && errno != EINTR) {
      reaped = true;  // not ours to wait for any more
      break;
    }
    if (w == 0) {
      if (std::chrono::steady_clock::now() >= deadline) {
        r.timed_out = true;
        kill_child();
      } else ::usleep(100);  // the child is exiting (its pipes are closed): a short wait
    }
  }
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  else if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  return r;
}

} // namespace serve
} // namespace fair_curves

#endif // FAIR_CURVES_SERVE_CHILD_PROCESS_H
