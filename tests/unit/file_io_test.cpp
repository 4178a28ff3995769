// Reading a program (viewer/src/cli/file_io.h): a long one is mapped where the system keeps it, not
// copied. It must read as the file's bytes with a NUL after them, and a file cut short or grown
// while it is mapped must neither crash the program nor move that NUL.
#include "file_io.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <unistd.h>

namespace kerf::cli {
namespace {

namespace fs = std::filesystem;

/// A program of about `bytes` bytes whose lines differ, so that a byte out of place shows.
std::string programOf(std::size_t bytes) {
  std::string text;
  for (std::size_t k = 0; text.size() < bytes; ++k)
    text += "G01 X" + std::to_string(k) + ".125 Y-" + std::to_string(k % 977) + "\n";
  text.resize(bytes);
  return text;
}

class FileIo : public ::testing::Test {
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

TEST_F(FileIo, a_long_program_is_mapped_and_reads_as_its_bytes_with_a_nul_after) {
  // A size inside a page, and whole pages (the NUL then lies on the page after the file's).
  for (const std::size_t size : {std::size_t{300000}, std::size_t{4096 * 100}, std::size_t{1 << 20}}) {
    const std::string text = programOf(size);
    const std::string path = write("long.nc", text);
    std::string error;
    std::shared_ptr<const std::atomic<bool>> cut;
    const std::optional<converter::TextBytes> read =
        readProgramFile(path, converter::SourceFile::kMaxSize, error, &cut);
    ASSERT_TRUE(read) << error;
    ASSERT_TRUE(cut) << "a program of " << size << " bytes was not mapped";
    EXPECT_FALSE(cut->load());
    ASSERT_EQ(read->size(), size);
    EXPECT_TRUE(read->view() == text) << size;
    EXPECT_EQ(read->data()[size], '\0');
    // A copy is text of its own, the same bytes.
    const converter::TextBytes copy = *read;
    EXPECT_NE(copy.data(), read->data());
    EXPECT_TRUE(copy.view() == text);
  }
}

TEST_F(FileIo, a_short_program_is_read_not_mapped) {
  const std::string text = programOf(1000);
  const std::string path = write("short.nc", text);
  std::string error;
  std::shared_ptr<const std::atomic<bool>> cut;
  const std::optional<converter::TextBytes> read = readProgramFile(path, converter::SourceFile::kMaxSize, error, &cut);
  ASSERT_TRUE(read) << error;
  EXPECT_FALSE(cut);
  EXPECT_TRUE(read->view() == text);
  EXPECT_EQ(read->data()[read->size()], '\0');
}

TEST_F(FileIo, a_mapped_program_cut_short_reads_as_zeros_past_the_cut_and_says_so) {
  const std::size_t size = 1 << 20, kept = 300001;
  const std::string text = programOf(size);
  const std::string path = write("cut.nc", text);
  std::string error;
  std::shared_ptr<const std::atomic<bool>> cut;
  const std::optional<converter::TextBytes> read = readProgramFile(path, converter::SourceFile::kMaxSize, error, &cut);
  ASSERT_TRUE(read && cut) << error;
  ASSERT_EQ(::truncate(path.c_str(), static_cast<off_t>(kept)), 0);
  // Every byte is read, from the first page past the cut on through SIGBUS and the zero pages.
  std::size_t same = 0, zeros = 0;
  for (std::size_t k = 0; k < size; ++k) {
    const char c = read->data()[k];
    if (k < kept)
      same += c == text[k];
    else
      zeros += c == '\0';
  }
  EXPECT_EQ(same, kept);
  EXPECT_EQ(zeros, size - kept);
  EXPECT_TRUE(cut->load());
  EXPECT_EQ(read->data()[size], '\0');
}

TEST_F(FileIo, a_mapped_program_that_grows_keeps_its_size_and_its_nul) {
  const std::size_t size = 300000;
  const std::string text = programOf(size);
  const std::string path = write("grow.nc", text);
  std::string error;
  std::shared_ptr<const std::atomic<bool>> cut;
  const std::optional<converter::TextBytes> read = readProgramFile(path, converter::SourceFile::kMaxSize, error, &cut);
  ASSERT_TRUE(read && cut) << error;
  std::ofstream(path, std::ios::binary | std::ios::app) << std::string(10000, 'X');
  EXPECT_EQ(read->size(), size);
  EXPECT_EQ(read->data()[size], '\0');  // on a page of the reader's own, not the file's
  EXPECT_TRUE(read->view() == text);
  EXPECT_FALSE(cut->load());
}

}  // namespace
}  // namespace kerf::cli
