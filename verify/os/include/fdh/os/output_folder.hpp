// A multi-file output published whole (issue 34): audit --out, certify, report, table1 and
// scenes build their whole output in a private folder beside the user's,
// DIR.tmp.<pid>.staged-XXXXXX (mkdtemp, mode 0700), and commit() swaps it in with one rename
// (renameat2's RENAME_EXCHANGE), so that DIR is always the old output or the new one, never a
// mix. What the old folder holds that the job does not own (another job's files, the user's own)
// is carried into the new folder first: files as hard links (a copy where a link is refused),
// links as links, folders entry by entry. An owned entry that the run did not write again is
// gone. Uncommitted (an error, an exception), the private folder is removed and DIR is left as
// it was, byte for byte; SIGTERM and SIGINT remove it too (fdh/os/temporaries.hpp), and what a
// run killed otherwise (SIGKILL) left beside DIR is removed by the next run that writes DIR.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "fdh/os/temporaries.hpp"

namespace fdh::verify {

// Checks, before a run, that `dir` can take a multi-file output: as check_output_dir
// (fdh/os/atomic_file.hpp) with `files`, and its parent folder is writable (the private folder
// is made there), and it is neither the current folder nor one holding it (the folder is
// replaced whole). Throws std::runtime_error naming `dir` and what is wrong.
void check_output_folder(const std::string& dir, const std::vector<std::string>& files = {});

class OutputFolder {
 public:
  // `owned`: the job's entries in DIR, as relative paths or fnmatch(3) patterns ("cases",
  // "data/pareto.csv", "violation-*"); a folder matched is owned with all it holds. Makes the
  // private folder (and DIR's parent, if absent); throws std::runtime_error naming DIR.
  OutputFolder(const std::string& dir, std::vector<std::string> owned);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  // The private folder, where the job writes (the path as DIR was given, its name changed).
  const std::string& path() const { return staged_; }
  // Carries what DIR holds and the job does not own into the private folder, then swaps it in,
  // then removes the old folder. Throws std::runtime_error naming DIR; DIR is then unchanged.
  void commit();
  // write(path()), then commit(). A std::runtime_error's message names DIR where it named the
  // private folder, so that a failed write names the output the user asked for.
  void publish(const std::function<void(const std::string& into)>& write);

 private:
  std::string dir_, staged_;
  std::vector<std::string> owned_;
  RecordedTemporary recorded_;  // staged_, removed whole by SIGTERM and SIGINT
  bool committed_ = false;
};

}  // namespace fdh::verify
