// A multi-file output published whole (fdh/os/output_folder.hpp): all of it or the old folder as
// it was; the job's own entries replaced as a set, the rest carried; no private folder left.
#include "fdh/os/output_folder.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

#include "fdh/os/child_process.hpp"
#include "fdh/os/temporaries.hpp"
#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

std::string of_read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Every entry under `dir` by relative name: a file's bytes, a link's target, "/" for a folder.
std::map<std::string, std::string> of_tree(const fs::path& dir) {
  std::map<std::string, std::string> m;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string rel = e.path().lexically_relative(dir).string();
    m[rel] = e.is_symlink()     ? "-> " + fs::read_symlink(e.path()).string()
             : e.is_directory() ? "/"
                                : of_read(e.path());
  }
  return m;
}

// The names in `dir`'s parent that begin with `dir`'s name and ".tmp.".
int of_beside(const fs::path& dir) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir.parent_path()))
    n += e.path().filename().string().rfind(dir.filename().string() + ".tmp.", 0) == 0;
  return n;
}

// An earlier output: the job's files (a.txt, cases/1.vf, data/own.csv) beside the user's.
fs::path of_old_output(const fs::path& root) {
  const fs::path out = root / "out";
  fs::create_directories(out / "cases");
  fs::create_directories(out / "data" / "deep");
  std::ofstream(out / "a.txt") << "old a\n";
  std::ofstream(out / "cases" / "1.vf") << "old case\n";
  std::ofstream(out / "data" / "own.csv") << "old own\n";
  std::ofstream(out / "data" / "theirs.csv") << "another job's\n";
  std::ofstream(out / "data" / "deep" / "notes") << "the user's\n";
  std::ofstream(out / "mine.txt") << "the user's\n";
  fs::create_symlink("mine.txt", out / "link");
  return out;
}

const std::vector<std::string> kOwned = {"a.txt", "cases", "data/own.csv", "b-*"};

TEST(OutputFolder, IntoANewFolderAllAtOnce) {
  const fs::path root = fresh_temp_dir("output_folder_new"), out = root / "sub" / "out";
  {
    OutputFolder f(out.string(), kOwned);
    std::ofstream(fs::path(f.path()) / "a.txt") << "new a\n";
    EXPECT_FALSE(fs::exists(out)) << "visible before the commit";
    f.commit();
  }
  EXPECT_EQ(of_tree(out), (std::map<std::string, std::string>{{"a.txt", "new a\n"}}));
  EXPECT_EQ(of_beside(out), 0);
}

TEST(OutputFolder, OverAnOldOneReplacesTheOwnedAsASetAndCarriesTheRest) {
  const fs::path root = fresh_temp_dir("output_folder_over");
  const fs::path out = of_old_output(root);
  fs::permissions(out, fs::perms(0750));
  {
    OutputFolder f(out.string(), kOwned);
    fs::create_directories(fs::path(f.path()) / "data");
    std::ofstream(fs::path(f.path()) / "a.txt") << "new a\n";
    std::ofstream(fs::path(f.path()) / "b-1.vf") << "new case\n";
    std::ofstream(fs::path(f.path()) / "data" / "own.csv") << "new own\n";
    f.commit();
  }
  EXPECT_EQ(of_tree(out), (std::map<std::string, std::string>{
                              {"a.txt", "new a\n"},
                              {"b-1.vf", "new case\n"},
                              {"data", "/"},
                              {"data/own.csv", "new own\n"},
                              {"data/theirs.csv", "another job's\n"},
                              {"data/deep", "/"},
                              {"data/deep/notes", "the user's\n"},
                              {"mine.txt", "the user's\n"},
                              {"link", "-> mine.txt"},
                          }));
  EXPECT_EQ(fs::status(out).permissions() & fs::perms::all, fs::perms(0750));
  EXPECT_EQ(of_beside(out), 0);
}

TEST(OutputFolder, UncommittedOrFailingLeavesTheOldOneAsItWas) {
  const fs::path root = fresh_temp_dir("output_folder_failed");
  const fs::path out = of_old_output(root);
  const auto before = of_tree(out);
  {
    OutputFolder f(out.string(), kOwned);
    std::ofstream(fs::path(f.path()) / "a.txt") << "new a\n";
    EXPECT_EQ(of_beside(out), 1);
  }
  EXPECT_EQ(of_tree(out), before);
  EXPECT_EQ(of_beside(out), 0);
  OutputFolder f(out.string(), kOwned);
  try {
    f.publish([](const std::string& into) {
      std::ofstream(fs::path(into) / "a.txt") << "new a\n";
      throw std::runtime_error(into + "/b-1.vf: cannot write file: File too large");
    });
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), out.string() + "/b-1.vf: cannot write file: File too large");
  }
  EXPECT_EQ(of_tree(out), before);
}

