// write_file_atomic: the target holds the old contents or the new ones, never part of them, and
// a writer killed while it writes leaves nothing beside the target.
#include <brdfnav/core/atomic_file.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace brdfnav {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

class AtomicFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("brdfnav_atomic_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename());
    return names;
  }

  fs::path dir_;
};

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST_F(AtomicFile, WritesTheContentsAndNothingElse) {
  const fs::path target = dir_ / "chosen.yaml";
  write_file_atomic(target, "model: he\n");
  EXPECT_EQ(read_text(target), "model: he\n");
  EXPECT_EQ(entries(), std::vector<std::string>{"chosen.yaml"});
  // The mode an ordinary new file gets: 0666 less the umask.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  struct stat st {};
  ASSERT_EQ(::stat(target.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0666 & ~mask);
}

TEST_F(AtomicFile, ReplacesTheOldContents) {
  const fs::path target = dir_ / "table.bin";
  write_file_atomic(target, std::string(100000, 'a'));
  write_file_atomic(target, "b");
  EXPECT_EQ(read_text(target), "b");
  EXPECT_EQ(entries(), std::vector<std::string>{"table.bin"});
}

TEST_F(AtomicFile, AFailureNamesTheTargetAndLeavesNoLitter) {
  const fs::path missing = dir_ / "no_such_dir" / "out.yaml";
  try {
    write_file_atomic(missing, "x");
    ADD_FAILURE() << "wrote into a missing directory";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr(missing.string() + ": cannot write"));
  }
  // A directory in the target's place: the rename fails, the directory stays as it was.
  fs::create_directories(dir_ / "taken");
  EXPECT_THROW(write_file_atomic(dir_ / "taken", "x"), std::runtime_error);
  EXPECT_TRUE(fs::is_directory(dir_ / "taken"));
  EXPECT_EQ(entries(), std::vector<std::string>{"taken"});
}

// The kernel kills a process whose file outgrows RLIMIT_FSIZE (SIGXFSZ): a deterministic kill in
// the middle of the write. A named temporary would be left with its first MiB; the unnamed file
// disappears with the process.
TEST_F(AtomicFile, AWriterKilledMidWriteLeavesNothing) {
  const fs::path target = dir_ / "big.bin";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_DFL);
    const rlimit limit{1 << 20, 1 << 20};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    write_file_atomic(target, std::string(4 << 20, 'x'));
    ::_exit(0);  // not reached: the write outgrows the limit
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the writer was not killed, status " << status;
  EXPECT_EQ(WTERMSIG(status), SIGXFSZ);
  EXPECT_EQ(entries(), std::vector<std::string>{});
}

}  // namespace
}  // namespace brdfnav
