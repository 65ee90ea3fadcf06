#include "fdh/fuzz/fuzz.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "fdh/gen/case_seed.hpp"
#include "fdh/gen/families.hpp"
#include "fdh/io/case_files.hpp"
#include "fdh/io/record_scope.hpp"
#include "fdh/os/atomic_file.hpp"
#include "fdh/os/child_process.hpp"
#include "fdh/os/folders.hpp"
#include "fdh/os/work_folder.hpp"
#include "fuzz_params.hpp"
#include "fuzz_target.hpp"

namespace fdh::verify {
namespace fs = std::filesystem;

long shard_begin(long count, int shard, int shards) {
  if (count < 0 || shards < 1 || shard < 0 || shard > shards)
    throw std::invalid_argument("shard_begin needs count >= 0 and 0 <= shard <= shards");
  // count = q·shards + r, so count·shard/shards = q·shard + r·shard/shards exactly; q·shard is
  // at most count and r·shard < shards² < 2^62: no product overflows.
  const long q = count / shards, r = count % shards;
  return q * shard + r * shard / shards;
}

namespace {

// A done-marker's content: `<disagreements> <case file>...`, paths relative to the out folder.
struct MarkerContent {
  long disagreements = 0;
  std::vector<std::string> files;
};

MarkerContent read_marker(const std::string& p) {
  std::ifstream in(p);
  MarkerContent r;
  if (!(in >> r.disagreements)) throw std::runtime_error(p + ": unreadable marker");
  for (std::string f; in >> f;) r.files.push_back(f);
  return r;
}

// A run folder's mark of a run that --budget stopped, cleanly (its cases marked, its outputs
// whole): paused, not broken, so that other runs may start beside it (issue 34).
constexpr const char* kPausedMark = "/paused-by-budget";

// Refuses to start while OUT/.fuzz holds an unfinished run other than `ours` that did not stop
// cleanly (killed, or a worker failed): its cases would be left half done under a run that looks
// resumed. A run paused by --budget is resumed by its own command, whatever ran between.
void refuse_other_unfinished_runs(const std::string& meta, const fs::path& out,
                                  const FuzzParams& ours) {
  for (const std::string& dir : run_folders(meta, "tmp")) {
    refuse_link(dir + "/manifest", "a run's manifest");
    const std::optional<FuzzParams> p = FuzzParams::read(dir + "/manifest");
    if (!p || *p == ours || fs::exists(dir + kPausedMark)) continue;
    if (coverage_of(dir, p->first(), p->last()).todo.empty()) continue;
    throw FuzzRefused(out.string() + " holds an unfinished fuzz run with other options (" +
                      p->options() + "): resume it with those, delete " + dir +
                      " to abandon it, or give another --out");
  }
}

// Any family of the registry: static or moving, vertex-face or edge-edge.
const Family& any_family(const std::string& name) {
  const Family* f = family_named(name);
  if (!f) throw std::invalid_argument("unknown family '" + name + "'");
  return *f;
}

FuzzParams params_of(const FuzzOptions& opt, const Method& m, const Family& f) {
  if (opt.shards < 1 || opt.shard < 0 || opt.shard >= opt.shards)
    throw std::invalid_argument("--shard I/N needs 1 <= I <= N");
  if (opt.count < 0) throw std::invalid_argument("--count must not be negative");
  if (opt.toi && opt.metamorphic)
    throw std::invalid_argument("--toi and --metamorphic look for different things: give one");
  if (opt.toi && !f.moving)
    throw std::invalid_argument("--toi needs a moving family, not '" + f.name + "'");
  if (opt.toi &&
      !std::all_of(m.toi.begin(), m.toi.end(), [](const QueryToi& t) { return bool(t); }))
    throw std::invalid_argument("method '" + m.name + "' gives no time of impact");
  if (opt.toi && !(opt.toi_width > 0 && opt.toi_width <= 1 && opt.toi_tolerance >= 0))
    throw std::invalid_argument("--toi needs 0 < --width <= 1 and --toi-tolerance >= 0");
  if (!(opt.min_distance >= 0 && std::isfinite(opt.min_distance)))
    throw std::invalid_argument("--min-distance needs a finite D >= 0");
  FuzzParams p{m.name, f.name, opt.seed, opt.count, opt.shard, opt.shards, opt.metamorphic};
  if (opt.toi) p.toi = true, p.width = opt.toi_width, p.tolerance = opt.toi_tolerance;
  p.min_distance = opt.min_distance + 0.0;  // -0 is 0
  return p;
}

// OUT/.fuzz, locked for the run; a run that is held by another refuses.
WorkFolder take_work_folder(const fs::path& out, double wait_seconds) {
  make_folder(out.string());
  try {
    return WorkFolder((out / ".fuzz").string(), wait_seconds);
  } catch (const LockBusy&) {
    throw FuzzRefused("another fuzz run is using " + out.string() + " (it holds " +
                      (out / ".fuzz" / "lock").string() +
                      "): wait for it to end, or give another --out");
  }
}

// What a worker tells the parent of a chunk: cases run, disagreements, cases whose shrinking
// the budget stopped.
struct ChunkReport {
  long cases = 0, found = 0, shrink_cut = 0;
};

struct Run {
  const FuzzOptions& opt;
  FuzzTarget target{select_methods({opt.method}).front(), opt.metamorphic, opt.toi, opt.toi_width,
                    opt.toi_tolerance};
  const Method& method = target.method;
  const Family& generator = any_family(opt.family);
  std::string family = generator.name;
  FuzzParams params = params_of(opt, method, generator);
  fs::path out{opt.out_dir};
  fs::path case_dir = out / target.case_folder(family);
  long first = params.first(), last = params.last();
  long chunk = std::max(1, opt.chunk);
  WorkFolder space;  // takes the lock: only after every option is known to be good
  std::string run_dir = space.dir() + "/" + params.folder_name();
  std::vector<IndexRange> todo;  // the cases no marker covered when the run started

