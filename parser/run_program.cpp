#include "parser/run_program.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <utility>

extern char** environ;

namespace darc {

namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

// The RI end of one answer.
constexpr char kTerminator = '\377';
// Bytes read from a pipe at a time.
constexpr size_t kReadChunk = size_t{1} << 16;
// A standard-error line longer than this is passed on in pieces, so that a program writing no
// line breaks cannot grow the buffer.
constexpr size_t kMaxStderrLine = 4096;
// Without pidfd_open (Linux before 5.3): how often to check whether the program has exited.
constexpr milliseconds kExitCheckInterval{10};

class UniqueFd {
 public:
  UniqueFd() = default;
  explicit UniqueFd(int fd) : fd_(fd) {}
  UniqueFd(UniqueFd&& o) noexcept : fd_(std::exchange(o.fd_, -1)) {}
  UniqueFd& operator=(UniqueFd&& o) noexcept {
    if (this != &o) {
      reset();
      fd_ = std::exchange(o.fd_, -1);
    }
    return *this;
  }
  UniqueFd(const UniqueFd&) = delete;
  UniqueFd& operator=(const UniqueFd&) = delete;
  ~UniqueFd() { reset(); }

  int get() const { return fd_; }
  bool is_open() const { return fd_ >= 0; }
  void reset() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }

 private:
  int fd_ = -1;
};

struct Pipe {
  UniqueFd read, write;
};

// Both ends close on exec: the child gets only the copies dup2'd onto 0, 1 and 2.
bool make_pipe(Pipe& p) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) return false;
  p.read = UniqueFd(fds[0]);
  p.write = UniqueFd(fds[1]);
  return true;
}

void set_nonblocking(const UniqueFd& fd) { ::fcntl(fd.get(), F_SETFL, ::fcntl(fd.get(), F_GETFL) | O_NONBLOCK); }

// The started program. Until it has been waited for, its pid (and so its process group id)
// cannot be reused, so killing the group is safe exactly then; a program still running when
// this goes out of scope is killed and waited for, so that no way out leaves a process behind.
class ChildProcess {
 public:
  explicit ChildProcess(pid_t pid) : pid_(pid) {}
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;
  ~ChildProcess() {
    if (!exited_) kill_and_wait();
  }

  pid_t pid() const { return pid_; }
  bool exited() const { return exited_; }
  int status() const { return status_; }

  // Reaps the program if it has exited; true when it has.
  bool check_exit() {
    if (exited_) return true;
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) == pid_) set_status(status);
    return exited_;
  }

  // SIGKILL to the process group (the program and what it started), then waits.
  void kill_and_wait() {
    if (exited_) return;
    ::kill(-pid_, SIGKILL);
    ::kill(pid_, SIGKILL);  // in case the group could not be made
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    set_status(status);
  }

 private:
  void set_status(int status) {
    status_ = status;
    exited_ = true;
  }
  pid_t pid_;
  bool exited_ = false;
  int status_ = 0;
};

// Blocks SIGPIPE in this thread while the program's standard input is written: a program that
// exits without reading it must not take darc down. A SIGPIPE raised meanwhile is taken off the
// pending set before the previous mask returns.
class SigpipeBlocked {
 public:
  SigpipeBlocked() {
    sigemptyset(&set_);
    sigaddset(&set_, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &set_, &previous_);
  }
  SigpipeBlocked(const SigpipeBlocked&) = delete;
  SigpipeBlocked& operator=(const SigpipeBlocked&) = delete;
  ~SigpipeBlocked() {
    if (raised_ && !sigismember(&previous_, SIGPIPE)) {
      const timespec no_wait{};
      while (sigtimedwait(&set_, nullptr, &no_wait) == SIGPIPE) {
      }
    }
    pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
  }
  void note_raised() { raised_ = true; }

 private:
  sigset_t set_{}, previous_{};
  bool raised_ = false;
};

// Splits the program's standard error into lines for the caller.
class StderrLines {
 public:
  explicit StderrLines(const std::function<void(std::string_view)>& sink) : sink_(sink) {}
  void add(std::string_view bytes) {
    for (char c : bytes) {
      if (c == '\n') {
        flush();
      } else {
        line_ += c;
        if (line_.size() >= kMaxStderrLine) flush();
      }
    }
  }
  void finish() {
    if (!line_.empty()) flush();
  }

