// SPDX-License-Identifier: MIT
// Progress and Ctrl-C in the tool (tools/cvms/interrupt.hpp,
// progress_line.hpp): --progress shows each stage's end on stderr, nothing is
// shown when stderr is no terminal and --progress is absent, and SIGINT in
// the middle of a long sum ends it with exit code 130 and one line, the
// existing output file byte for byte as it was and no temporary file left.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "support/cli_runner.hpp"

extern char** environ;

namespace {

using cvms::test::CliOutcome;
using Clock = std::chrono::steady_clock;

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class CliInterrupt : public cvms::test::CliTest {
 protected:
  CliInterrupt() : CliTest("interrupt_") {}
  void SetUp() override {
#ifndef CVMS_CLI_PATH
    GTEST_SKIP() << "the cvms tool is not built";
#endif
  }

  // Starts `cvms args...` in the scratch directory, stderr to err.txt.
  pid_t start(const std::vector<std::string>& args) const {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    const std::string err = (dir_.path() / "err.txt").string();
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    std::vector<std::string> words = {CVMS_CLI_PATH};
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    pid_t pid = -1;
    const int failed = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    return failed == 0 ? pid : -1;
  }

  // Waits up to `limit` for stderr to contain `text`; false if not, or if
  // the process ended before.
  bool wait_for_stderr(pid_t pid, const std::string& text, std::chrono::seconds limit) const {
    const auto end = Clock::now() + limit;
    while (Clock::now() < end) {
      if (slurp(dir_.path() / "err.txt").find(text) != std::string::npos) return true;
      if (ended(pid)) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
  }

  // Whether pid has ended (without reaping it).
  static bool ended(pid_t pid) {
    siginfo_t info = {};
    return waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOWAIT | WNOHANG) == 0 &&
           info.si_pid == pid;
  }

  // The exit code of pid, -1 if a signal ended it, -2 if it did not end
  // within `limit` (then it is killed).
  static int wait_exit(pid_t pid, std::chrono::seconds limit) {
    const auto end = Clock::now() + limit;
    int status = 0;
    while (Clock::now() < end) {
      if (waitpid(pid, &status, WNOHANG) == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    return -2;
  }
};

TEST_F(CliInterrupt, ProgressOnlyWhenAskedOffATerminal) {
  ASSERT_EQ(run("gen sphere --subdivisions 3 -o a.off").code, 0);
  const CliOutcome quiet = run("sum a.off a.off -o s.off");
  EXPECT_EQ(quiet.code, 0);
  EXPECT_EQ(quiet.err, "") << "no terminal, no --progress: nothing on stderr";
  const CliOutcome shown = run("sum a.off a.off -o t.off --progress");
  EXPECT_EQ(shown.code, 0);
  EXPECT_NE(shown.err.find("cvms: sum: facets 100% ("), std::string::npos) << shown.err;
  EXPECT_NE(shown.err.find("cvms: sum: output 100% ("), std::string::npos) << shown.err;
  EXPECT_EQ(slurp(dir_.path() / "s.off"), slurp(dir_.path() / "t.off")) << "the same output";
  const CliOutcome hull = run("hull a.off -o h.off --progress");
  EXPECT_EQ(hull.code, 0);
  EXPECT_NE(hull.err.find("cvms: hull 100% ("), std::string::npos) << hull.err;
  const CliOutcome diff = run("diff a.off a.off -o d.off --progress");
  EXPECT_EQ(diff.code, 0) << diff.err;
  EXPECT_NE(diff.err.find("cvms: difference: rows 100% ("), std::string::npos) << diff.err;
}

TEST_F(CliInterrupt, DecompositionsShowProgressWhenAsked) {
  // A non-convex solid is decomposed by `decompose` and by `check` (its piece
  // count); both hear the decomposition's stages, and showing them changes
  // nothing on stdout or in the pieces file.
  const std::string solid = (std::filesystem::path(CVMS_TEST_DATA_DIR) / "solids" / "l_block.off").string();
  const CliOutcome quiet = run("decompose " + solid + " -o q.obj");
  EXPECT_EQ(quiet.code, 0) << quiet.err;
  const CliOutcome shown = run("decompose " + solid + " -o p.obj --progress");
  EXPECT_EQ(shown.code, 0) << shown.err;
  EXPECT_NE(shown.err.find("cvms: decomposition: merge 100% ("), std::string::npos) << shown.err;
  EXPECT_EQ(slurp(dir_.path() / "q.obj"), slurp(dir_.path() / "p.obj")) << "the same pieces";
  const CliOutcome check_quiet = run("check " + solid);
  EXPECT_EQ(check_quiet.code, 0) << check_quiet.err;
  EXPECT_EQ(check_quiet.err, "");
  const CliOutcome check_shown = run("check " + solid + " --progress");
  EXPECT_EQ(check_shown.code, 0) << check_shown.err;
  EXPECT_NE(check_shown.err.find("cvms: decomposition: merge 100% ("), std::string::npos) << check_shown.err;
  EXPECT_EQ(check_quiet.out, check_shown.out);
}

TEST_F(CliInterrupt, CtrlCEndsALongSumWithTheOutputUntouched) {
  // ESSDMS on Sphere6 + rotated Sphere6 tests some 10^10 pairs: far longer
  // than the test waits, and it reports every few facets.
  ASSERT_EQ(run("gen sphere --subdivisions 6 -o a.off").code, 0);
  ASSERT_EQ(run("gen rotated-sphere --subdivisions 6 -o b.off").code, 0);
  const std::string before = "an existing file the interrupted sum must leave as it is\n";
  dir_.write("out.off", before);
  const auto path = [&](const char* name) { return (dir_.path() / name).string(); };
  const pid_t pid = start(
      {"sum", path("a.off"), path("b.off"), "--algorithm", "essdms", "--progress", "-o", path("out.off")});
  ASSERT_GT(pid, 0);
  // The first progress line means the sum runs, with Ctrl-C caught.
  const bool running = wait_for_stderr(pid, "cvms: sum: pairs", std::chrono::seconds(120));
  const auto sent = Clock::now();
  ASSERT_EQ(kill(pid, SIGINT), 0);
  const int code = wait_exit(pid, std::chrono::seconds(60));
  const double seconds = std::chrono::duration<double>(Clock::now() - sent).count();
  ASSERT_TRUE(running) << slurp(dir_.path() / "err.txt");
  EXPECT_EQ(code, 130) << slurp(dir_.path() / "err.txt");
  EXPECT_LT(seconds, 10.0) << "stopped promptly";
  const std::string err = slurp(dir_.path() / "err.txt");
  EXPECT_NE(err.find("\ncvms: interrupted; nothing was written\n"), std::string::npos) << err;
  EXPECT_EQ(slurp(dir_.path() / "out.off"), before);
  for (const auto& entry : std::filesystem::directory_iterator(dir_.path()))
    EXPECT_EQ(entry.path().filename().string().find(".cvms-"), std::string::npos)
        << "temporary file left: " << entry.path();
}

}  // namespace
