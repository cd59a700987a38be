// Output files (common/util/output_file.hpp): nothing is in place before commit, every location
// is checked before anything is written, and a failed command leaves nothing behind.
#include "common/util/output_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "tests/support/temp_dir.hpp"

namespace plumbago {
namespace {

namespace fs = std::filesystem;

void write_to(const OutputFile& f) { std::ofstream(f.temporary_path()) << "x"; }

TEST(OutputFiles, NothingIsInPlaceBeforeCommit) {
  testing::TempDir tmp;
  OutputFiles out;
  out.folder(tmp.path("a/b"));
  OutputFile& one = out.add(tmp.path("a/b/one.png"));
  EXPECT_EQ(&out.add(tmp.path("a/b/one.png")), &one) << "a path added twice is one file";
  OutputFile& two = out.add(tmp.path("two.exr"));
  write_to(one);
  write_to(two);
  EXPECT_FALSE(fs::exists(tmp.path("a/b/one.png")));
  out.commit();
  EXPECT_TRUE(fs::exists(tmp.path("a/b/one.png")));
  EXPECT_TRUE(fs::exists(tmp.path("two.exr")));
  EXPECT_EQ(std::distance(fs::directory_iterator(tmp.path("a/b")), {}), 1) << "no temporary file left";
}

TEST(OutputFiles, WithoutCommitNothingIsLeftIncludingTheFoldersMade) {
  testing::TempDir tmp;
  fs::create_directories(tmp.path("kept"));
  {
    OutputFiles out;
    out.folder(tmp.path("kept/new/deeper/"));
    write_to(out.add(tmp.path("kept/new/deeper/x.png")));
    write_to(out.add(tmp.path("y.png")));
  }
  EXPECT_TRUE(fs::is_directory(tmp.path("kept")));
  EXPECT_TRUE(fs::is_empty(tmp.path("kept")));
  EXPECT_EQ(std::distance(fs::directory_iterator(tmp.dir()), {}), 1);
}

TEST(OutputFiles, LocationsAreCheckedWhenAdded) {
  testing::TempDir tmp;
  tmp.write("file", "");
  fs::create_directories(tmp.path("folder.png"));
  OutputFiles out;
  EXPECT_THROW(out.folder(tmp.path("file")), std::runtime_error);
  EXPECT_THROW(out.folder(tmp.path("file/sub")), std::runtime_error);
  EXPECT_THROW(out.add(tmp.path("folder.png")), std::runtime_error);
  EXPECT_THROW(out.add(tmp.path("missing/x.png")), std::runtime_error);
  try {
    out.add(tmp.path("folder.png"));
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("folder.png: is a folder, not a file"), std::string::npos) << e.what();
  }
}

// A name the system would refuse, once written under its temporary name, or a folder path
// too long: refused when added, with the limit, not the system's "File name too long".
TEST(OutputFiles, NamesTooLongForTheSystemAreRefusedWhenAdded) {
  testing::TempDir tmp;
  auto refusal = [](const std::function<void()>& add) {
    try {
      add();
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  OutputFiles out;
  const std::string fits = std::string(230, 'a') + ".png", over = std::string(250, 'a') + ".png";
  EXPECT_EQ(refusal([&] { out.add(tmp.path(fits)); }), "");
  std::string why = refusal([&] { out.add(tmp.path(over)); });
  EXPECT_NE(why.find("as its temporary file"), std::string::npos) << why;
  EXPECT_NE(why.find("NAME_MAX"), std::string::npos) << why;
  why = refusal([&] { out.folder(tmp.path(std::string(300, 'd'))); });
  EXPECT_NE(why.find("cannot be made"), std::string::npos) << why;
  EXPECT_NE(why.find("NAME_MAX"), std::string::npos) << why;
  EXPECT_EQ(std::distance(fs::directory_iterator(tmp.dir()), {}), 0) << "nothing made";
}

}  // namespace
}  // namespace plumbago
