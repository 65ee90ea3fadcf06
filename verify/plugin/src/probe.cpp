#include "probe.hpp"

#include <dlfcn.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>

#include "fdh/io/record_scope.hpp"
#include "fdh/os/atomic_file.hpp"
#include "fdh/os/child_process.hpp"
#include "fdh/plugin/loader.hpp"
#include "guard.hpp"
#include "init_call.hpp"

namespace fdh::verify::plugin {
namespace {

QueryRecord probe_query(QueryKind kind, const char* id, std::array<Vec3, 8> x) {
  QueryRecord r;
  r.query.kind = kind;
  r.query.x = x;
  r.id = std::string("probe/") + id;
  return r;
}

// Ordinary inputs of every decision: a hit, a miss, a degenerate one, extreme coordinates.
std::vector<QueryRecord> probe_queries() {
  const Vec3 d{0, 0, 0}, e{1, 0, 0}, f{0, 1, 0};
  const QueryKind vf = QueryKind::VertexFace, ee = QueryKind::EdgeEdge;
  return {
      probe_query(vf, "through-triangle", {{{.25, .25, 1}, d, e, f, {.25, .25, -1}, d, e, f}}),
      probe_query(vf, "beside-triangle", {{{2, 2, 1}, d, e, f, {2, 2, -1}, d, e, f}}),
      probe_query(vf, "all-at-origin", {}),
      probe_query(vf, "triangle-rising-through-point",
                  {{{.25, .25, .5}, d, e, f, {.25, .25, .5}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}}}),
      probe_query(vf, "extreme-coordinates",
                  {{{1e30, 0.1, -0.0}, d, {-1e30, 0, 0}, f, {-1e30, -1e30, 5e-324}, d, e, f}}),
      probe_query(ee, "edges-crossing",
                  {{d, e, {.5, -1, 1}, {.5, 1, 1}, d, e, {.5, -1, -1}, {.5, 1, -1}}}),
      probe_query(ee, "edges-apart", {{d, e, {0, 5, 1}, {1, 5, 1}, d, e, {0, 5, 2}, {1, 5, 2}}}),
      probe_query(ee, "all-at-origin", {}),
  };
}

// Each probe again at minimum separations δ > 0 (fdh_plugin_min_distance): a small one and one
// larger than the probes' coordinates.
std::vector<QueryRecord> with_min_distances(const std::vector<QueryRecord>& probes) {
  std::vector<QueryRecord> all = probes;
  for (const double delta : {0x1p-10, 0x1p+40})
    for (QueryRecord r : probes) {
      r.query.min_distance = delta;
      r.id += delta < 1 ? "/min-distance-2^-10" : "/min-distance-2^40";
      all.push_back(r);
    }
  return all;
}

// Each call is followed by a '.' on `fd`: the parent's deadline is per call, so that a slow
// plug-in (seconds a call) is probed to the end, and it can count the calls made. A time
// outside [0, 1] is not refused here: the run counts it as a broken promise ("not a time").
void run_probes(int fd, const std::vector<Method>& methods, const std::vector<BoxMethod>& boxes) {
  const std::vector<QueryRecord> probes = probe_queries();
  for (const Method& m : methods)
    for (const QueryRecord& r : with_min_distances(probes)) {
      const RecordScope asking(r);  // a crash names the probe
      if (m.applies_to(r.query)) m.hit(r.query), write_all(fd, ".");
      if (m.gives_toi(r.query) && (r.query.min_distance == 0 || m.answers_min_distance))
        m.time_of_impact(r.query, kDefaultToiWidth), write_all(fd, ".");
    }
  double lo[13], hi[13];
  for (const BoxMethod& b : boxes)
    for (const QueryRecord& r : probes)
      for (std::size_t n : {std::size_t(1), std::size_t(3), std::size_t(8)})
        b.build(r.query.x.data(), n, lo, hi), write_all(fd, ".");
}

// The child: probes, then says "ok" on `fd` (a plug-in that calls exit() never says it).
[[noreturn]] void child(int fd, const std::vector<Method>& methods,
                        const std::vector<BoxMethod>& boxes) {
  set_crash_report_fd(fd);
  std::string said = "ok";
  int status = 0;
  try {
    run_probes(fd, methods, boxes);
  } catch (const std::exception& e) {
    said = std::string("fdhcert: ") + e.what() + "\n";
    status = kPluginFailureStatus;
  }
  write_all(fd, said);
  ::_exit(status);
}

using Clock = std::chrono::steady_clock;

// What the child writes on `fd`, into `text`, until it closes it (true), or until `seconds` pass
// without a byte from it or `until` is past (false; `cut` says it was `until`).
bool read_until_closed(int fd, double seconds, Clock::time_point until, std::string& text,
                       bool& cut) {
  const auto quiet = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(std::min(seconds, 1e9)));
  auto deadline = std::min(Clock::now() + quiet, until);
  for (;;) {
    cut = Clock::now() >= until;
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return false;
    pollfd p{fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, int(std::min<long long>(left, 1000)));
    if (ready <= 0) continue;  // EINTR, or the time: the deadline is checked above
    char buf[512];
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return true;
    text.append(buf, std::size_t(n));
    deadline = std::min(Clock::now() + quiet, until);
  }
}

