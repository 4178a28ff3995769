// Reading inputs as the kerf program reads them (viewer/src/cli/file_io.h): a regular file whole,
// a FIFO to its end, and clear refusals for a folder, a missing file and one past the limit.
#include "file_io.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <sys/stat.h>
#include <unistd.h>

namespace kerf::cli {
namespace {

namespace fs = std::filesystem;

/// A program of `bytes` bytes whose lines differ, so that a byte out of place shows.
std::string programOf(std::size_t bytes) {
  std::string text;
  for (std::size_t k = 0; text.size() < bytes; ++k)
    text += "G01 X" + std::to_string(k) + ".125 Y-" + std::to_string(k % 977) + "\n";
  text.resize(bytes);
  return text;
}

class file_io_test : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("kerf-file-io-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  fs::path dir_;
};

TEST_F(file_io_test, a_regular_file_reads_as_its_bytes) {
  for (const std::size_t size : {std::size_t{0}, std::size_t{1000}, std::size_t{65536}, std::size_t{1 << 20}}) {
    const std::string text = programOf(size);
    std::string error;
    const std::optional<std::string> read = readTextFile(write("p.nc", text), 1u << 30, error);
    ASSERT_TRUE(read) << error;
    EXPECT_TRUE(*read == text) << size;
  }
}

TEST_F(file_io_test, a_fifo_is_read_to_its_end) {
  const std::string path = (dir_ / "fifo").string();
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  const std::string text = programOf(200000);  // more than a pipe holds at once
  std::thread writer([&] { std::ofstream(path, std::ios::binary) << text; });
  std::string error;
  const std::optional<std::string> read = readTextFile(path, 1u << 30, error);
  writer.join();
  ASSERT_TRUE(read) << error;
  EXPECT_TRUE(*read == text);
}

TEST_F(file_io_test, a_folder_a_missing_file_and_a_file_past_the_limit_are_refused) {
  std::string error;
  EXPECT_FALSE(readTextFile(dir_.string(), 1000, error));
  EXPECT_NE(error.find("is a folder"), std::string::npos) << error;
  EXPECT_FALSE(readTextFile((dir_ / "missing.nc").string(), 1000, error));
  EXPECT_NE(error.find("no such file"), std::string::npos) << error;
  EXPECT_FALSE(readTextFile(write("big.nc", programOf(1001)), 1000, error));
  EXPECT_NE(error.find("larger than 1000 bytes"), std::string::npos) << error;
}

}  // namespace
}  // namespace kerf::cli
