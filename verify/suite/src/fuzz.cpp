#include "fdh/suite/fuzz.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "fdh/check/checker.hpp"
#include "fdh/gen/families.hpp"
#include "fdh/io/case_files.hpp"
#include "fdh/io/record_scope.hpp"
#include "fuzz_target.hpp"

namespace fdh::verify {
namespace fs = std::filesystem;

std::uint64_t case_seed(std::uint64_t seed, long i) {
  std::uint64_t z = seed * 0x9e3779b97f4a7c15ull + std::uint64_t(i) + 0x632be59bd9b4e019ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

long shard_begin(long count, int shard, int shards) {
  if (count < 0 || shards < 1 || shard < 0 || shard > shards)
    throw std::invalid_argument("shard_begin needs count >= 0 and 0 <= shard <= shards");
  // count = q·shards + r, so count·shard/shards = q·shard + r·shard/shards exactly; q·shard is
  // at most count and r·shard < shards² < 2^62: no product overflows.
  const long q = count / shards, r = count % shards;
  return q * shard + r * shard / shards;
}

// Everything below lives in fuzz_run: the suite is one unity translation unit.
namespace {
namespace fuzz_run {

[[noreturn]] void fail(const fs::path& p, const std::string& what, int err) {
  throw std::runtime_error(p.string() + ": " + what + ": " + std::strerror(err));
}

// Writes all of `text` to `fd`; false (errno set) on failure.
bool write_all(int fd, const std::string& text) {
  for (std::size_t done = 0; done < text.size();) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = EIO;
      return false;
    }
    done += std::size_t(n);
  }
  return true;
}

// Makes `dir` (and its parents) a folder, or says why not.
void make_folder(const fs::path& dir) {
  std::error_code ec;
  if (fs::is_directory(dir, ec)) return;
  if (fs::exists(dir, ec)) throw std::runtime_error(dir.string() + ": exists and is not a folder");
  fs::create_directories(dir, ec);
  if (ec) throw std::runtime_error(dir.string() + ": cannot create the folder: " + ec.message());
}

// Flushes a folder's entries (the renames into it) to the disk.
void sync_folder(const fs::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) fail(dir, "cannot open the folder", errno);
  const bool ok = ::fsync(fd) == 0 || errno == EINVAL;  // some file systems cannot sync folders
  const int err = errno;
  ::close(fd);
  if (!ok) fail(dir, "cannot sync the folder", err);
}

// Whether `file` is a regular file holding exactly `text`.
bool holds(const fs::path& file, const std::string& text) {
  struct stat st;
  if (::lstat(file.c_str(), &st) != 0 || !S_ISREG(st.st_mode) ||
      st.st_size != static_cast<off_t>(text.size()))
    return false;
  std::ifstream in(file, std::ios::binary);
  std::string got(text.size(), '\0');
  return in.read(got.data(), std::streamsize(got.size())) && got == text;
}

// OUT/.fuzz, held for one run: the lock, the temporaries and the runs' markers.
class Workspace {
 public:
  Workspace(const fs::path& out, double lock_wait_seconds)
      : out_(out), meta_(out / ".fuzz"), tmp_(meta_ / "tmp") {
    make_folder(out_);
    make_folder(meta_);
    try {
      lock(lock_wait_seconds);
      make_folder(tmp_);
      // Emptied by clear_stale_temporaries: it must be the folder itself, never a link to
      // someone else's.
      std::error_code ec;
      if (!fs::is_directory(fs::symlink_status(tmp_, ec)))
        throw std::runtime_error(tmp_.string() + ": is not a folder (fuzz's temporaries go there)");
    } catch (...) {
      if (lock_fd_ >= 0) ::close(lock_fd_);
      throw;
    }
  }

  // Under the lock no live run owns a temporary: whatever is in tmp/ is a killed run's. Called
  // once the run knows it will go on, so that a run that refuses changes nothing.
  void clear_stale_temporaries() const {
    std::error_code ec;
    std::vector<fs::path> stale;
    for (fs::directory_iterator it(tmp_, ec), end; !ec && it != end; it.increment(ec))
      stale.push_back(it->path());
    for (const fs::path& p : stale)
      if (!ec) fs::remove_all(p, ec);
    if (ec) throw std::runtime_error(tmp_.string() + ": cannot clean up: " + ec.message());
  }
  ~Workspace() {
    if (lock_fd_ >= 0) ::close(lock_fd_);
  }
  Workspace(const Workspace&) = delete;
  Workspace& operator=(const Workspace&) = delete;