// What a probing child said on its pipe before it closed it (nullopt: nothing within the
// limit, and it was killed) and how it ended.
struct Said {
  std::optional<std::string> text;
  ChildStatus status;
  bool cut = false;  // the run's budget ended the listening (fdh/os/budget.hpp)
  long calls = 0;    // the calls the child made (a '.' each), taken off the text
};

// Runs body(fd) in a child (it must end with _exit) and listens on fd for `seconds`.
template <class Body>
Said talk(const std::string& what, double seconds, const Body& body,
          Clock::time_point until = Clock::time_point::max()) {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error("cannot probe " + what + ": no pipe");
  std::optional<ChildProcess> process;
  try {
    process.emplace([&]() -> int {
      ::close(fds[0]);
      body(fds[1]);
      return 3;  // unreachable: body ends with _exit
    });
  } catch (const std::exception&) {
    ::close(fds[0]), ::close(fds[1]);
    throw std::runtime_error("cannot probe " + what + ": no process");
  }
  ::close(fds[1]);
  Said said;
  std::string text;
  const bool closed = read_until_closed(fds[0], seconds, until, text, said.cut);
  ::close(fds[0]);
  if (!closed) process->kill();
  said.status = process->wait();
  const std::size_t dots = text.find_first_not_of('.');
  said.calls = long(dots == std::string::npos ? text.size() : dots);
  if (closed) said.text = text.substr(std::size_t(said.calls));
  return said;
}

// The child's own report ("fdhcert: plug-in P crashed ...", from the crash handler, the
// watchdog or the exit catcher, status kPluginFailureStatus), without "fdhcert: ".
std::optional<std::string> own_report(const Said& said) {
  const std::string prefix = "fdhcert: ";
  if (!said.status.exited() || said.status.exit_code() != kPluginFailureStatus ||
      said.text->rfind(prefix, 0) != 0)
    return std::nullopt;
  return said.text->substr(prefix.size(), said.text->find('\n') - prefix.size());
}

// The load child: dlopen (its constructors run), then the entry point; "ok" or dlerror's words.
[[noreturn]] void load_child(int fd, const std::string& path, const std::string& file,
                             const PluginSettings& settings) {
  set_crash_report_fd(fd);
  const CallSite loading{path.c_str(), "dlopen (its constructors)"};
  void* lib = nullptr;
  {
    const InCall in(loading);
    lib = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  }
  if (!lib) {
    const char* why = ::dlerror();
    write_all(fd, std::string("dlerror ") + (why ? why : "unknown error"));
    ::_exit(0);
  }
  // A refusal is the parent's to report (it calls init again); a crash is reported here.
  call_init(lib, path, settings);
  call_flags(lib, path);
  for (const char* name : {"fdh_plugin_v2", "fdh_plugin_v1"})
    if (void* f = ::dlsym(lib, name)) {
      const CallSite entry{path.c_str(), name};
      const InCall in(entry);
      reinterpret_cast<const void* (*)()>(f)();
      break;
    }
  call_min_distance(lib, path);
  write_all(fd, "ok");
  ::_exit(0);
}

}  // namespace

std::optional<std::string> probe_load(const std::string& path, const std::string& file,
                                      const PluginSettings& settings, double seconds) {
  const Said said =
      talk("plug-in " + path, seconds, [&](int fd) { load_child(fd, path, file, settings); });
  // (The load child writes no '.': its text is whole.)
  if (!said.text)
    throw PluginLoadError("plug-in " + path + ": cannot load: it did not finish loading within " +
                          std::to_string(int(seconds)) + " s (docs/plugins.md)");
  if (said.status.ok() && *said.text == "ok") return std::nullopt;
  if (said.status.ok() && said.text->rfind("dlerror ", 0) == 0) return said.text->substr(8);
  std::string why = "it ended the process (" + said.status.words() + ") while loading";
  const std::string own = "plug-in " + path + " ";
  if (const std::optional<std::string> report = own_report(said))
    why = report->rfind(own, 0) == 0 ? report->substr(own.size()) : *report;
  throw PluginLoadError("plug-in " + path + ": cannot load: " + why + " (docs/plugins.md)");
}

ProbeCut probe(const std::string& plugin, const std::vector<Method>& methods,
               const std::vector<BoxMethod>& boxes, double seconds, const Budget& budget) {
  const Said said = talk(
      "plug-in " + plugin, seconds, [&](int fd) { child(fd, methods, boxes); }, budget.deadline());
  const std::string what = "plug-in " + plugin;
  if (!said.text && said.cut) return {true, said.calls};
  if (!said.text)
    throw PluginFailure(what + " did not answer within " + std::to_string(int(seconds)) +
                        " s of a call when probed on built-in inputs");
  if (said.status.ok() && *said.text == "ok") return {false, said.calls};
  if (const std::optional<std::string> report = own_report(said)) throw PluginFailure(*report);
  throw PluginFailure(what + " ended the process (" + said.status.words() +
                      ") when probed on built-in inputs");
}

}  // namespace fdh::verify::plugin
