// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <array>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "disktune/errors.h"
#include "disktune/io.h"
#include "disktune/sampling.h"
#include "test_util.h"

namespace disktune {
namespace {

namespace fs = std::filesystem;

using test::TempDir;

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

TEST(PointsCsv, RoundTripsEveryBit) {
  TempDir dir;
  const PeriodicBox box;
  Rng rng(11);
  const Packing p = sample_mps(box, 0.05, rng);
  write_points_csv(dir.file("p.csv"), p);
  const auto back = read_points_csv(dir.file("p.csv"));
  ASSERT_EQ(back.size(), p.size());
  std::size_t k = 0;
  for (DiskId id : p.ids()) {
    EXPECT_EQ(back[k].x, p.center(id).x);
    EXPECT_EQ(back[k].y, p.center(id).y);
    EXPECT_EQ(back[k].r, p.radius(id));
    ++k;
  }
  std::ifstream in(dir.file("p.csv"));
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "x,y,r");
}

TEST(PointsCsv, BadContentNamesTheLine) {
  TempDir dir;
  const std::pair<const char*, const char*> cases[] = {
      {"", ":1:"},
      {"a,b,c\n1,2,3\n", ":1: expected the header"},
      {"x,y,r\n0.1,0.2,0.3\n0.1,oops,0.3\n", ":3:"},
      {"x,y,r\n0.1,0.2\n", ":2:"},
      {"x,y,r\n0.1,0.2,0.3,4\n", ":2:"},
      {"x,y,r\n0.1,0.2,-1\n", ":2: radius must be positive"},
      {"x,y,r\n0.1,nan,1\n", ":2:"},
  };
  for (const auto& [text, where] : cases) {
    write_text(dir.file("bad.csv"), text);
    try {
      read_points_csv(dir.file("bad.csv"));
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find(where), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(read_points_csv(dir.file("missing.csv")), IoError);
}

TEST(PointsCsv, RadiusRangeOfPlanarAndSurfaceFiles) {
  TempDir dir;
  write_text(dir.file("p.csv"), "x,y,r\n0.1,0.2,0.05\n0.3,0.4,0.03\n0.5,0.5,0.04\n");
  EXPECT_EQ(read_radius_range(dir.file("p.csv")), (std::array<double, 2>{0.03, 0.05}));
  write_text(dir.file("s.csv"), "x,y,z,r\n0.1,0.2,0.3,0.02\n0.3,0.4,0.5,0.02\n");
  EXPECT_EQ(read_radius_range(dir.file("s.csv")), (std::array<double, 2>{0.02, 0.02}));
  write_text(dir.file("bad.csv"), "x,y,r\n0.1,0.2,0\n");
  EXPECT_THROW(read_radius_range(dir.file("bad.csv")), InvalidInput);
  write_text(dir.file("empty.csv"), "x,y,r\n");
  EXPECT_THROW(read_radius_range(dir.file("empty.csv")), InvalidInput);
}

TEST(FibersCsv, DiametersReadFromAListOrAnArrangement) {
  TempDir dir;
  write_text(dir.file("d.csv"), "d\n6.8\n\n7.25\n");
  EXPECT_EQ(read_diameters_csv(dir.file("d.csv")), (std::vector<double>{6.8, 7.25}));
  // What write_fibers_csv writes reads back as its d column, every bit.
  const std::vector<double> diameters{0.1, 1.0 / 3, 7e-6};
  write_fibers_csv(dir.file("fibers.csv"), {{0.5, 0.25}, {0.1, 0.9}, {0.3, 0.3}}, diameters);
  EXPECT_EQ(read_diameters_csv(dir.file("fibers.csv")), diameters);
  const std::pair<const char*, const char*> cases[] = {
      {"d\n", "holds no diameters"},
      {"x,y,r\n0.1,0.2,0.3\n", ":1: expected the header 'd' or 'x,y,d'"},
      {"d\n7\n0\n", ":3: a diameter must be positive"},
      {"d\n7,8\n", ":2: unexpected text"},
      {"x,y,d\n0.1,0.2,-7\n", ":2: a diameter must be positive"},
  };
  for (const auto& [text, says] : cases) {
    write_text(dir.file("bad.csv"), text);
    try {
      read_diameters_csv(dir.file("bad.csv"));
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(read_diameters_csv(dir.file("missing.csv")), IoError);
}

// A packing that does not fit the box or the radius asked for: the message says what to
// give in the library's terms (no command-line flags), and names the parameter to change
// so that a front end can add its own name for it.
TEST(PointsCsv, MismatchNamesWhatToChange) {
  TempDir dir;
  write_text(dir.file("r.csv"), "x,y,r\n0.5,0.5,0.03\n");
  try {
    read_packing_csv(dir.file("r.csv"), PeriodicBox(), 0.02);
    ADD_FAILURE() << "accepted a radius of 0.03 for 0.02";
  } catch (const InvalidInput& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("r.csv:2: radius 0.03 differs from the radius 0.02"), std::string::npos) << msg;
    EXPECT_NE(msg.find("give the radius the packing was made with, 0.03"), std::string::npos) << msg;
    EXPECT_EQ(msg.find("--"), std::string::npos) << msg;
    EXPECT_EQ(e.remedy(), InvalidInput::Remedy::radius);
    EXPECT_EQ(e.value(), "0.03");
  }
  // Radii that vary in the file: it was made with a sizing, whatever was asked for.
  write_text(dir.file("v.csv"), "x,y,r\n0.2,0.5,0.02\n0.6,0.5,0.03\n");
  try {
    read_packing_csv(dir.file("v.csv"), PeriodicBox(), 0.02);
    ADD_FAILURE() << "accepted a radius of 0.03 for 0.02";
  } catch (const InvalidInput& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("v.csv:3: radius 0.03 differs from the radius 0.02"), std::string::npos) << msg;
    EXPECT_NE(msg.find("the file's radii run from 0.02 to 0.03: give the sizing the packing was made with"),
              std::string::npos)
        << msg;
    EXPECT_EQ(e.remedy(), InvalidInput::Remedy::sizing);
  }
  write_text(dir.file("box.csv"), "x,y,r\n1.5,0.5,0.1\n");
  try {
    read_packing_csv(dir.file("box.csv"), PeriodicBox(), 0.1);
    ADD_FAILURE() << "accepted a center outside the box";
  } catch (const InvalidInput& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("box.csv:2: center (1.5, 0.5) lies outside the 1 x 1 box; give the width and height"),
              std::string::npos)
        << msg;
    EXPECT_EQ(msg.find("--"), std::string::npos) << msg;
    EXPECT_EQ(e.remedy(), InvalidInput::Remedy::box_size);
  }
}

TEST(AtomicWrite, FailureLeavesNoFileBehind) {
  TempDir dir;
  const std::string target = dir.file("out.csv");
  EXPECT_THROW(write_file_atomically(target,
                                     [](std::ostream& out) {
                                       out << "half";
                                       throw std::runtime_error("boom");
                                     }),
               std::runtime_error);
  EXPECT_TRUE(fs::is_empty(dir.path)) << "a temporary or partial file was left";
  EXPECT_THROW(write_file_atomically(dir.file("no/such/folder/x.csv"), [](std::ostream&) {}), IoError);
  EXPECT_TRUE(fs::is_empty(dir.path));
}

TEST(AtomicWrite, ReplacesAnExistingFileWhole) {
  TempDir dir;
  const std::string target = dir.file("out.txt");
  write_text(target, "old content that is longer");
  write_file_atomically(target, [](std::ostream& out) { out << "new"; });
  std::ifstream in(target);
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_EQ(ss.str(), "new");
}

std::string text_of(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::size_t files_in(const fs::path& dir) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

// Outputs as one transaction (#17): nothing is in place before commit, everything after;
// a transaction given up (an exception in the command) leaves every file as it was.
TEST(OutputTransaction, RenamesEveryOutputTogetherOrNone) {
  TempDir dir;
  const std::string a = dir.file("a.csv"), b = dir.file("b.json");
  write_text(a, "old a");
  {
    OutputTransaction outputs;
    write_file_atomically(a, [](std::ostream& out) { out << "new a"; });
    write_file_atomically(b, [](std::ostream& out) { out << "new b"; });
    EXPECT_EQ(text_of(a), "old a");  // not yet
    EXPECT_FALSE(fs::exists(b));
    EXPECT_EQ(files_in(dir.path), 3u);  // a, and the two temporaries
  }  // given up
  EXPECT_EQ(text_of(a), "old a");
  EXPECT_FALSE(fs::exists(b));
  EXPECT_EQ(files_in(dir.path), 1u) << "a temporary was left";
  {
    OutputTransaction outputs;
    write_file_atomically(a, [](std::ostream& out) { out << "new a"; });
    write_file_atomically(b, [](std::ostream& out) { out << "new b"; });
    outputs.commit();
  }
  EXPECT_EQ(text_of(a), "new a");
  EXPECT_EQ(text_of(b), "new b");
  EXPECT_EQ(files_in(dir.path), 2u);
  // A write that fails inside a transaction takes nothing else with it, but the
  // transaction given up removes what was written before it.
  {
    OutputTransaction outputs;
    write_file_atomically(a, [](std::ostream& out) { out << "newer a"; });
    EXPECT_THROW(write_file_atomically(b, [](std::ostream&) { throw std::runtime_error("boom"); }),
                 std::runtime_error);
  }
  EXPECT_EQ(text_of(a), "new a");
  EXPECT_EQ(text_of(b), "new b");
  EXPECT_EQ(files_in(dir.path), 2u);
  // An output that is a folder is refused when it is written, not at the commit, after
  // the outputs before it were put in place.
  fs::create_directory(dir.file("folder"));
  {
    OutputTransaction outputs;
    write_file_atomically(a, [](std::ostream& out) { out << "newest a"; });
    try {
      write_file_atomically(dir.file("folder"), [](std::ostream& out) { out << "x"; });
      ADD_FAILURE() << "a folder was taken as an output";
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find("is a folder"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(text_of(a), "new a");
  EXPECT_TRUE(fs::is_directory(dir.file("folder")));
  EXPECT_EQ(files_in(dir.path), 3u);
}

TEST(AtomicWrite, WritesThroughASymbolicLinkAndKeepsPermissions) {
  TempDir dir;
  const std::string target = dir.file("real.csv"), link = dir.file("link.csv");
  write_text(target, "old");
  fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write);
  fs::create_symlink(target, link);
  write_file_atomically(link, [](std::ostream& out) { out << "new"; });
  EXPECT_TRUE(fs::is_symlink(link)) << "the link was replaced by a file";
  EXPECT_EQ(text_of(target), "new");
  EXPECT_EQ(fs::status(target).permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);
  EXPECT_EQ(files_in(dir.path), 2u);
}

// What the command's SIGINT/SIGTERM handler does (plugins/cli/main.cpp): the temporaries
// of an open transaction go, no output is replaced.
extern "C" void remove_and_die(int sig) {
  remove_temporary_outputs();
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

TEST(OutputTransaction, ASignalRemovesTheTemporaries) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  TempDir dir;
  const std::string a = dir.file("a.csv");
  write_text(a, "old a");
  EXPECT_EXIT(
      {
        std::signal(SIGTERM, remove_and_die);
        OutputTransaction outputs;
        write_file_atomically(a, [](std::ostream& out) { out << "new a"; });
        write_file_atomically(dir.file("b.csv"), [](std::ostream& out) { out << "new b"; });
        std::raise(SIGTERM);
      },
      ::testing::KilledBySignal(SIGTERM), "");
  EXPECT_EQ(text_of(a), "old a");
  EXPECT_EQ(files_in(dir.path), 1u) << "a temporary was left";
}

TEST(Svg, DrawsEveryDiskAndItsSeamImages) {
  TempDir dir;
  const PeriodicBox box;
  Packing p(box.frame(), 0.1);
  p.insert({0.5, 0.5}, 0.1);
  p.insert({0.01, 0.99}, 0.1, kFixed);  // near a corner: drawn 4 times
  write_packing_svg(dir.file("p.svg"), p);
  std::ifstream in(dir.file("p.svg"));
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string svg = ss.str();
  // The disks in the frame, then the legend: a sample of each kind of disk and its words.
  const std::size_t legend = svg.find("<g font-family");
  ASSERT_NE(legend, std::string::npos);
  std::size_t circles = 0;
  for (std::size_t at = svg.find("<circle"); at < legend; at = svg.find("<circle", at + 1)) ++circles;
  EXPECT_EQ(circles, 5u);
  EXPECT_NE(svg.find("#d62728"), std::string::npos);  // the fixed disk's color
  EXPECT_NE(svg.find("half its radius", legend), std::string::npos);
  EXPECT_NE(svg.find("held on the boundary", legend), std::string::npos);
  EXPECT_EQ(svg.find("frozen", legend), std::string::npos);  // none here
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
}

}  // namespace
}  // namespace disktune