TEST(OutputFolder, ALinkAtTheFolderKeepsTheLinkAndReplacesWhatItNames) {
  const fs::path root = fresh_temp_dir("output_folder_link");
  const fs::path real = of_old_output(root), link = root / "link-to-out";
  fs::create_symlink(real, link);
  {
    OutputFolder f(link.string(), kOwned);
    std::ofstream(fs::path(f.path()) / "a.txt") << "new a\n";
    f.commit();
  }
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(of_read(link / "a.txt"), "new a\n");
  EXPECT_EQ(of_read(real / "mine.txt"), "the user's\n");
}

TEST(OutputFolder, TheCurrentFolderIsRefused) {
  const fs::path root = fresh_temp_dir("output_folder_cwd");
  const fs::path was = fs::current_path();
  fs::current_path(root);
  std::string what;
  try {
    check_output_folder(".");
  } catch (const std::runtime_error& e) {
    what = e.what();
  }
  const bool holder_refused = [&] {
    try {
      check_output_folder(root.parent_path().string());
    } catch (const std::runtime_error&) {
      return true;
    }
    return false;
  }();
  fs::current_path(was);
  EXPECT_NE(what.find("is the current folder"), std::string::npos) << what;
  EXPECT_TRUE(holder_refused) << "a folder that holds the current one";
}

// SIGKILL leaves the private folder (here made as a dead run would have left it); the next run
// that writes the same output removes it with all it holds, links not followed.
TEST(OutputFolder, AKilledRunsFolderIsRemovedByTheNextRun) {
  const fs::path root = fresh_temp_dir("output_folder_dead");
  const fs::path out = of_old_output(root), victim = root / "victim";
  fs::create_directories(victim);
  std::ofstream(victim / "precious") << "kept\n";
  ChildProcess dead([] { return 0; });
  const pid_t pid = dead.pid();
  dead.wait();
  const fs::path p = root / ("out.tmp." + std::to_string(pid) + ".staged-AbCdEf");
  fs::create_directories(p / "data" / ("chart.tmp." + std::to_string(pid) + ".AbCdEf"));
  std::ofstream(p / "data" / ("chart.tmp." + std::to_string(pid) + ".AbCdEf") / "c.png") << "cut";
  std::ofstream(p / "a.txt") << "a";
  fs::create_symlink(victim, p / "data" / "to-victim");
  EXPECT_EQ(of_beside(out), 1);
  {
    OutputFolder f(out.string(), kOwned);
    EXPECT_FALSE(fs::exists(p)) << "the dead run's folder was not removed";
    EXPECT_EQ(of_beside(out), 1);  // this run's own
  }
  EXPECT_EQ(of_beside(out), 0);
  EXPECT_EQ(of_read(victim / "precious"), "kept\n");
}

// An old run's temporary of one of the job's own files is left behind; one of another file (the
// user's) is carried as any file.
TEST(OutputFolder, DeadRunsTemporariesOfOwnedFilesAreNotCarried) {
  const fs::path root = fresh_temp_dir("output_folder_litter");
  const fs::path out = of_old_output(root);
  ChildProcess dead([] { return 0; });
  const std::string pid = std::to_string(dead.pid());
  dead.wait();
  std::ofstream(out / ("a.txt.tmp." + pid + ".3")) << "cut";
  std::ofstream(out / ("mine.txt.tmp." + pid + ".3")) << "the user's\n";
  {
    OutputFolder f(out.string(), kOwned);
    std::ofstream(fs::path(f.path()) / "a.txt") << "new a\n";
    f.commit();
  }
  EXPECT_FALSE(fs::exists(out / ("a.txt.tmp." + pid + ".3")));
  EXPECT_EQ(of_read(out / ("mine.txt.tmp." + pid + ".3")), "the user's\n");
}

TEST(OutputFolder, RemoveTreeRemovesDeepFoldersAndNoLinksTarget) {
  const fs::path root = fresh_temp_dir("output_folder_tree");
  fs::path p = root / "t";
  for (int i = 0; i < 20; ++i) {
    fs::create_directories(p);
    for (int f = 0; f < 100; ++f) std::ofstream(p / ("f" + std::to_string(f))) << f;
    p /= "d";
  }
  std::ofstream(root / "outside") << "kept\n";
  fs::create_symlink(root, root / "t" / "up");
  remove_tree((root / "t").c_str());
  EXPECT_FALSE(fs::exists(root / "t"));
  EXPECT_EQ(of_read(root / "outside"), "kept\n");
}

}  // namespace
}  // namespace fdh::verify
