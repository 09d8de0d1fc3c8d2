// The coordinator: hands cases to worker processes over pipes, turns a worker's death or
// silence into that case's verdict, restarts it, appends every result to results.jsonl as
// it arrives, reruns unexpected failures once, and writes the reports at the end.
#include "tierlift/corpus/runner.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <climits>
#include <csignal>
#include <cstring>
#include <deque>
#include <fcntl.h>
#include <filesystem>
#include <map>
#include <poll.h>
#include <set>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include "tierlift/corpus/output_guard.h"
#include "tierlift/corpus/shard.h"
#include "tierlift/io/output_file.h"

namespace tierlift::corpus {
namespace {

using Clock = std::chrono::steady_clock;

// Cases a worker holds at once: the one it runs and those written after it before its answer
// comes back. The worker starts the next as soon as it has answered instead of waiting for the
// coordinator to wake, read, record and write (on a busy machine that wait is a scheduling
// delay per case), and the coordinator, woken once, takes every answer that has come in.
// How many are written ahead follows the time a case takes: about kAheadMs of work, at least
// one case and at most kCasesAhead. Fast cases (check-only: 0.1-0.2 ms) go many at a time, so
// the coordinator, a third process on two cores, costs less per case; slow ones (a full lift:
// milliseconds) one at a time, so the last cases of a run do not queue behind a busy worker
// while another idles.
constexpr size_t kCasesAhead = 15;
constexpr double kAheadMs = 2.0;
// What may wait in a worker's input pipe unread: a pipe holds at least PIPE_BUF bytes (a
// user over the kernel's pipe-buffer limit gets one page), so writing no more than that
// ahead never blocks the coordinator, whatever a busy or hung worker does.
constexpr size_t kBytesAhead = PIPE_BUF;

struct Worker {
  pid_t pid = -1;
  int to = -1, from = -1;
  std::string buffer;
  // Indices into the case list, written and not yet answered, in order: the worker answers
  // them in this order, so the front one is running (a death or a timeout is its verdict).
  std::deque<size_t> jobs;
  std::deque<size_t> line_bytes; // the length of each job's line, in the same order
  Clock::time_point started;     // when the front case started: written, or the answer before it
};

void pop_job(Worker& w) {
  w.jobs.pop_front();
  w.line_bytes.pop_front();
}

// The bytes of the cases written after the one the worker runs.
size_t bytes_ahead(const Worker& w) {
  size_t n = 0;
  for (size_t k = 1; k < w.line_bytes.size(); ++k) n += w.line_bytes[k];
  return n;
}

bool spawn(Worker& w, const std::vector<std::string>& argv, int log_fd) {
  int in[2], out[2];
  if (::pipe2(in, O_CLOEXEC) != 0) return false;
  if (::pipe2(out, O_CLOEXEC) != 0) {
    ::close(in[0]);
    ::close(in[1]);
    return false;
  }
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  // Taken at each start: a caller may change its environment between runs.
  const std::vector<std::string> environment = worker_environment(environ);
  std::vector<char*> env;
  for (const std::string& e : environment) env.push_back(const_cast<char*>(e.c_str()));
  env.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(in[0], 0);
    ::dup2(out[1], 1);
    if (log_fd >= 0) ::dup2(log_fd, 2);
    ::execve(args[0], args.data(), env.data());
    ::_exit(127);
  }
  ::close(in[0]);
  ::close(out[1]);
  if (pid < 0) {
    ::close(in[1]);
    ::close(out[0]);
    return false;
  }
  w = Worker{};
  w.pid = pid;
  w.to = in[1];
  w.from = out[0];
  return true;
}

// Closes the pipes and collects the process; its wait status.
int reap(Worker& w, bool kill_first) {
  if (kill_first) ::kill(w.pid, SIGKILL);
  ::close(w.to);
  ::close(w.from);
  int status = 0;
  while (::waitpid(w.pid, &status, 0) < 0 && errno == EINTR) {
  }
  w.pid = -1;
  return status;
}

std::string death(int status) {
  if (WIFSIGNALED(status))
    return fmt::format("worker killed by signal {} ({})", WTERMSIG(status),
                       ::strsignal(WTERMSIG(status)));
  return fmt::format("worker exited with status {} before answering", WEXITSTATUS(status));
}

bool write_all(int fd, const std::string& s) {
  size_t done = 0;
  while (done < s.size()) {
    ssize_t n = ::write(fd, s.data() + done, s.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

std::string file_name_of(const std::string& id) {
  std::string out;
  for (char c : id) out += std::isalnum(static_cast<unsigned char>(c)) || c == '.' ? c : '_';
  return out;
}

class Coordinator {
public:
  // `listings`: the files of the cases (a reduced program is never written over one).
  Coordinator(const std::vector<Case>& cases, const RunOptions& o,
              const std::vector<std::string>& listings)
      : cases_(cases), o_(o), listings_(listings) {}

  // Every case's last result, by id: what results.jsonl holds after the run (the last line of
  // each id wins), kept as recorded instead of read back and parsed again at the end (on a
  // check-only run that was a sixth of the coordinator's time).
  std::vector<CaseResult> take_results() {
    std::vector<CaseResult> out;
    out.reserve(results_.size());
    for (auto& [id, r] : results_) out.push_back(std::move(r));
    return out;
  }

  ir::Status run() {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(o_.out_dir, ec);
    jsonl_path_ = (fs::path(o_.out_dir) / "results.jsonl").string();
    // The times of the run this folder holds, if any, before the file is replaced.
    std::map<std::string, uint64_t> costs = o_.costs;
    if (costs.empty() && fs::is_regular_file(jsonl_path_, ec))
      if (auto earlier = read_costs(jsonl_path_)) costs = std::move(*earlier);
    std::set<std::string> done;
    if (o_.resume)
      for (CaseResult& r : read_results_jsonl(jsonl_path_)) {
        done.insert(r.id);
        results_[r.id] = std::move(r);
      }
    jsonl_ = ::open(jsonl_path_.c_str(),
                    O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | (o_.resume ? 0 : O_TRUNC), 0644);
    if (jsonl_ < 0)
      return ir::fail(jsonl_path_, "io", fmt::format("{}: {}", jsonl_path_, std::strerror(errno)));
    const std::string log = (fs::path(o_.out_dir) / "workers.log").string();
    log_ = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    std::vector<size_t> to_run;
    for (size_t i = 0; i < cases_.size(); ++i) {
      if (done.contains(cases_[i].id)) continue;
      if (Expectations::matches(o_.expectations.skips, cases_[i].id)) {
        CaseResult r;
        r.id = cases_[i].id;
        r.verdict = Verdict::Skip;
        r.note = "--skips";
        record(cases_[i], r);
        continue;
      }
      to_run.push_back(i);
    }
    flush_results(); // the skipped ones
    // Costliest first: on a corpus where a few cases take a tenth of the time each, the last
    // one handed out decides when the run ends.
    to_run = costliest_first(cases_, std::move(to_run), costs);
    std::deque<size_t> pending(to_run.begin(), to_run.end());
    total_ = pending.size();
    t0_ = Clock::now();
    std::signal(SIGPIPE, SIG_IGN);
    ir::Status s = drain(pending, 1);
    std::deque<size_t> again(rerun_.begin(), rerun_.end());
    if (s && o_.rerun && !again.empty()) s = drain(again, 2);
    for (Worker& w : workers_)
      if (w.pid > 0) reap(w, false);
    if (o_.progress) std::fputs("\n", stderr);
    flush_results();
    ::close(jsonl_);
    if (log_ >= 0) ::close(log_);
    return s;
  }

private:
  ir::Status drain(std::deque<size_t>& pending, unsigned attempt) {
    attempt_ = attempt;
    pending_ = &pending;
    const unsigned jobs = std::max(1u, std::min<unsigned>(o_.jobs, pending.size()));
    workers_.resize(std::max<size_t>(workers_.size(), jobs));
    for (;;) {
      size_t busy = 0;
      for (size_t k = 0; k < jobs; ++k) {
        Worker& w = workers_[k];
        // The lines of this round go out in one write: on a check-only run a round hands a
        // worker up to kCasesAhead cases, and a write each was a system call a case.
        std::string lines;
        while (w.jobs.size() < 1 + cases_ahead() && !pending.empty()) {
          const std::string line = case_json(cases_[pending.front()]).dump() + "\n";
          // The cases written ahead must fit the pipe's buffer together: a busy (or hung)
          // worker reads nothing, and a longer write would block the coordinator and its
          // timeouts. The front case's line may be any length: its worker is reading it.
          if (!w.jobs.empty() && bytes_ahead(w) + line.size() > kBytesAhead) break;
          if (w.pid < 0 && !spawn(w, o_.worker_argv, log_))
            return ir::fail("worker", "io", "cannot start a worker process");
          if (w.jobs.empty()) w.started = Clock::now();
          w.jobs.push_back(pending.front());
          w.line_bytes.push_back(line.size());
          pending.pop_front();
          lines += line;
        }
        if (!lines.empty() && !write_all(w.to, lines)) finish_dead(w, reap(w, true));
        if (!w.jobs.empty()) ++busy;
      }
      if (busy == 0 && pending.empty()) return ir::ok_status();
      wait_for(jobs);
    }
  }

  void wait_for(unsigned jobs) {
    std::vector<pollfd> fds;
    std::vector<size_t> which;
    int timeout_ms = 500; // the progress line is redrawn at least this often
    const auto now = Clock::now();
    for (size_t k = 0; k < jobs; ++k) {
      Worker& w = workers_[k];
      if (w.jobs.empty()) continue;
      fds.push_back({w.from, POLLIN, 0});
      which.push_back(k);
      const double left_ms =
          o_.timeout_s * 1000 - std::chrono::duration<double, std::milli>(now - w.started).count();
      timeout_ms = std::min(timeout_ms, std::max(0, static_cast<int>(left_ms) + 1));
    }
    ::poll(fds.data(), fds.size(), timeout_ms);
    for (size_t i = 0; i < fds.size(); ++i) {
      Worker& w = workers_[which[i]];
      if (fds[i].revents) read_from(w);
    }
    for (size_t k = 0; k < jobs; ++k) {
      Worker& w = workers_[k];
      if (w.jobs.empty()) continue;
      if (std::chrono::duration<double>(Clock::now() - w.started).count() <= o_.timeout_s) continue;
      reap(w, true);
      CaseResult r =
          lost(w, Verdict::Timeout,
               fmt::format("no answer within --timeout {} s; worker killed", o_.timeout_s));
      record(cases_[w.jobs.front()], r);
      pop_job(w);
      give_back(w);
    }
    flush_results();
    progress();
  }

  // The results recorded since the last flush, in one write: those of one wake of the
  // coordinator (a read can bring several answers), so a kill of the whole run loses none
  // that a worker had answered before the wake ended.
  void flush_results() {
    if (jsonl_lines_.empty()) return;
    write_all(jsonl_, jsonl_lines_);
    jsonl_lines_.clear();
  }

  void read_from(Worker& w) {
    char chunk[65536];
    const ssize_t n = ::read(w.from, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) return;
    if (n <= 0) {
      finish_dead(w, reap(w, false));
      return;
    }
    w.buffer.append(chunk, static_cast<size_t>(n));
    // Every whole line: one read may bring the answers to both cases in flight.
    size_t nl;
    size_t from = 0;
    while (!w.jobs.empty() && (nl = w.buffer.find('\n', from)) != std::string::npos) {
      std::string line = w.buffer.substr(from, nl - from);
      from = nl + 1;
      std::optional<CaseResult> r = from_json(nlohmann::json::parse(line, nullptr, false));
      if (!r) {
        finish_dead(w, reap(w, true));
        return;
      }
      // The first answer's time, then an average over the last few dozen (an exponential
      // one).
      mean_case_ms_ = answers_++ == 0 ? r->ms : mean_case_ms_ + (r->ms - mean_case_ms_) / 32;
      record(cases_[w.jobs.front()], std::move(*r), std::move(line));
      pop_job(w);
      w.started = Clock::now(); // the next case, if any, starts now
    }
    w.buffer.erase(0, from);
  }

  CaseResult lost(const Worker& w, Verdict v, std::string note) {
    CaseResult r;
    r.id = cases_[w.jobs.front()].id;
    r.verdict = v;
    r.note = std::move(note);
    r.ms = std::chrono::duration<double, std::milli>(Clock::now() - w.started).count();
    return r;
  }

  // The front case of a worker that died is its verdict; the cases written after it go back
  // to the head of the queue, in order, for the worker started next.
  void finish_dead(Worker& w, int status) {
    if (w.jobs.empty()) return;
    record(cases_[w.jobs.front()], lost(w, Verdict::Crash, death(status)));
    pop_job(w);
    give_back(w);
  }
  void give_back(Worker& w) {
    pending_->insert(pending_->begin(), w.jobs.begin(), w.jobs.end());
    w.jobs.clear();
    w.line_bytes.clear();
    w.buffer.clear();
  }

  // `answered`: the worker's line, when the result is one. It goes to results.jsonl as it
  // came, with the repro command added, unless the coordinator changed more of the result
  // (a rerun's attempt, a flake, a reduced program): on a check-only run, serialising each
  // result again was the larger part of the coordinator's time a case.
  void record(const Case& c, CaseResult r, std::string answered = {}) {
    const unsigned answered_attempt = r.attempt;
    r.attempt = attempt_;
    if (o_.repro) r.repro = o_.repro(c);
    const bool unexpected = is_failure(r.verdict) && !o_.expectations.baseline.contains(r.id) &&
                            !Expectations::matches(o_.expectations.flakes, r.id);
    if (attempt_ == 1 && unexpected) rerun_.push_back(index_of(c));
    if (attempt_ == 2 && !is_failure(r.verdict)) r.flaky = true;
    // (A line that names "repro" at all, even empty, would get the key twice.)
    const bool as_answered = !answered.empty() && answered.back() == '}' &&
                             answered_attempt == attempt_ && !r.flaky && r.reduced.empty() &&
                             answered.find("\"repro\"") == std::string::npos;
    if (!r.reduced.empty()) {
      namespace fs = std::filesystem;
      std::error_code ec;
      fs::create_directories(fs::path(o_.out_dir) / "reduced", ec);
      const std::string path =
          (fs::path(o_.out_dir) / "reduced" / (file_name_of(r.id) + ".asm")).string();
      if (io::refuse_if_input(path, listings_) && io::write_output(path, r.reduced))
        r.repro += fmt::format(" (reduced program: tierlift test {})", path);
    }
    if (as_answered && !r.repro.empty()) {
      answered.pop_back();
      answered += ",\"repro\":" + nlohmann::json(r.repro).dump() + "}";
    }
    jsonl_lines_ += as_answered ? answered : to_json(r).dump();
    jsonl_lines_ += '\n';
    if (attempt_ == 1) {
      ++finished_;
      if (is_failure(r.verdict)) ++failures_;
    }
    results_[r.id] = std::move(r);
  }

  // Cases to write after the running one (kAheadMs).
  size_t cases_ahead() const {
    if (!(mean_case_ms_ > 0)) return kCasesAhead;
    return std::clamp<size_t>(static_cast<size_t>(kAheadMs / mean_case_ms_), 1, kCasesAhead);
  }

  size_t index_of(const Case& c) const { return static_cast<size_t>(&c - cases_.data()); }

  void progress() {
    if (!o_.progress || attempt_ != 1) return;
    const double s = std::chrono::duration<double>(Clock::now() - t0_).count();
    const double rate = s > 0 ? finished_ / s : 0;
    const double left = rate > 0 ? (total_ - std::min(total_, finished_)) / rate : 0;
    std::fprintf(stderr, "\r[%zu/%zu] %.1f cases/s, %zu failures, %d:%02d left   ", finished_,
                 total_, rate, failures_, static_cast<int>(left) / 60, static_cast<int>(left) % 60);
  }

  const std::vector<Case>& cases_;
  const RunOptions& o_;
  const std::vector<std::string>& listings_;
  std::vector<Worker> workers_;
  std::deque<size_t>* pending_ = nullptr; // drain's queue: where a dead worker's cases go back
  std::vector<size_t> rerun_;
  std::map<std::string, CaseResult> results_;
  std::string jsonl_path_;
  std::string jsonl_lines_; // recorded, not yet written (flush_results)
  int jsonl_ = -1, log_ = -1;
  unsigned attempt_ = 1;
  size_t total_ = 0, finished_ = 0, failures_ = 0;
  Clock::time_point t0_;
  // What a case takes in a worker, on average; until answers come, as much as a slow case
  // (one written ahead).
  double mean_case_ms_ = kAheadMs;
  size_t answers_ = 0;
};

} // namespace

ir::Result<std::vector<CaseResult>> run_corpus(const std::vector<Case>& cases,
                                               const RunOptions& options) {
  std::vector<std::string> paths;
  for (const Case& c : cases)
    if (!c.path.empty()) paths.push_back(c.path);
  if (ir::Status s = refuse_foreign_folder(options.out_dir); !s) return s.failure();
  if (ir::Status s = refuse_outputs_among_inputs(options.out_dir, paths); !s) return s.failure();
  Coordinator coordinator(cases, options, paths);
  if (ir::Status s = coordinator.run(); !s) return s.failure();
  std::vector<CaseResult> results = coordinator.take_results();
  if (ir::Status s = write_reports(options.out_dir, results, options.expectations); !s)
    return s.failure();
  return results;
}

std::vector<std::string> worker_environment(char* const* parent) {
  std::vector<std::string> out;
  bool chosen = false;
  for (char* const* e = parent; e && *e; ++e) {
    out.emplace_back(*e);
    chosen = chosen || out.back().starts_with("LP_NUM_THREADS=");
  }
  if (!chosen) out.emplace_back("LP_NUM_THREADS=0");
  return out;
}

} // namespace tierlift::corpus