  const fs::path& meta() const { return meta_; }

  // `text` into `target` whole: a temporary in tmp/, synced, then renamed over `target`, which
  // must be absent or a regular file.
  void write_whole(const fs::path& target, const std::string& text) const {
    static std::atomic<unsigned long> serial{0};
    const fs::path tmp = tmp_ / (std::to_string(::getpid()) + "." + std::to_string(serial++));
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) fail(target, "cannot write the file", errno);
    bool ok = write_all(fd, text) && ::fsync(fd) == 0;
    int err = errno;
    if (::close(fd) != 0 && ok) ok = false, err = errno;
    struct stat st;
    if (ok && ::lstat(target.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
      ::unlink(tmp.c_str());
      throw std::runtime_error(target.string() + ": exists and is not a regular file");
    }
    if (ok && ::rename(tmp.c_str(), target.c_str()) != 0) ok = false, err = errno;
    if (!ok) {
      ::unlink(tmp.c_str());
      fail(target, "cannot write the file", err);
    }
  }

 private:
  // An exclusive flock on .fuzz/lock. The workers inherit it, so it is free only once every
  // process of a run has ended; a killed run's workers die with it, hence the short wait.
  void lock(double wait_seconds) {
    const fs::path path = meta_ / "lock";
    lock_fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0666);
    if (lock_fd_ < 0) fail(path, "cannot open the lock file", errno);
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::duration<double>(wait_seconds);
    while (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
      if (errno == EINTR) continue;
      if (errno != EWOULDBLOCK) fail(path, "cannot lock", errno);
      if (std::chrono::steady_clock::now() >= deadline)
        throw FuzzRefused("another fuzz run is using " + out_.string() + " (it holds " +
                          path.string() + "): wait for it to end, or give another --out");
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  }

  fs::path out_, meta_, tmp_;
  int lock_fd_ = -1;
};

// The parameters that fix a run's cases (--chunk and --threads do not).
struct Params {
  std::string method, family;
  std::uint64_t seed = 0;
  long count = 0;
  int shard = 0, shards = 1;  // shard 0-based
  bool metamorphic = false;   // recorded only when set: older manifests stay valid

