#include "fdh/suite/fuzz.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "fdh/check/checker.hpp"
#include "fdh/exact/point_triangle.hpp"
#include "fdh/gen/families.hpp"
#include "fdh/io/atomic_file.hpp"
#include "fdh/io/case_files.hpp"

namespace fdh::verify {
namespace fs = std::filesystem;

std::uint64_t case_seed(std::uint64_t seed, long i) {
  std::uint64_t z = seed * 0x9e3779b97f4a7c15ull + std::uint64_t(i) + 0x632be59bd9b4e019ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

namespace {

// A chunk's done-marker: `<disagreements> <case file>...`, paths relative to the out folder.
struct ChunkResult {
  long disagreements = 0;
  std::vector<std::string> files;
};

bool read_marker(const fs::path& p, ChunkResult& r) {
  std::ifstream in(p);
  if (!(in >> r.disagreements)) return false;
  for (std::string f; in >> f;) r.files.push_back(f);
  return true;
}

// A killed run can leave `<file>.tmp.<pid>.<n>` behind: never a case, always safe to remove.
void remove_stale_temporaries(const fs::path& dir) {
  std::vector<fs::path> stale;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file() && e.path().filename().string().find(".tmp.") != std::string::npos)
      stale.push_back(e.path());
  std::error_code ec;
  for (const fs::path& p : stale) fs::remove(p, ec);
}

std::string describe(const Method& m, bool said, const exact::PointTriangleContact& e) {
  std::string s = m.name + " says " + (said ? "hit" : "no") + ", exact says ";
  s += e.hit ? std::string("hit (") + exact::to_string(e.kind) + " at t = " + e.time + ")" : "no";
  return s;
}

// Fuzzing checks static vertex-face queries: only a static family will do.
const Family& static_family(const std::string& name) {
  const Family* f = family_named(name);
  if (!f || f->moving) throw std::invalid_argument("unknown family '" + name + "'");
  return *f;
}

struct Run {
  const FuzzOptions& opt;
  Method method = select_methods({opt.method}).front();
  const Family& generator = static_family(opt.family);
  std::string family = generator.name;
  fs::path out{opt.out_dir};
  fs::path case_dir = out / method.name / family;
  fs::path marker_dir = out / ".fuzz" /
                        (method.name + "." + family + ".seed" + std::to_string(opt.seed) +
                         ".count" + std::to_string(opt.count) + ".shard" +
                         std::to_string(opt.shard + 1) + "of" + std::to_string(opt.shards));
  long first, last, chunk, chunks;

  explicit Run(const FuzzOptions& o) : opt(o) {
    first = opt.count * opt.shard / opt.shards;
    last = opt.count * (opt.shard + 1) / opt.shards;
    chunk = std::max(1, opt.chunk);
    chunks = (last - first + chunk - 1) / chunk;
  }

  fs::path marker(long c) const { return marker_dir / ("chunk-" + std::to_string(c)); }
  long chunk_size(long c) const { return std::min(chunk, last - (first + c * chunk)); }

  bool fails(const Generated& g) const { return !check(method, g.query).agree(); }

  ChunkResult run_chunk(long c) const {
    ChunkResult r;
    const long begin = first + c * chunk, end = begin + chunk_size(c);
    for (long i = begin; i < end; ++i) {
      std::optional<Generated> g = shrunk_failure(generator, case_seed(opt.seed, i),
                                                  [this](const Generated& x) { return fails(x); });
      if (!g) continue;
      ++r.disagreements;
      Query& q = g->query;
      const exact::PointTriangleContact e =
          exact::point_triangle(q.b0(), q.b1(), q.d(), q.e(), q.f());
      q.truth = e.hit;
      q.id = method.name + "/" + family;
      const fs::path file = case_dir / (case_hash(q) + ".vf");
      write_file_atomically(
          file.string(),
          // The text depends on the case alone (not on which i found it first), so that any
          // number of workers and shards write identical files.
          case_file_text(q, {describe(method, method.hit(q), e) + ".",
                             "Shrunk by fdhcert fuzz from family " + family + "."}));
      r.files.push_back(fs::relative(file, out).string());
    }
    std::ostringstream os;
    os << r.disagreements;
    for (const std::string& f : r.files) os << ' ' << f;
    os << '\n';
    write_file_atomically(marker(c).string(), os.str());  // only after every case is on disk
    return r;
  }

  // Worker w of n takes chunks w, w + n, ...; finished chunks are skipped. Each chunk it
  // finishes is reported on `progress_fd` as {cases, disagreements} (16 bytes: one atomic
  // pipe write), so the parent's progress line reads no files.
  void work(int w, int n, int progress_fd) const {
    for (long c = w; c < chunks; c += n) {
      if (fs::exists(marker(c))) continue;
      const long report[2] = {chunk_size(c), run_chunk(c).disagreements};
      // Progress is cosmetic: a full or closed pipe changes nothing, so the result is unused.
      const ssize_t written = ::write(progress_fd, report, sizeof report);
      (void)written;
    }
  }
};

}  // namespace

namespace {

// Worker processes 0 .. n-1, each reporting (cases, found) per chunk on the pipe.
std::vector<pid_t> start_workers(const Run& run, int workers, int progress_fd) {
  std::vector<pid_t> children;
  std::fflush(nullptr);
  for (int w = 0; w < workers; ++w) {
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("fuzz: cannot start a worker process");
    if (pid == 0) {
      ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // a killed run leaves no worker behind
      int status = 0;
      try {
        run.work(w, workers, progress_fd);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "fdhcert: fuzz worker: %s\n", e.what());
        status = 3;
      }
      std::fflush(nullptr);
      ::_exit(status);
    }
    children.push_back(pid);
  }
  return children;
}

// Waits for every worker, showing progress; false if one failed.
bool wait_for_workers(const Run& run, std::size_t alive, int progress_fd, long done, long found,
                      const FuzzSummary& sum, std::ostream* progress) {
  const auto start = std::chrono::steady_clock::now();
  bool ok = true;
  while (alive > 0) {
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, WNOHANG);
    if (pid > 0) {
      --alive;
      ok &= WIFEXITED(status) && WEXITSTATUS(status) == 0;
      continue;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    for (long report[2]; ::read(progress_fd, report, sizeof report) == sizeof report;)
      done += report[0], found += report[1];
    if (!progress) continue;
    const double secs =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char line[200];
    std::snprintf(line, sizeof line, "\rfuzz %s on %s: %ld/%ld cases, %.0f cases/s, %ld found ",
                  run.method.name.c_str(), run.family.c_str(), done, sum.last - sum.first,
                  double(done - sum.resumed) / std::max(secs, 1e-9), found);
    *progress << line << std::flush;
  }
  if (progress) *progress << '\n';
  return ok;
}

}  // namespace