  // Every refusal comes before anything in OUT changes.
  explicit Run(const FuzzOptions& o) : opt(o), space(take_work_folder(out, o.lock_wait_seconds)) {
    refuse_other_unfinished_runs(space.dir(), out, params);
    const std::string manifest = run_dir + "/manifest";
    refuse_link(manifest, "a run's manifest");
    const bool resumed = fs::exists(manifest);
    if (resumed) {
      const std::optional<FuzzParams> p = FuzzParams::read(manifest);
      if (!p || !(*p == params))
        throw FuzzRefused(manifest + " does not record this run (" + params.options() +
                          "): delete " + run_dir + " to start it afresh");
    }
    space.clear_stale_temporaries();
    make_folder(case_dir.string());
    space.make_subfolder(params.folder_name());
    fs::remove(run_dir + kPausedMark);  // running again: a kill now leaves it unfinished
    if (!resumed) {
      space.write_whole(manifest, params.manifest().text());  // before any case
      sync_folder(run_dir);
    }
  }

  // The case at the run's δ: a case drawn, each shrink of it, and the case stored.
  Generated at_delta(Generated g) const {
    if (params.min_distance > 0) g.query.min_distance = params.min_distance;
    return g;
  }

  std::string finding(const Generated& drawn) const {
    const Generated g = at_delta(drawn);
    const QueryRecord r = g.record();
    const RecordScope asking(r);  // a plug-in's crash names the family
    return target.finding(g.query);
  }

  // Case i shrunk while the method fails on it in the same class as on the case drawn (a false
  // alarm stays a false alarm, a late time stays late, not a missed contact); nullopt where it
  // does not fail. shrunk_failure keeps the case's kind besides. Once the budget is spent no
  // simpler case is taken (`cut`): the case stays as far as it shrank.
  std::optional<Generated> shrunk_case(long i, bool& cut) const {
    std::string drawn;  // shrunk_failure asks first about the case drawn
    const std::optional<Generated> g =
        shrunk_failure(generator, case_seed(opt.seed, i), [&](const Generated& x) {
          if (!drawn.empty() && opt.budget.spent()) {
            cut = true;
            return false;
          }
          const std::string f = finding(x);
          if (drawn.empty()) drawn = f;
          return !f.empty() && f == drawn;
        });
    if (!g) return g;
    return at_delta(*g);
  }

