#include "sandbox.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

#include "shockfield/core/error.hpp"

namespace shockfield::fuzz {
namespace {

namespace fs = std::filesystem;
constexpr std::size_t kMessageBytes = 4096;

std::uintmax_t folder_bytes(const fs::path& dir) {
  std::uintmax_t total = 0;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    std::error_code size_ec;
    if (it->is_regular_file(size_ec)) {
      const auto n = it->file_size(size_ec);
      if (!size_ec) total += n;
    }
  }
  return total;
}

std::string head_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string text(kMessageBytes, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return text;
}

// A sanitizer report anywhere in `file` (not only in its first kilobytes: a run may print a lot
// before it): a UBSan "runtime error:" or an "==PID==ERROR: AddressSanitizer/LeakSanitizer"
// header. Not ASan's "WARNING: AddressSanitizer failed to allocate", printed under
// allocator_may_return_null=1 when a library (libhdf5 reading a damaged header) asks for 10^18
// bytes and handles the null it gets, as it does with glibc's malloc.
bool mentions_sanitizer(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  return s.find("runtime error:") != std::string::npos || s.find("==ERROR: ") != std::string::npos;
}

// In the child: the memory bound (see Limits::memory_bytes).
void limit_memory(const Limits& limits) {
#if !defined(__SANITIZE_ADDRESS__)
  if (limits.memory_bytes == 0) return;  // --memory-limit 0: a sanitized program under test
  const rlimit r{static_cast<rlim_t>(limits.memory_bytes), static_cast<rlim_t>(limits.memory_bytes)};
  ::setrlimit(RLIMIT_AS, &r);
#else
  (void)limits;
#endif
}

// In the child: stdout and stderr into files of the work folder.
void redirect_output(const fs::path& work) {
  const int out = ::open((work / "stdout.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int err = ::open((work / "stderr.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (out >= 0) ::dup2(out, 1);
  if (err >= 0) ::dup2(err, 2);
}

// Waits for the child, killing it at the time or output bound; fills kind and detail.
Outcome wait_for(pid_t pid, const fs::path& work, const Limits& limits) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  Outcome o;
  int status = 0;
  for (int polls = 0;; ++polls) {
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) break;
    const double elapsed = std::chrono::duration<double>(clock::now() - start).count();
    const bool too_long = elapsed > limits.seconds;
    const bool too_big = polls % 50 == 49 && folder_bytes(work) > limits.output_bytes;
    if (too_long || too_big) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      o.kind = too_long ? Outcome::Kind::timed_out : Outcome::Kind::too_much_output;
      o.seconds = elapsed;
      return o;
    }
    std::this_thread::sleep_for(std::chrono::microseconds(polls < 100 ? 200 : 2000));
  }
  o.seconds = std::chrono::duration<double>(clock::now() - start).count();
  if (WIFSIGNALED(status)) {
    o.kind = Outcome::Kind::crashed;
    o.detail = WTERMSIG(status);
    return o;
  }
  o.detail = WEXITSTATUS(status);
  switch (o.detail) {
    case 0: o.kind = Outcome::Kind::accepted; break;
    case 2: o.kind = Outcome::Kind::input_error; break;
    case 3: o.kind = Outcome::Kind::run_error; break;
    case 130: o.kind = Outcome::Kind::stopped; break;
    default: o.kind = Outcome::Kind::other_error;
  }
  if (folder_bytes(work) > limits.output_bytes) o.kind = Outcome::Kind::too_much_output;
  return o;
}

}  // namespace

const char* kind_name(Outcome::Kind k) {
  switch (k) {
    case Outcome::Kind::accepted: return "accepted";
    case Outcome::Kind::input_error: return "input error";
    case Outcome::Kind::run_error: return "run error";
    case Outcome::Kind::stopped: return "stopped";
    case Outcome::Kind::other_error: return "other error";
    case Outcome::Kind::crashed: return "CRASHED";
    case Outcome::Kind::timed_out: return "TIMED OUT";
    case Outcome::Kind::too_much_output: return "TOO MUCH OUTPUT";
    case Outcome::Kind::non_finite_output: return "NON-FINITE OUTPUT";
    case Outcome::Kind::invalid_output: return "INVALID OUTPUT";
  }
  return "?";
}

Outcome run_function(const std::function<void()>& body, const fs::path& work, const Limits& limits) {
  fs::create_directories(work);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    redirect_output(work);
    limit_memory(limits);
    int code = 0;
    std::string message;
    try {
      body();
    } catch (const InputError& e) {
      code = 2, message = e.what();
    } catch (const RunError& e) {
      code = 3, message = e.what();
    } catch (const std::exception& e) {
      code = 1, message = std::string("unexpected exception: ") + e.what();
    }
    std::ofstream(work / "message.txt") << message;
    std::fflush(nullptr);
    ::_exit(code);
  }
  Outcome o = wait_for(pid, work, limits);
  o.message = head_of(work / "message.txt");
  o.sanitizer_report = mentions_sanitizer(work / "stderr.txt");
  if (o.kind == Outcome::Kind::crashed || o.kind == Outcome::Kind::other_error)
    o.message += head_of(work / "stderr.txt");
  return o;
}

Outcome run_program(const std::vector<std::string>& argv, const fs::path& work, const Limits& limits) {
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    redirect_output(work);
    limit_memory(limits);
    if (::chdir(work.c_str()) != 0) ::_exit(127);
    ::setenv("OMP_NUM_THREADS", "1", 1);
    ::setenv("OMP_WAIT_POLICY", "passive", 1);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  Outcome o = wait_for(pid, work, limits);
  o.message = head_of(work / "stderr.txt");
  o.sanitizer_report = mentions_sanitizer(work / "stderr.txt");
  return o;
}

}  // namespace shockfield::fuzz