FuzzSummary run_fuzz(const FuzzOptions& opt, std::ostream& progress_stream) {
  if (opt.shards < 1 || opt.shard < 0 || opt.shard >= opt.shards)
    throw std::invalid_argument("--shard I/N needs 1 <= I <= N");
  if (opt.count < 0) throw std::invalid_argument("--count must not be negative");
  const Run run(opt);  // throws std::invalid_argument for an unknown method or family
  fs::create_directories(run.case_dir);
  fs::create_directories(run.marker_dir);
  remove_stale_temporaries(run.out);

  FuzzSummary sum;
  sum.first = run.first;
  sum.last = run.last;
  long found = 0;  // for the progress line
  for (long c = 0; c < run.chunks; ++c) {
    ChunkResult r;
    if (read_marker(run.marker(c), r)) sum.resumed += run.chunk_size(c), found += r.disagreements;
  }

  const int workers = int(std::min<long>(
      std::max(1, opt.threads > 0 ? opt.threads : int(std::thread::hardware_concurrency())),
      std::max(1L, run.chunks)));
  int pipe_fd[2];
  if (::pipe(pipe_fd) != 0) throw std::runtime_error("fuzz: cannot make a pipe");
  ::fcntl(pipe_fd[0], F_SETFL, O_NONBLOCK);
  ::fcntl(pipe_fd[1], F_SETFL, O_NONBLOCK);
  const std::vector<pid_t> children = start_workers(run, workers, pipe_fd[1]);
  ::close(pipe_fd[1]);
  const bool ok = wait_for_workers(run, children.size(), pipe_fd[0], sum.resumed, found, sum,
                                   opt.progress ? &progress_stream : nullptr);
  ::close(pipe_fd[0]);
  if (!ok) throw std::runtime_error("fuzz: a worker failed (see above)");

  for (long c = 0; c < run.chunks; ++c) {
    ChunkResult r;
    if (!read_marker(run.marker(c), r))
      throw std::runtime_error("fuzz: chunk " + std::to_string(c) + " did not finish");
    sum.disagreements += r.disagreements;
    for (const std::string& f : r.files) sum.distinct.insert((run.out / f).string());
  }
  sum.cases = sum.last - sum.first;
  return sum;
}

}  // namespace fdh::verify
