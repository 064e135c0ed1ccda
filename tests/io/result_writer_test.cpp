// ResultWriter: a run's files appear in the result folder only with its summary; a run that
// fails leaves nothing, or the previous run's complete results (issue 21).

#include "geardyn/io/result_writer.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace geardyn::io {
namespace {
namespace fs = std::filesystem;

std::string readWholeFile(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Every entry of a folder, hidden ones included.
std::set<std::string> entries(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(folder)) names.insert(e.path().filename().string());
  return names;
}

/// The folders this test process made, removed when it ends (they were left in /tmp, and two
/// builds testing at once shared them).
struct ScratchFolders {
  std::vector<fs::path> folders;
  ~ScratchFolders() {
    for (const auto& folder : folders) {
      std::error_code ignored;
      fs::remove_all(folder, ignored);
    }
  }
};

fs::path freshFolder(const std::string& name) {
  static ScratchFolders scratch;
  const fs::path folder = fs::temp_directory_path() /
                          ("geardyn_result_writer_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(folder);
  scratch.folders.push_back(folder);
  return folder;
}

RunSummary summaryOf(const std::string& command) {
  RunSummary s;
  s.command = command;
  return s;
}

TEST(ResultWriter, FilesAppearOnlyWithTheSummary) {
  const fs::path out = freshFolder("commit") / "a" / "b";
  ResultWriter writer(out);
  writer.writeText("table.csv", "x\n1\n");
  std::ofstream(writer.pathFor("record.bin")) << "own writer";
  writer.recordFile("record.bin");
  // Before the commit the result folder holds only the hidden staging folder.
  const auto staged = entries(out);
  ASSERT_EQ(staged.size(), 1u);
  EXPECT_TRUE(staged.begin()->starts_with(".partial-"));
  writer.writeSummary(summaryOf("test"));
  EXPECT_EQ(entries(out), (std::set<std::string>{"record.bin", "summary.json", "table.csv"}));
  EXPECT_EQ(readWholeFile(out / "table.csv"), "x\n1\n");
  // After the commit further files (plots) go straight to the result folder.
  EXPECT_EQ(writer.pathFor("plot.png"), out / "plot.png");
}

TEST(ResultWriter, AFailedRunInANewFolderLeavesNothing) {
  const fs::path root = freshFolder("failed_new");
  const fs::path out = root / "deep" / "out";
  fs::create_directories(root);
  try {
    ResultWriter writer(out);
    writer.writeText("time_history.csv", "t\n0\n");
    throw std::runtime_error("the post-processing failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_FALSE(fs::exists(root / "deep"));  // the folders it created, removed again
  EXPECT_TRUE(fs::exists(root));            // not the ones that were there
}

TEST(ResultWriter, AFailedRunKeepsThePreviousResultsWhole) {
  const fs::path out = freshFolder("failed_rerun");
  {
    ResultWriter first(out);
    first.writeText("table.csv", "first\n");
    first.writeSummary(summaryOf("first"));
  }
  const std::string summary = readWholeFile(out / "summary.json");
  {
    ResultWriter second(out);
    second.writeText("table.csv", "second\n");
    second.writeText("other.csv", "second\n");
  }  // destroyed without a summary: the run failed
  EXPECT_EQ(entries(out), (std::set<std::string>{"summary.json", "table.csv"}));
  EXPECT_EQ(readWholeFile(out / "table.csv"), "first\n");
  EXPECT_EQ(readWholeFile(out / "summary.json"), summary);
}

TEST(ResultWriter, ACommitReplacesOnlyThePreviousRunsListedFiles) {
  const fs::path out = freshFolder("rerun");
  {
    ResultWriter first(out);
    first.writeText("old_only.csv", "old\n");
    first.writeText("table.csv", "old\n");
    first.writeSummary(summaryOf("first"));
  }
  std::ofstream(out / "notes.txt") << "the user's own file";
  ResultWriter second(out);
  second.writeText("table.csv", "new\n");
  second.writeSummary(summaryOf("second"));
  EXPECT_EQ(entries(out), (std::set<std::string>{"notes.txt", "summary.json", "table.csv"}));
  EXPECT_EQ(readWholeFile(out / "table.csv"), "new\n");
  EXPECT_NE(readWholeFile(out / "summary.json").find("\"second\""), std::string::npos);
}

TEST(ResultWriter, TheStagingFolderOfAKilledRunIsRemovedByTheNextRun) {
  const fs::path out = freshFolder("killed");
  fs::create_directories(out);
  // A child process stages a file and is killed before its commit.
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ResultWriter writer(out);
    writer.writeText("table.csv", "partial\n");
    ::kill(::getpid(), SIGKILL);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  const auto left = entries(out);
  ASSERT_EQ(left.size(), 1u);  // only its hidden staging folder: nothing that looks finished
  EXPECT_TRUE(left.begin()->starts_with(".partial-"));
  {
    ResultWriter next(out);
    next.writeText("table.csv", "whole\n");
    next.writeSummary(summaryOf("next"));
  }
  EXPECT_EQ(entries(out), (std::set<std::string>{"summary.json", "table.csv"}));
}

}  // namespace
}  // namespace geardyn::io