 private:
  void flush() {
    if (sink_) sink_(line_);
    line_.clear();
  }
  const std::function<void(std::string_view)>& sink_;
  std::string line_;
};

// The answer on standard output: the bytes up to the terminator; what follows it is dropped.
class AnswerText {
 public:
  void add(std::string_view bytes) {
    if (complete_) return;
    const size_t end = bytes.find(kTerminator);
    rib_.append(bytes.substr(0, end));
    complete_ = end != std::string_view::npos;
  }
  bool complete() const { return complete_; }
  size_t size() const { return rib_.size(); }
  std::string take() { return std::move(rib_); }

 private:
  std::string rib_;
  bool complete_ = false;
};

enum class ReadResult { Data, Empty, Closed };

// One non-blocking read from `fd` into `buffer`; closes `fd` at end of file or on an error.
ReadResult read_some(UniqueFd& fd, std::vector<char>& buffer, std::string_view& got) {
  const ssize_t n = ::read(fd.get(), buffer.data(), buffer.size());
  if (n > 0) {
    got = std::string_view(buffer.data(), static_cast<size_t>(n));
    return ReadResult::Data;
  }
  if (n < 0 && (errno == EAGAIN || errno == EINTR)) return ReadResult::Empty;
  fd.reset();
  return ReadResult::Closed;
}

std::string seconds_text(milliseconds ms) { return fmt::format("{:g} s", static_cast<double>(ms.count()) / 1000.0); }

std::string exit_problem(int status) {
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    return fmt::format("was killed by signal {} ({})", sig, ::strsignal(sig));
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) != 0) return fmt::format("exited with status {}", WEXITSTATUS(status));
  return "";
}

ProgramAnswer failure(std::string why) {
  ProgramAnswer a;
  a.error = std::move(why);
  return a;
}

// The process, its three pipes, and the exchange with it.
class Exchange {
 public:
  Exchange(ChildProcess& child, Pipe& in, Pipe& out, Pipe& err, const std::string& request,
           const RunProgramLimits& limits, const std::function<void(std::string_view)>& stderr_line)
      : child_(child),
        input_(in.write),
        output_(out.read),
        errors_(err.read),
        request_(request),
        limits_(limits),
        stderr_lines_(stderr_line),
        buffer_(kReadChunk) {
#ifdef SYS_pidfd_open
    exit_fd_ = UniqueFd(static_cast<int>(::syscall(SYS_pidfd_open, child.pid(), 0)));
#endif
  }

  ProgramAnswer run() {
    const Clock::time_point deadline = Clock::now() + limits_.time_limit;
    while (!child_.exited()) {
      const Clock::time_point now = Clock::now();
      if (now >= deadline) {
        child_.kill_and_wait();
        return failure(answer_.complete()
                           ? fmt::format("answered but did not exit within {} after its input was closed: killed",
                                         seconds_text(limits_.time_limit))
                           : fmt::format("did not answer within {}: killed", seconds_text(limits_.time_limit)));
      }
      milliseconds wait = std::chrono::ceil<milliseconds>(deadline - now);
      if (!exit_fd_.is_open()) wait = std::min(wait, kExitCheckInterval);
      if (!exchange_once(wait))
        return failure(fmt::format("wrote more than {} bytes of RIB: killed", limits_.max_output_bytes));
    }
    // What is still in the pipes was written before the program exited; processes it left
    // behind may hold them open, so read only what is there.
    while (output_.is_open() && Clock::now() < deadline && read_output() == ReadResult::Data) {
      if (over_limit()) return failure(fmt::format("wrote more than {} bytes of RIB", limits_.max_output_bytes));
    }
    while (errors_.is_open() && Clock::now() < deadline && read_errors() == ReadResult::Data) {
    }
    stderr_lines_.finish();
    if (std::string problem = exit_problem(child_.status()); !problem.empty()) return failure(problem);
    if (!answer_.complete())
      return failure(fmt::format("ended without the \\377 terminator after {} bytes of output", answer_.size()));
    ProgramAnswer a;
    a.ok = true;
    a.rib = answer_.take();
    return a;
  }