  // Runs cases [r.begin, r.end), writes their case files, then the marker of the cases run:
  // all of them, or those before the budget ran out.
  ChunkReport run_chunk(IndexRange r) const {
    ChunkReport done;
    long& disagreements = done.found;
    std::vector<std::string> files;
    long i = r.begin;
    for (; i < r.end && !opt.budget.spent(); ++i) {
      bool cut = false;
      const std::optional<Generated> g = shrunk_case(i, cut);
      done.shrink_cut += cut;
      if (!g) continue;
      ++disagreements;
      const std::string name = target.case_name(g->query);
      const std::string text = target.case_text(g->query, family);
      const std::string path = (case_dir / name).string();
      // Most disagreements shrink to a case found before: one read instead of a synced write.
      if (!file_holds(path, text)) space.write_whole(path, text);
      files.push_back(target.case_folder(family) + "/" + name);
    }
    done.cases = i - r.begin;
    if (done.cases == 0) return done;
    if (!files.empty()) sync_folder(case_dir.string());  // the cases are on disk before the marker
    std::ostringstream os;
    os << disagreements;
    for (const std::string& f : files) os << ' ' << f;
    os << '\n';
    space.write_whole(run_dir + "/" + marker_name({r.begin, i}), os.str());
    return done;
  }

  // The chunks of the cases to do: each gap of `todo` cut into pieces of `chunk` cases,
  // numbered in order. Worker w of n takes chunks w, w + n, ...
  long chunks() const {
    long n = 0;
    for (const IndexRange& g : todo) n += (g.end - g.begin - 1) / chunk + 1;
    return n;
  }

