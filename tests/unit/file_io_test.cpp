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
  /// The file read as the program reads it, with its cut-short mark (null unless mapped).
  struct Read {
    std::optional<converter::TextBytes> text;
    std::shared_ptr<const std::atomic<bool>> cut;
    std::string error;
  };
  static Read read(const std::string& path) {
    Read r;
    r.text = readProgramFile(path, converter::SourceFile::kMaxSize, r.error, &r.cut);
    return r;
  }
  fs::path dir_;
};

TEST_F(FileIo, a_long_program_is_mapped_and_reads_as_its_bytes_with_a_nul_after) {
  // A size inside a page, and whole pages (the NUL then lies on the page after the file's).
  for (const std::size_t size : {std::size_t{300000}, std::size_t{4096 * 100}, std::size_t{1 << 20}}) {
    const std::string text = programOf(size);
    const Read r = read(write("long.nc", text));
    ASSERT_TRUE(r.text) << r.error;
    ASSERT_TRUE(r.cut) << "a program of " << size << " bytes was not mapped";
    EXPECT_FALSE(r.cut->load());
    ASSERT_EQ(r.text->size(), size);
    EXPECT_TRUE(r.text->view() == text) << size;
    EXPECT_EQ(r.text->data()[size], '\0');
    // A copy is text of its own, the same bytes.
    const converter::TextBytes copy = *r.text;
    EXPECT_NE(copy.data(), r.text->data());
    EXPECT_TRUE(copy.view() == text);
  }
}

TEST_F(FileIo, a_short_program_is_read_not_mapped) {
  const std::string text = programOf(1000);
  const Read r = read(write("short.nc", text));
  ASSERT_TRUE(r.text) << r.error;
  EXPECT_FALSE(r.cut);
  EXPECT_TRUE(r.text->view() == text);
  EXPECT_EQ(r.text->data()[r.text->size()], '\0');
}

TEST_F(FileIo, a_mapped_program_cut_short_reads_as_zeros_past_the_cut_and_says_so) {
  const std::size_t size = 1 << 20, kept = 300001;
  const std::string text = programOf(size);
  const std::string path = write("cut.nc", text);
  const Read r = read(path);
  ASSERT_TRUE(r.text && r.cut) << r.error;
  const converter::TextBytes& bytes = *r.text;
  ASSERT_EQ(::truncate(path.c_str(), static_cast<off_t>(kept)), 0);
  // Every byte is read, from the first page past the cut on through SIGBUS and the zero pages.
  std::size_t same = 0, zeros = 0;
  for (std::size_t k = 0; k < size; ++k) {
    const char c = bytes.data()[k];
    if (k < kept)
      same += c == text[k];
    else
      zeros += c == '\0';
  }
  EXPECT_EQ(same, kept);
  EXPECT_EQ(zeros, size - kept);
  EXPECT_TRUE(r.cut->load());
  EXPECT_EQ(bytes.data()[size], '\0');
}

TEST_F(FileIo, a_mapped_program_that_grows_keeps_its_size_and_its_nul) {
  const std::size_t size = 300000;
  const std::string text = programOf(size);
  const std::string path = write("grow.nc", text);
  const Read r = read(path);
  ASSERT_TRUE(r.text && r.cut) << r.error;
  std::ofstream(path, std::ios::binary | std::ios::app) << std::string(10000, 'X');
  EXPECT_EQ(r.text->size(), size);
  EXPECT_EQ(r.text->data()[size], '\0');  // on a page of the reader's own, not the file's
  EXPECT_TRUE(r.text->view() == text);
  EXPECT_FALSE(r.cut->load());
}

}  // namespace
}  // namespace kerf::cli