 private:
  // One poll and what it allows; false when the output went over the limit (the program is killed).
  bool exchange_once(milliseconds wait) {
    std::array<pollfd, 4> fds{};
    nfds_t count = 0;
    auto watch = [&](const UniqueFd& fd, short events) {
      if (!fd.is_open()) return -1;
      fds[count] = pollfd{fd.get(), events, 0};
      return static_cast<int>(count++);
    };
    const int in = input_sent_ ? -1 : watch(input_, POLLOUT);
    const int out = watch(output_, POLLIN);
    const int err = watch(errors_, POLLIN);
    const int exit = watch(exit_fd_, POLLIN);
    if (::poll(fds.data(), count, static_cast<int>(wait.count())) < 0 && errno != EINTR) {
      child_.kill_and_wait();
      return true;  // reported as the program's status (killed)
    }
    auto ready = [&](int i) { return i >= 0 && fds[static_cast<size_t>(i)].revents != 0; };
    if (ready(in)) write_input();
    if (ready(out)) {
      read_output();
      if (over_limit()) {
        child_.kill_and_wait();
        return false;
      }
    }
    if (ready(err)) read_errors();
    if (exit < 0 || ready(exit)) child_.check_exit();
    return true;
  }

  void write_input() {
    const ssize_t n = ::write(input_.get(), request_.data() + written_, request_.size() - written_);
    if (n > 0) written_ += static_cast<size_t>(n);
    if (n < 0 && errno == EPIPE) sigpipe_.note_raised();
    // A program that closed its input may still answer: stop writing, wait for the answer.
    if (written_ == request_.size() || (n < 0 && errno != EAGAIN && errno != EINTR)) input_sent_ = true;
  }

  ReadResult read_output() {
    std::string_view got;
    const ReadResult r = read_some(output_, buffer_, got);
    if (r == ReadResult::Data) {
      answer_.add(got);
      // RI: the input stays open until the answer is complete; one request per process here.
      if (answer_.complete()) input_.reset();
    }
    return r;
  }

  ReadResult read_errors() {
    std::string_view got;
    const ReadResult r = read_some(errors_, buffer_, got);
    if (r == ReadResult::Data) stderr_lines_.add(got);
    return r;
  }

  bool over_limit() const { return answer_.size() > limits_.max_output_bytes; }

  ChildProcess& child_;
  UniqueFd& input_;
  UniqueFd& output_;
  UniqueFd& errors_;
  UniqueFd exit_fd_;  // a pidfd: readable once the program has exited
  const std::string& request_;
  const RunProgramLimits& limits_;
  StderrLines stderr_lines_;
  AnswerText answer_;
  std::vector<char> buffer_;
  size_t written_ = 0;
  bool input_sent_ = false;
  SigpipeBlocked sigpipe_;
};

// Starts argv[0] with 0, 1, 2 on the pipes, in a process group of its own, with the signal
// mask cleared and SIGPIPE at its default (darc may block or ignore it). Returns 0 or an errno.
int spawn(const std::vector<std::string>& argv, Pipe& in, Pipe& out, Pipe& err, pid_t& pid) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in.read.get(), STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, out.write.get(), STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, err.write.get(), STDERR_FILENO);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  posix_spawnattr_setpgroup(&attributes, 0);
  sigset_t none, defaults;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attributes, &none);
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGPIPE);
  posix_spawnattr_setsigdefault(&attributes, &defaults);

  const int rc = posix_spawn(&pid, args[0], &actions, &attributes, args.data(), environ);
  posix_spawnattr_destroy(&attributes);
  posix_spawn_file_actions_destroy(&actions);
  return rc;
}

}  // namespace

ProgramAnswer run_program(const std::vector<std::string>& argv, const std::string& request,
                          const RunProgramLimits& limits, const std::function<void(std::string_view)>& stderr_line) {
  if (argv.empty()) return failure("no program given");
  Pipe in, out, err;
  if (!make_pipe(in) || !make_pipe(out) || !make_pipe(err))
    return failure(fmt::format("cannot make pipes: {}", std::strerror(errno)));
  pid_t pid = 0;
  if (const int rc = spawn(argv, in, out, err, pid); rc != 0)
    return failure(fmt::format("cannot start {}: {}", argv[0], std::strerror(rc)));
  ChildProcess child(pid);
  // The child's ends belong to the child now: with them closed here, its exit ends the pipes.
  in.read.reset();
  out.write.reset();
  err.write.reset();
  set_nonblocking(in.write);
  set_nonblocking(out.read);
  set_nonblocking(err.read);
  return Exchange(child, in, out, err, request, limits, stderr_line).run();
}

}  // namespace darc