  bool operator==(const Params& o) const {
    return method == o.method && family == o.family && seed == o.seed && count == o.count &&
           shard == o.shard && shards == o.shards && metamorphic == o.metamorphic;
  }
  std::string folder_name() const {
    return (metamorphic ? "metamorphic." : "") + method + "." + family + ".seed" +
           std::to_string(seed) + ".count" + std::to_string(count) + ".shard" +
           std::to_string(shard + 1) + "of" + std::to_string(shards);
  }
  std::string options() const {
    return (metamorphic ? "--metamorphic " : "") + std::string("--method ") + method +
           " --family " + family + " --seed " + std::to_string(seed) + " --count " +
           std::to_string(count) + " --shard " + std::to_string(shard + 1) + "/" +
           std::to_string(shards);
  }
  std::string manifest() const {
    return "fdhcert fuzz run\nmethod " + method + "\nfamily " + family + "\nseed " +
           std::to_string(seed) + "\ncount " + std::to_string(count) + "\nshard " +
           std::to_string(shard + 1) + "/" + std::to_string(shards) + "\n" +
           (metamorphic ? "mode metamorphic\n" : "");
  }
  long first() const { return shard_begin(count, shard, shards); }
  long last() const { return shard_begin(count, shard + 1, shards); }
};

// A manifest's parameters; nullopt for a missing or unreadable one.
std::optional<Params> read_manifest(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  if (!std::getline(in, line) || line != "fdhcert fuzz run") return std::nullopt;
  Params p;
  bool m = false, f = false, s = false, c = false, sh = false;
  for (std::string key; in >> key;) {
    if (key == "method") {
      m = bool(in >> p.method);
    } else if (key == "family") {
      f = bool(in >> p.family);
    } else if (key == "seed") {
      s = bool(in >> p.seed);
    } else if (key == "count") {
      c = bool(in >> p.count);
    } else if (key == "shard") {
      char slash = 0;
      sh = bool(in >> p.shard >> slash >> p.shards) && slash == '/';
      --p.shard;
    } else if (key == "mode") {
      std::string mode;
      if (!(in >> mode) || mode != "metamorphic") return std::nullopt;
      p.metamorphic = true;
    } else {
      return std::nullopt;
    }
  }
  if (!(m && f && s && c && sh) || p.count < 0 || p.shards < 1 || p.shard < 0 ||
      p.shard >= p.shards)
    return std::nullopt;
  return p;
}

struct Range {
  long begin = 0, end = 0;
};

// A done-marker: `<disagreements> <case file>...`, paths relative to the out folder.
struct Marker {
  Range cases;
  fs::path file;
};

std::string marker_name(Range r) {
  return "cases-" + std::to_string(r.begin) + "-" + std::to_string(r.end);
}

std::optional<Range> parse_marker_name(const std::string& name) {
  Range r;
  char dash = 0;
  std::istringstream in(name.rfind("cases-", 0) == 0 ? name.substr(6) : std::string());
  if (!(in >> r.begin >> dash >> r.end) || dash != '-' || in.peek() != EOF) return std::nullopt;
  if (r.begin < 0 || r.end <= r.begin || name != marker_name(r)) return std::nullopt;
  return r;
}

// The markers of a run folder that cover [first, last) without overlapping (sorted), and the
// gaps between them: the cases still to run.
struct Progress {
  std::vector<Marker> done;
  std::vector<Range> todo;
  long done_cases() const {
    long n = 0;
    for (const Marker& m : done) n += m.cases.end - m.cases.begin;
    return n;
  }
};

Progress progress_of(const fs::path& run_dir, long first, long last) {
  std::vector<Marker> all;
  std::error_code ec;
  for (fs::directory_iterator it(run_dir, ec), end; !ec && it != end; it.increment(ec))
    if (const std::optional<Range> r = parse_marker_name(it->path().filename().string()))
      if (r->begin >= first && r->end <= last) all.push_back({*r, it->path()});
  if (ec) throw std::runtime_error(run_dir.string() + ": cannot list: " + ec.message());
  std::sort(all.begin(), all.end(), [](const Marker& a, const Marker& b) {
    return a.cases.begin != b.cases.begin ? a.cases.begin < b.cases.begin
                                          : a.cases.end > b.cases.end;
  });
  // Markers never overlap (one run at a time, gaps only are run); were they to, the first wins.
  Progress p;
  long covered = first;
  for (const Marker& m : all) {
    if (m.cases.begin < covered) continue;
    if (m.cases.begin > covered) p.todo.push_back({covered, m.cases.begin});
    p.done.push_back(m);
    covered = m.cases.end;
  }
  if (covered < last) p.todo.push_back({covered, last});
  return p;
}

struct MarkerContent {
  long disagreements = 0;
  std::vector<std::string> files;
};

MarkerContent read_marker(const fs::path& p) {
  std::ifstream in(p);
  MarkerContent r;
  if (!(in >> r.disagreements)) throw std::runtime_error(p.string() + ": unreadable marker");
  for (std::string f; in >> f;) r.files.push_back(f);
  return r;
}

// Refuses to start while OUT/.fuzz holds an unfinished run other than `ours`: its cases would
// be left half done under a run that looks resumed.
void refuse_other_unfinished_runs(const fs::path& meta, const fs::path& out, const Params& ours) {
  std::error_code ec;
  for (fs::directory_iterator it(meta, ec), end; !ec && it != end; it.increment(ec)) {
    if (!it->is_directory() || it->path().filename() == "tmp") continue;
    const std::optional<Params> p = read_manifest(it->path() / "manifest");
    if (!p || *p == ours) continue;
    if (progress_of(it->path(), p->first(), p->last()).todo.empty()) continue;
    throw FuzzRefused(out.string() + " holds an unfinished fuzz run with other options (" +
                      p->options() + "): resume it with those, delete " + it->path().string() +
                      " to abandon it, or give another --out");
  }
  if (ec) throw std::runtime_error(meta.string() + ": cannot list: " + ec.message());
}

// Any family of the registry: static or moving, vertex-face or edge-edge.
const Family& any_family(const std::string& name) {
  const Family* f = family_named(name);
  if (!f) throw std::invalid_argument("unknown family '" + name + "'");
  return *f;
}

Params params_of(const FuzzOptions& opt, const Method& m, const Family& f) {
  if (opt.shards < 1 || opt.shard < 0 || opt.shard >= opt.shards)
    throw std::invalid_argument("--shard I/N needs 1 <= I <= N");
  if (opt.count < 0) throw std::invalid_argument("--count must not be negative");
  return {m.name, f.name, opt.seed, opt.count, opt.shard, opt.shards, opt.metamorphic};
}

struct Run {
  const FuzzOptions& opt;
  FuzzTarget target{select_methods({opt.method}).front(), opt.metamorphic};
  const Method& method = target.method;
  const Family& generator = any_family(opt.family);
  std::string family = generator.name;
  Params params = params_of(opt, method, generator);
  fs::path out{opt.out_dir};
  fs::path case_dir = out / target.case_folder(family);
  long first = params.first(), last = params.last();
  long chunk = std::max(1, opt.chunk);
  Workspace space;  // takes the lock: only after every option is known to be good
  fs::path run_dir = space.meta() / params.folder_name();
  std::vector<Range> todo;  // the cases no marker covered when the run started

