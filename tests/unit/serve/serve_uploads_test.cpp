// The uploads folder (issue 45, items 6 and 7): a private folder nobody can
// predict or plant links in, removed at the end; a named one that no upload
// can turn against the machine's or a program's files; writes that never
// follow a link.
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "nck/serve/program_folders.hpp"
#include "nck/serve/uploads_folder.hpp"

namespace nck::app::serve {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A folder of its own for one test, removed after it.
struct Scratch {
  fs::path base;
  explicit Scratch(const char* name) : base(fs::temp_directory_path() / name) {
    fs::remove_all(base);
    fs::create_directories(base);
  }
  ~Scratch() { fs::remove_all(base); }
};

TEST(ServeUploads, APlantedLinkIsReplacedNotWrittenThrough) {
  Scratch s("nck_serve_uploads_link_test");
  fs::create_directories(s.base / "uploads");
  std::ofstream(s.base / "victim") << "keep me\n";
  // the server wrote job.nc.part and renamed it: a link of that name made the upload overwrite its target
  fs::create_symlink(s.base / "victim", s.base / "uploads" / "job.nc.part");
  fs::create_symlink(s.base / "victim", s.base / "uploads" / "old.nc");
  const ProgramFolders f({}, s.base / "uploads", 1000);
  ASSERT_TRUE(f.save_upload("job.nc", "G0 X1\nM30\n"));
  ASSERT_TRUE(f.save_upload("old.nc", "M30\n"));
  EXPECT_EQ(read_all(s.base / "victim"), "keep me\n");
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(s.base / "uploads" / "old.nc")));  // the link itself went
  EXPECT_EQ(read_all(s.base / "uploads" / "job.nc"), "G0 X1\nM30\n");
  for (const auto& e : fs::directory_iterator(s.base / "uploads"))  // no temporary left behind
    EXPECT_FALSE(e.path().filename().string().starts_with(".upload-")) << e.path();
}

TEST(ServeUploads, ThePrivateFolderIsNewUnpredictableAndRemoved) {
  fs::path kept;
  {
    auto a = UploadsFolder::create_private();
    auto b = UploadsFolder::create_private();
    ASSERT_TRUE(a && b);
    EXPECT_NE(a->path(), b->path());
    EXPECT_EQ(a->path().filename().string().find(std::to_string(::getpid())), std::string::npos);
    struct stat st{};
    ASSERT_EQ(::lstat(a->path().c_str(), &st), 0);
    EXPECT_TRUE(S_ISDIR(st.st_mode));
    EXPECT_EQ(st.st_mode & 0777, 0700u);
    std::ofstream(a->path() / "up.nc") << "M30\n";
    kept = a->path();
  }
  EXPECT_FALSE(fs::exists(kept));
}

TEST(ServeUploads, ANamedFolderMayNotHoldWhatTheMachineReads) {
  Scratch s("nck_serve_uploads_named_test");
  fs::create_directories(s.base / "machine" / "cycles");
  fs::create_directories(s.base / "programs");
  const std::vector<fs::path> guarded{s.base / "machine", s.base / "machine" / "cycles", s.base / "programs"};
  for (const fs::path& bad : {s.base, s.base / "machine", s.base / "machine" / "cycles", s.base / "programs",
                              fs::path("/"), fs::path("/proc/self"), fs::path("/sys/kernel"), fs::path("/dev/shm")}) {
    const auto u = UploadsFolder::named(bad, guarded);
    ASSERT_FALSE(u) << bad;
    EXPECT_EQ(u.error().id, ErrorId::ServeUploadsRefused) << bad;
  }
  fs::create_symlink("/", s.base / "root-link");
  EXPECT_FALSE(UploadsFolder::named(s.base / "root-link", guarded)) << "a link to / holds the machine folder";
  auto own = UploadsFolder::named(s.base / "uploads", guarded);  // made when missing, and kept
  ASSERT_TRUE(own);
  EXPECT_TRUE(UploadsFolder::named(s.base / "programs" / "uploads", guarded)) << "inside a programs folder is fine";
  const fs::path made = own->path();
  { auto gone = std::move(*own); }
  EXPECT_TRUE(fs::is_directory(made));
}

}  // namespace
}  // namespace nck::app::serve