  // Each chunk it finishes is reported on `progress_fd` as a ChunkReport (one atomic pipe
  // write), so the parent's progress reads no files. A chunk cut by the budget is the last.
  void work(int w, int n, int progress_fd) const {
    long base = 0;  // number of the gap's first chunk
    for (const IndexRange& g : todo) {
      const long m = (g.end - g.begin - 1) / chunk + 1;
      for (long j = ((w - base) % n + n) % n; j < m; j += n) {
        const IndexRange r{g.begin + j * chunk, std::min(g.end, g.begin + j * chunk + chunk)};
        const ChunkReport report = run_chunk(r);
        // Progress is cosmetic: a full or closed pipe changes nothing, so the result is unused.
        [[maybe_unused]] const ssize_t written = ::write(progress_fd, &report, sizeof report);
        if (report.cases < r.end - r.begin) return;
      }
      base += m;
    }
  }
};

// Worker processes 0 .. n-1, each reporting (cases, found) per chunk on the pipe. Processes,
// not threads: RapidCheck's generators keep global state. A killed run leaves no worker behind.
std::vector<ChildProcess> start_workers(const Run& run, int workers, int progress_fd) {
  std::vector<ChildProcess> children;
  for (int w = 0; w < workers; ++w)
    children.emplace_back([&run, w, workers, progress_fd] {
      try {
        run.work(w, workers, progress_fd);
        return 0;
      } catch (const NoAnswer& e) {  // a plug-in's hang, in its own words, as before
        std::fprintf(stderr, "fdhcert: %s\n", e.what());
        return 3;
      } catch (const std::exception& e) {
        std::fprintf(stderr, "fdhcert: fuzz worker: %s\n", e.what());
        return 3;
      }
    });
  return children;
}

// The counts a run's progress shows.
struct Tally {
  long done = 0, found = 0, shrink_cut = 0;
};

// Waits for every worker, reporting progress; "" if all ended well, else how the first that
// failed ended ("exit status 3").
std::string wait_for_workers(const Run& run, std::vector<ChildProcess> children, int progress_fd,
                             Tally& tally) {
  std::string failed;
  const Progress shape{"fuzz " + run.method.name + " on " + run.family, 0, run.last - run.first,
                       "cases"};
  while (!children.empty()) {
    for (std::size_t k = 0; k < children.size();) {
      if (const std::optional<ChildStatus> s = children[k].poll()) {
        if (!s->ok() && failed.empty()) failed = s->words();
        children.erase(children.begin() + long(k));
      } else {
        ++k;
      }
    }
    for (ChunkReport got; ::read(progress_fd, &got, sizeof got) == sizeof got;)
      tally.done += got.cases, tally.found += got.found, tally.shrink_cut += got.shrink_cut;
    if (children.empty()) break;
    Progress p = shape;
    p.done = tally.done, p.detail = std::to_string(tally.found) + " found";
    report(run.opt.progress, p);
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  return failed;
}

// Runs the chunks still to do on `opt.threads` workers; throws if one failed. `tally` ends with
// what they did.
void run_workers(const Run& run, Tally& tally) {
  const long chunks = run.chunks();
  if (chunks == 0) return;
  const int threads =
      run.opt.threads > 0 ? run.opt.threads : int(std::thread::hardware_concurrency());
  const int workers = int(std::min<long>(std::max(1, threads), chunks));
  int pipe_fd[2];
  if (::pipe2(pipe_fd, O_CLOEXEC | O_NONBLOCK) != 0)
    throw std::runtime_error("fuzz: cannot make a pipe");
  std::vector<ChildProcess> children;
  try {
    children = start_workers(run, workers, pipe_fd[1]);
  } catch (...) {
    ::close(pipe_fd[0]);
    ::close(pipe_fd[1]);
    throw;
  }
  ::close(pipe_fd[1]);
  const std::string failed = wait_for_workers(run, std::move(children), pipe_fd[0], tally);
  ::close(pipe_fd[0]);
  // The worker said why (a plug-in's crash, exit() or hang names the plug-in) just above.
  if (!failed.empty())
    throw std::runtime_error("fuzz: a worker of method " + run.method.name + " ended with " +
                             failed + " (its message is above)");
}

}  // namespace

FuzzSummary run_fuzz(const FuzzOptions& opt) {
  if (opt.out_dir.empty()) throw std::invalid_argument("fuzz needs an output folder");
  Run run(opt);  // throws as run_fuzz says; holds OUT's lock until it returns

  FuzzSummary sum;
  sum.first = run.first;
  sum.last = run.last;
  const Coverage before = coverage_of(run.run_dir, run.first, run.last);
  run.todo = before.todo;
  sum.resumed = before.done_count();
  Tally tally{sum.resumed, 0};
  for (const DoneMarker& m : before.done) tally.found += read_marker(m.path).disagreements;
  run_workers(run, tally);

  const Coverage after = coverage_of(run.run_dir, run.first, run.last);
  sum.shrink_cut = tally.shrink_cut;
  sum.cut = !after.todo.empty() && opt.budget.spent();
  if (sum.cut) run.space.write_whole(run.run_dir + kPausedMark, "stopped by --budget\n");
  if (!after.todo.empty() && !sum.cut)
    throw std::runtime_error("fuzz: cases " + std::to_string(after.todo.front().begin) + ".." +
                             std::to_string(after.todo.front().end - 1) + " of method " +
                             run.method.name + " did not finish: their worker ended early");
  for (const DoneMarker& m : after.done) {
    const MarkerContent r = read_marker(m.path);
    sum.disagreements += r.disagreements;
    for (const std::string& f : r.files) {
      sum.distinct.insert((run.out / f).string());
      ++sum.by_class[class_of_case_file(f, opt.metamorphic)];
    }
  }
  sum.cases = sum.cut ? after.done_count() : sum.last - sum.first;
  return sum;
}

}  // namespace fdh::verify