  // Every refusal comes before anything in OUT changes.
  explicit Run(const FuzzOptions& o) : opt(o), space(out, o.lock_wait_seconds) {
    refuse_other_unfinished_runs(space.meta(), out, params);
    const fs::path manifest = run_dir / "manifest";
    const bool resumed = fs::exists(manifest);
    if (resumed) {
      const std::optional<Params> p = read_manifest(manifest);
      if (!p || !(*p == params))
        throw FuzzRefused(manifest.string() + " does not record this run (" + params.options() +
                          "): delete " + run_dir.string() + " to start it afresh");
    }
    space.clear_stale_temporaries();
    make_folder(case_dir);
    make_folder(run_dir);
    if (!resumed) {
      space.write_whole(manifest, params.manifest());  // before any case
      sync_folder(run_dir);
    }
  }

  bool fails(const Generated& g) const {
    const QueryRecord r = g.record();
    const RecordScope asking(r);  // a plug-in's crash names the family
    return target.fails(g.query);
  }

  // Runs cases [r.begin, r.end), writes their case files, then the marker; its disagreements.
  long run_chunk(Range r) const {
    long disagreements = 0;
    std::vector<std::string> files;
    for (long i = r.begin; i < r.end; ++i) {
      std::optional<Generated> g = shrunk_failure(generator, case_seed(opt.seed, i),
                                                  [this](const Generated& x) { return fails(x); });
      if (!g) continue;
      ++disagreements;
      const std::string name = case_hash(g->query) + ".vf";
      const std::string text = target.case_text(g->query, family);
      // Most disagreements shrink to a case found before: one read instead of a synced write.
      if (!holds(case_dir / name, text)) space.write_whole(case_dir / name, text);
      files.push_back(target.case_folder(family) + "/" + name);
    }
    if (!files.empty()) sync_folder(case_dir);  // the cases are on disk before their marker
    std::ostringstream os;
    os << disagreements;
    for (const std::string& f : files) os << ' ' << f;
    os << '\n';
    space.write_whole(run_dir / marker_name(r), os.str());
    return disagreements;
  }

  // The chunks of the cases to do: each gap of `todo` cut into pieces of `chunk` cases,
  // numbered in order. Worker w of n takes chunks w, w + n, ...
  long chunks() const {
    long n = 0;
    for (const Range& g : todo) n += (g.end - g.begin - 1) / chunk + 1;
    return n;
  }

