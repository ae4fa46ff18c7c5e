// Shards of one build (precompute_database() with --shard i/N) and their merge: each renders its
// share of the node images and of the blend check's cell midpoints; merged, they give the
// single-machine database byte for byte, whether or not the shards brought the midpoints.
#include <brdfnav/navigator/database_format.h>
#include <brdfnav/precompute/database.h>
#include <gtest/gtest.h>

#include "database_fixture.h"

#include <functional>
#include <regex>
#include <set>
#include <sstream>

namespace brdfnav {
namespace {

using namespace test;

// The shards of the tiny profile, built once per process (ctest runs the suite as one test).
const std::vector<fs::path>& shards() {
  static const std::vector<fs::path> dirs = [] {
    std::vector<fs::path> d;
    for (int i = 0; i < 2; ++i) {
      d.push_back(scratch("shard" + std::to_string(i)));
      PrecomputeRequest request{tiny_profile(), d.back(), false, 0, {}};
      request.shard_index = i, request.shard_count = 2;
      precompute_database(request, fixture().env, fixture().scene);
    }
    return d;
  }();
  return dirs;
}

// The relative paths of the files below `dir/sub`.
std::set<std::string> files_under(const fs::path& dir, const std::string& sub) {
  std::set<std::string> files;
  if (!fs::exists(dir / sub)) return files;
  for (const auto& e : fs::recursive_directory_iterator(dir / sub))
    if (e.is_regular_file()) files.insert(fs::relative(e.path(), dir).generic_string());
  return files;
}

// Merges `from` into a fresh directory; returns it and the merge's log lines.
std::pair<fs::path, std::vector<std::string>> merge(const std::vector<fs::path>& from,
                                                    const std::string& name) {
  const fs::path merged = scratch(name);
  std::vector<std::string> log;
  PrecomputeRequest request{tiny_profile(), merged, false, 0, {}};
  request.observer.log = [&](const std::string& line) { log.push_back(line); };
  merge_shards(from, request, fixture().env, fixture().scene);
  return {merged, log};
}

std::string line_starting(const std::vector<std::string>& log, const std::string& start) {
  for (const std::string& line : log)
    if (line.rfind(start, 0) == 0) return line;
  return "";
}

std::size_t cell_count() {
  std::size_t n = 0;
  for (const ProfileGrid& g : tiny_profile().grids) n += g.grid.cell_count();
  return n;
}

// The shards render disjoint parts of the images and of the cell midpoints, together all of
// them, and list every one in shard.yaml.
TEST(Shards, SplitTheImagesAndTheCellMidpoints) {
  const std::vector<fs::path>& s = shards();
  EXPECT_TRUE(fs::exists(s[0] / "diffuse.exr"));
  EXPECT_FALSE(fs::exists(s[1] / "diffuse.exr"));
  std::set<std::string> cells, images;
  for (const fs::path& shard : s) {
    const ShardOrigin o = read_shard_origin(shard);
    for (const char* sub : {"cells", "images"}) {
      std::set<std::string>& all = std::string(sub) == "cells" ? cells : images;
      for (const std::string& f : files_under(shard, sub)) {
        EXPECT_TRUE(all.insert(f).second) << f << " is in both shards";
        EXPECT_TRUE(o.files.contains(f)) << f << " is not in " << shard / db::kShardFile;
      }
    }
    EXPECT_FALSE(files_under(shard, "cells").empty()) << shard << " rendered no midpoint";
  }
  EXPECT_EQ(cells.size(), cell_count());
  EXPECT_EQ(images.size(), tiny_profile().image_count() - 1);  // the diffuse image apart
}

// Two shards merge into the reference database byte for byte, the merge rendering no midpoint
// (the shards did), and leave no midpoint file in it. A merge with a shard missing or given
// twice is refused.
TEST(Shards, MergeIntoTheSameDatabase) {
  const std::vector<fs::path>& s = shards();
  try {
    merge({s[0], s[0]}, "twice");
    ADD_FAILURE() << "merged a shard twice";
  } catch (const DatabaseError& e) {
    EXPECT_NE(std::string(e.what()).find("given twice"), std::string::npos) << e.what();
  }
  try {
    merge({s[1]}, "missing");
    ADD_FAILURE() << "merged without shard 0";
  } catch (const DatabaseError& e) {
    EXPECT_NE(std::string(e.what()).find("shard 0/2 is missing"), std::string::npos) << e.what();
  }
  const auto [merged, log] = merge(s, "merged");
  EXPECT_EQ(tree(merged), tree(fixture().db));
  EXPECT_FALSE(fs::exists(merged / "cells"));
  EXPECT_EQ(line_starting(log, "blend check: "),
            "blend check: " + std::to_string(cell_count()) +
                " cells, 0 midpoints rendered here (the others by the shards)");
}

// A shard interrupted while it renders its midpoints resumes: it renders only those it had not
// finished and is byte-identical to the uninterrupted shard. (Blinn-Phong on 9 nodes: the tiny
// profile has too few cells to interrupt a shard among them.)
TEST(Shards, AnInterruptedShardResumesItsMidpoints) {
  struct Interrupted {};
  Profile profile = tiny_profile();
  profile.grids = {{ModelId::blinn_phong, ParamGrid(model_info(ModelId::blinn_phong).params,
                                                    {{5, 10, 20, 50, 100, 200, 500, 1000, 2000}})}};
  const auto shard = [&](const fs::path& dir, bool resume, PrecomputeObserver observer) {
    PrecomputeRequest request{profile, dir, resume, 0, std::move(observer)};
    request.shard_index = 1, request.shard_count = 2;
    precompute_database(request, fixture().env, fixture().scene);
  };
  const fs::path whole = scratch("uninterrupted");
  shard(whole, false, {});
  const std::size_t mine = files_under(whole, "cells").size();
  ASSERT_EQ(mine, 4u);  // of 8 cells

  const fs::path dir = scratch("interrupted"), work = dir.string() + ".partial";
  PrecomputeObserver interrupt;
  interrupt.progress = [&](std::string_view phase, std::size_t, std::size_t) {
    if (phase == "cells" && files_under(work, "cells").size() >= 2) throw Interrupted{};
  };
  EXPECT_THROW(shard(dir, false, interrupt), Interrupted);
  const std::size_t kept = files_under(work, "cells").size();
  ASSERT_GE(kept, 2u);
  ASSERT_LT(kept, mine);

  std::vector<std::string> log;
  PrecomputeObserver logged;
  logged.log = [&](const std::string& line) { log.push_back(line); };
  shard(dir, true, logged);
  EXPECT_EQ(tree(dir), tree(whole));
  EXPECT_EQ(line_starting(log, "cells: "), "cells: 8 cell midpoints, " +
                                               std::to_string(8 - (mine - kept)) +
                                               " reused or left to other shards");
}

// A copy of shard `i` whose shard.yaml lists only the files `keep` accepts.
fs::path filtered_shard(int i, const std::string& name,
                        const std::function<bool(const std::string& line)>& keep) {
  const fs::path dir = scratch(name);
  fs::copy(shards()[std::size_t(i)], dir, fs::copy_options::recursive);
  std::istringstream in(read_bytes(dir / db::kShardFile));
  std::string text, line;
  while (std::getline(in, line))
    if (keep(line)) text += line + "\n";
  write_bytes(dir / db::kShardFile, text);
  return dir;
}

// Shards that bring no midpoint (as made before they rendered any): the merge renders them
// itself and the database is the same.
TEST(Shards, WithoutTheirMidpointsMergeIntoTheSameDatabase) {
  std::vector<fs::path> bare;
  for (int i = 0; i < 2; ++i)
    bare.push_back(filtered_shard(i, "bare" + std::to_string(i), [](const std::string& line) {
      return line.find("cells/") == std::string::npos;
    }));
  const auto [merged, log] = merge(bare, "merged-bare");
  EXPECT_EQ(tree(merged), tree(fixture().db));
  EXPECT_EQ(line_starting(log, "blend check: "), "blend check: " + std::to_string(cell_count()) +
                                                     " cells, " + std::to_string(cell_count()) +
                                                     " midpoints rendered here");
}

// A shard.yaml naming a file outside its shard is refused before anything is copied there.
TEST(Shards, AFileOutsideTheShardIsRefused) {
  const fs::path outside = scratch("outside.exr");
  for (const std::string path : {"../outside.exr", "/etc/passwd"}) {
    const fs::path evil = filtered_shard(1, "evil", [](const std::string&) { return true; });
    std::string text = read_bytes(evil / db::kShardFile);
    text = std::regex_replace(text, std::regex("images/[^:]*:"), path + ":",
                              std::regex_constants::format_first_only);
    write_bytes(evil / db::kShardFile, text);
    try {
      merge({shards()[0], evil}, "merged-evil");
      ADD_FAILURE() << "merged a shard naming " << path;
    } catch (const DatabaseError& e) {
      EXPECT_NE(std::string(e.what()).find("'" + path + "' is not a path inside the shard"),
                std::string::npos)
          << e.what();
    }
    EXPECT_FALSE(fs::exists(outside));
  }
}

}  // namespace
}  // namespace brdfnav