  // Each chunk it finishes is reported on `progress_fd` as {cases, disagreements} (16 bytes:
  // one atomic pipe write), so the parent's progress line reads no files.
  void work(int w, int n, int progress_fd) const {
    long base = 0;  // number of the gap's first chunk
    for (const Range& g : todo) {
      const long m = (g.end - g.begin - 1) / chunk + 1;
      for (long j = ((w - base) % n + n) % n; j < m; j += n) {
        const Range r{g.begin + j * chunk, std::min(g.end, g.begin + j * chunk + chunk)};
        const long report[2] = {r.end - r.begin, run_chunk(r)};
        // Progress is cosmetic: a full or closed pipe changes nothing, so the result is unused.
        const ssize_t written = ::write(progress_fd, report, sizeof report);
        (void)written;
      }
      base += m;
    }
  }
};

// Worker processes 0 .. n-1, each reporting (cases, found) per chunk on the pipe.
std::vector<pid_t> start_workers(const Run& run, int workers, int progress_fd) {
  std::vector<pid_t> children;
  std::fflush(nullptr);
  const pid_t parent = ::getpid();
  for (int w = 0; w < workers; ++w) {
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("fuzz: cannot start a worker process");
    if (pid == 0) {
      ::prctl(PR_SET_PDEATHSIG, SIGKILL);     // a killed run leaves no worker behind
      if (::getppid() != parent) ::_exit(3);  // it died before the line above
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
bool wait_for_workers(const Run& run, std::vector<pid_t> children, int progress_fd, long done,
                      long found, const FuzzSummary& sum, std::ostream* progress) {
  const auto start = std::chrono::steady_clock::now();
  bool ok = true;
  while (!children.empty()) {
    for (std::size_t k = 0; k < children.size();) {
      int status = 0;
      const pid_t pid = ::waitpid(children[k], &status, WNOHANG);
      if (pid == children[k] || (pid < 0 && errno != EINTR)) {
        ok &= pid > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
        children.erase(children.begin() + long(k));
      } else {
        ++k;
      }
    }
    for (long report[2]; ::read(progress_fd, report, sizeof report) == sizeof report;)
      done += report[0], found += report[1];
    if (children.empty()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
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

}  // namespace fuzz_run
}  // namespace

FuzzSummary run_fuzz(const FuzzOptions& opt, std::ostream& progress_stream) {
  using namespace fuzz_run;
  if (opt.out_dir.empty()) throw std::invalid_argument("fuzz needs an output folder");
  Run run(opt);  // throws as run_fuzz says; holds OUT's lock until it returns

  FuzzSummary sum;
  sum.first = run.first;
  sum.last = run.last;
  const Progress before = progress_of(run.run_dir, run.first, run.last);
  run.todo = before.todo;
  sum.resumed = before.done_cases();
  long found = 0;  // for the progress line
  for (const Marker& m : before.done) found += read_marker(m.file).disagreements;

  const long chunks = run.chunks();
  if (chunks > 0) {
    const int workers = int(std::min<long>(
        std::max(1, opt.threads > 0 ? opt.threads : int(std::thread::hardware_concurrency())),
        chunks));
    int pipe_fd[2];
    if (::pipe2(pipe_fd, O_CLOEXEC | O_NONBLOCK) != 0)
      throw std::runtime_error("fuzz: cannot make a pipe");
    std::vector<pid_t> children;
    try {
      children = start_workers(run, workers, pipe_fd[1]);
    } catch (...) {
      ::close(pipe_fd[0]);
      ::close(pipe_fd[1]);
      throw;
    }
    ::close(pipe_fd[1]);
    const bool ok = wait_for_workers(run, children, pipe_fd[0], sum.resumed, found, sum,
                                     opt.progress ? &progress_stream : nullptr);
    ::close(pipe_fd[0]);
    if (!ok) throw std::runtime_error("fuzz: a worker failed (see above)");
  }

  const Progress after = progress_of(run.run_dir, run.first, run.last);
  if (!after.todo.empty())
    throw std::runtime_error("fuzz: cases " + std::to_string(after.todo.front().begin) + ".." +
                             std::to_string(after.todo.front().end - 1) + " did not finish");
  for (const Marker& m : after.done) {
    const MarkerContent r = read_marker(m.file);
    sum.disagreements += r.disagreements;
    for (const std::string& f : r.files) sum.distinct.insert((run.out / f).string());
  }
  sum.cases = sum.last - sum.first;
  return sum;
}

}  // namespace fdh::verify
