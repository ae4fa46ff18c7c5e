// Bad input through the real CLI (docs/RELIABILITY.md): every case exits with the status of its
// kind of failure (never a signal), prints a message that names what is wrong and where (the file,
// key or option), prints nothing on stdout and leaves no output file. What other suites already
// check through the CLI is not repeated: a missing --env file, a corrupt table (checksum mismatch),
// bad inline specs and non-finite directions (test_cli_eval, test_cli_precompute, test_cli_render).
// The suite builds one smoke-profile database and damages copies of it (it is registered WHOLE).
#include "app/cli_runner.h"

#include <brdfnav/precompute/database.h>
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <unistd.h>

#include <limits>
#include <vector>

namespace brdfnav::test {
namespace {

namespace fs = std::filesystem;

// Exit statuses by the kind of failure (app/main.cpp): 2 a wrong argument, 3 a malformed
// material or spec, 4 a file that cannot be read or used, 5 a damaged database.
void expect_rejected(const CliResult& r, int status, const std::vector<std::string>& phrases) {
  EXPECT_EQ(r.exit_code, status) << (r.exit_code >= 128 ? "killed by a signal: " : "") << r.err;
  for (const std::string& p : phrases)
    EXPECT_NE(r.err.find(p), std::string::npos) << "no '" << p << "' in: " << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

void replace_in_file(const fs::path& path, const std::string& from, const std::string& to) {
  std::string text = read_text(path);
  const std::size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from << " not in " << path;
  write_bytes(path, text.replace(at, from.size(), to));
}

class BadInputs : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fs::temp_directory_path() / ("brdfnav_bad_inputs_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
    const CliResult r = run_cli("precompute --profile smoke --res 8 --out " + db().string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }

  static fs::path file(const std::string& name) { return root_ / name; }
  static fs::path db() { return file("db"); }
  // A fresh copy of the database, to damage.
  static fs::path copy_of_db(const std::string& name) {
    const fs::path copy = file(name);
    fs::copy(db(), copy, fs::copy_options::recursive);
    return copy;
  }
  // An empty directory for the output of one case; it must stay empty.
  static fs::path out_dir(const std::string& name) {
    const fs::path dir = file("out_" + name);
    fs::create_directories(dir);
    return dir;
  }
  static void expect_empty(const fs::path& dir) {
    for (const auto& e : fs::directory_iterator(dir)) ADD_FAILURE() << "left behind: " << e.path();
  }

  // A w x h float map of `channels` channels, every value `fill` except texel (1, 1) = `special`.
  static fs::path write_map(const std::string& name, int w, int h, int channels, float fill,
                            float special, const char* type = "float") {
    const fs::path path = file(name);
    std::vector<float> pixels(static_cast<std::size_t>(w) * h * channels, fill);
    for (int c = 0; c < channels; ++c) pixels[(std::size_t(w) + 1) * channels + c] = special;
    auto out = OIIO::ImageOutput::create(path.string());
    EXPECT_TRUE(out && out->open(path.string(), OIIO::ImageSpec(w, h, channels, type)));
    EXPECT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
    out->close();
    return path;
  }
  // `brdfnav render` of a small image under `env` into a fresh directory.
  static CliResult render_under(const fs::path& env, const fs::path& out) {
    return run_cli("render --material ward --res 8 --env " + env.string() + " --out " +
                   (out / "ward.exr").string());
  }

  static inline fs::path root_;
};

TEST_F(BadInputs, EnvironmentMapsThatCannotBeUsed) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const fs::path truncated = write_map("truncated.exr", 64, 32, 3, 1.f, 1.f);
  fs::resize_file(truncated, fs::file_size(truncated) / 2);
  const fs::path garbage = file("garbage.exr");
  write_bytes(garbage, std::string("\x76\x2f\x31\x01 not an image\0\xff", 20));
  // A Radiance header that claims 80000 x 40000 texels, in 60 bytes.
  const fs::path huge = file("huge.hdr");
  write_bytes(huge, "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 40000 +X 80000\n\x02\x02");
  const struct {
    fs::path env;
    std::vector<std::string> phrases;
  } cases[] = {
      {write_map("nan.exr", 16, 8, 3, 1.f, nan),
       {"1 texel(s) are NaN or infinite", "--sanitize-env"}},
      {write_map("inf.exr", 16, 8, 3, 1.f, inf), {"NaN or infinite"}},
      {write_map("square.exr", 8, 8, 3, 1.f, 1.f), {"is 8x8", "exactly 2:1"}},
      {write_map("two_channels.exr", 16, 8, 2, 1.f, 1.f), {"has 2 channel(s)"}},
      {truncated, {"cannot read"}},
      {garbage, {"cannot read"}},
      {huge, {"is 80000x40000", "up to 16384x8192"}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.env.filename().string());
    const fs::path out = out_dir(c.env.filename().string());
    std::vector<std::string> phrases = c.phrases;
    phrases.push_back(c.env.string() + ": ");
    expect_rejected(render_under(c.env, out), 4, phrases);
    expect_empty(out);
  }
}

// Not errors, by design (env_map.h): negative texels are clamped, and --sanitize-env zeroes
// NaN/Inf ones; each says so once, naming the file.
TEST_F(BadInputs, NegativeOrSanitizedTexelsRenderWithOneWarning) {
  const fs::path negative = write_map("negative.exr", 16, 8, 3, -0.5f, 2.f);
  CliResult r = render_under(negative, out_dir("negative"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: " + negative.string() + ": clamped 127 texel(s)"),
            std::string::npos)
      << r.err;
  const fs::path nan =
      write_map("nan_sanitized.exr", 16, 8, 3, 1.f, std::numeric_limits<float>::quiet_NaN());
  r = run_cli("render --material ward --res 8 --sanitize-env --env " + nan.string() + " --out " +
              (out_dir("sanitized") / "ward.exr").string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find(nan.string() + ": 1 texel(s) are NaN or infinite; set to 0"),
            std::string::npos)
      << r.err;
}

// A merge reloads the map as the shards' build loaded it: shards of a --sanitize-env build merge
// into the database a single --sanitize-env build makes (the merge once reloaded the map without
// sanitizing and refused it), and a map changed since the shards were made is refused by name.
TEST_F(BadInputs, ShardsOfASanitizedMapMerge) {
  const fs::path nan =
      write_map("nan_shards.exr", 16, 8, 3, 1.f, std::numeric_limits<float>::quiet_NaN());
  const fs::path dir = out_dir("sanitized_shards");
  const std::string build =
      "precompute --profile smoke --res 8 --sanitize-env --env " + nan.string();
  for (int i = 0; i < 2; ++i) {
    const CliResult r = run_cli(build + " --shard " + std::to_string(i) + "/2 --out " +
                                (dir / ("shard" + std::to_string(i))).string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const std::string merge =
      "precompute merge " + (dir / "shard0").string() + " " + (dir / "shard1").string() + " --out ";
  CliResult r = run_cli(merge + (dir / "merged").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_cli(build + " --out " + (dir / "single").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_text(dir / "merged" / "manifest.yaml"),
            read_text(dir / "single" / "manifest.yaml"));

  write_map("nan_shards.exr", 16, 8, 3, 2.f, std::numeric_limits<float>::quiet_NaN());
  r = run_cli(merge + (dir / "merged_again").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find(nan.string() + ": changed since the database was built"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("shard.yaml"), std::string::npos) << r.err;
}

// Every reader of a database loads its map as the build did: a database built with --sanitize-env
// from a map with NaN texels exports in every format (MaterialX and Cycles render the equivalent
// to state its residual; they once reloaded the map without sanitizing and exited 4), and once
// the map has changed, an export that renders is refused naming the map and the manifest.
TEST_F(BadInputs, ADatabaseOfASanitizedMapExportsInEveryFormat) {
  const fs::path nan =
      write_map("nan_export.exr", 16, 8, 3, 1.f, std::numeric_limits<float>::quiet_NaN());
  const fs::path db = out_dir("sanitized_export") / "db";
  CliResult r = run_cli("precompute --profile smoke --res 8 --sanitize-env --env " + nan.string() +
                        " --out " + db.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string exports = "export --db " + db.string() + " --material ward --out ";
  for (const std::string format : {"yaml", "materialx", "cycles"}) {
    const fs::path out = out_dir("sanitized_export") / ("ward." + format);
    r = run_cli(exports + out.string() + " --format " + format);
    EXPECT_EQ(r.exit_code, 0) << format << ": " << r.err;
    EXPECT_TRUE(fs::is_regular_file(out)) << format;
  }
  write_map("nan_export.exr", 16, 8, 3, 2.f, std::numeric_limits<float>::quiet_NaN());
  r = run_cli(exports + (out_dir("sanitized_export") / "changed.mtlx").string() +
              " --format materialx");
  EXPECT_EQ(r.exit_code, 5) << r.err;
  EXPECT_NE(r.err.find(nan.string() + ": changed since the database was built"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find((db / "manifest.yaml").string()), std::string::npos) << r.err;
}

TEST_F(BadInputs, DamagedDatabases) {
  const std::string manifest = "manifest.yaml";
  struct Case {
    std::string name;
    std::vector<std::string> phrases;
  };
  std::vector<Case> cases;
  const auto damaged = [&](const std::string& name, std::vector<std::string> phrases) {
    cases.push_back({name, std::move(phrases)});
    return copy_of_db(name);
  };

  fs::path d =
      damaged("version", {"manifest.yaml: database format version 4", "reads versions 1 to 3"});
  replace_in_file(d / manifest, "brdfnav_database: 3", "brdfnav_database: 4");

  d = damaged("missing_file", {"images/ward/00001.exr: missing"});
  fs::remove(d / "images/ward/00001.exr");

  d = damaged("missing_key", {"manifest.yaml: missing key 'components'"});
  replace_in_file(d / manifest, "components: 24\n", "");

  d = damaged("manifest_is_a_directory", {"manifest.yaml: is a directory"});
  fs::remove(d / manifest);
  fs::create_directory(d / manifest);

  d = damaged("not_yaml", {"manifest.yaml: line 1"});
  write_bytes(d / manifest, "{[: ::\n");

  // A table cut short whose checksum someone "repaired" in the manifest.
  d = damaged("truncated_table", {"embedding/ward.f32: table size does not match its header"});
  const std::string sha = file_sha1(d / "embedding/ward.f32");
  fs::resize_file(d / "embedding/ward.f32", fs::file_size(d / "embedding/ward.f32") - 4);
  replace_in_file(d / manifest, sha, file_sha1(d / "embedding/ward.f32"));

  // Files of another database: an image, then the whole manifest. The second database differs
  // only in its resolution, so that both take the same time to build as the first.
  const fs::path other = file("other_db");
  ASSERT_EQ(run_cli("precompute --profile smoke --res 9 --out " + other.string()).exit_code, 0);
  d = damaged("swapped_image", {"images/ward/00003.exr: checksum mismatch"});
  fs::copy_file(other / "images/ward/00003.exr", d / "images/ward/00003.exr",
                fs::copy_options::overwrite_existing);
  d = damaged("swapped_repaired", {"images/ward/00003.exr: image is 9x9, the manifest says 8"});
  fs::copy_file(other / "images/ward/00003.exr", d / "images/ward/00003.exr",
                fs::copy_options::overwrite_existing);
  replace_in_file(d / manifest, file_sha1(db() / "images/ward/00003.exr"),
                  file_sha1(d / "images/ward/00003.exr"));
  d = damaged("swapped_manifest", {"checksum mismatch"});
  fs::copy_file(other / manifest, d / manifest, fs::copy_options::overwrite_existing);

  // A grid value edited in the manifest (which no checksum covers): the images say otherwise.
  d = damaged("edited_grid", {"rendered at eta = 4, the manifest's grid says 4.5"});
  replace_in_file(d / manifest, "eta: [1.5, 4]", "eta: [1.5, 4.5]");

  // Found by tests/fuzz: a manifest naming a file outside the database (reading /dev/zero never
  // ended), and grids far larger than the files listed (billions of names).
  d = damaged("lists_dev_zero", {"manifest.yaml: lists the file /dev/zero"});
  replace_in_file(d / manifest, "files:\n", "files:\n  /dev/zero: " + sha + "\n");
  d = damaged("huge_grid", {"manifest.yaml: models.he has more nodes than the manifest lists"});
  std::string axis = "[1.2";
  for (int i = 1; i < 300; ++i) axis += ", " + std::to_string(1.2 + i * 0.01);
  replace_in_file(d / manifest, "eta: [1.5, 4]", "eta: " + axis + "]");
  replace_in_file(d / manifest, "tau: [2, 128]", "tau: [2, 3, 4, 5, 6, 7, 8, 9, 10, 128]");

  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    std::vector<std::string> phrases = c.phrases;
    phrases.push_back(file(c.name).string() + "/");  // the message names a file of the database
    expect_rejected(run_cli("db-info " + file(c.name).string()), 5, phrases);
  }
  // Commands that write a file write nothing from a damaged database.
  const fs::path out = out_dir("export");
  expect_rejected(run_cli("export --db " + file("version").string() + " --material ward --out " +
                          (out / "ward.yaml").string()),
                  5, {"format version 4"});
  expect_empty(out);
}

// The metric is defined on radiance: linear floating-point pixels, finite and not negative, read
// from OpenEXR. An 8-bit file is display-encoded; read as radiance it would give a plausible,
// wrong distance.
TEST_F(BadInputs, ImagesThatAreNotRadiance) {
  const std::string good = write_map("good.exr", 4, 4, 4, 1.f, 1.f).string();
  const std::string nan =
      write_map("nan.exr", 4, 4, 4, 1.f, std::numeric_limits<float>::quiet_NaN()).string();
  const std::string negative = write_map("negative.exr", 4, 4, 4, 1.f, -1.f).string();
  const std::string display = write_map("display.png", 4, 4, 4, 1.f, 1.f).string();
  const std::string integer = write_map("integer.exr", 4, 4, 4, 1.f, 1.f, "uint").string();
  ASSERT_EQ(run_cli("distance " + good + " " + good).exit_code, 0);
  expect_rejected(run_cli("distance " + good + " " + nan), 4, {nan + ": pixel (1, 1) has R"});
  expect_rejected(run_cli("distance " + negative + " " + good), 4,
                  {negative + ": pixel (1, 1) has R = -1"});
  expect_rejected(run_cli("distance " + good + " " + display), 4,
                  {display + ": not an OpenEXR file"});
  expect_rejected(run_cli("distance " + integer + " " + good), 4,
                  {integer + ": holds uint32 pixels", "linear floating point"});
}

TEST_F(BadInputs, MaterialFiles) {
  const std::string valid =
      "brdfnav_material: 1\nmodel: ward\nparams: {alpha_x: 0.1, alpha_y: 0.05}\n"
      "rho_d: [0.2, 0.2, 0.2]\nrho_s: [0.04, 0.04, 0.04]\ncolorspace: lin_rec709\n";
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string text = valid;
    return text.replace(text.find(from), from.size(), to);
  };
  const struct {
    std::string name, text, phrase;
  } cases[] = {
      {"unknown_key", valid + "gloss: 0.5\n", ":7: gloss: unknown key"},
      {"wrong_type", with("alpha_x: 0.1", "alpha_x: rough"),
       ":3: params.alpha_x: expected a number"},
      {"list_for_params", with("{alpha_x: 0.1, alpha_y: 0.05}", "[0.1, 0.05]"),
       ":3: params: expected a mapping"},
      {"out_of_range", with("alpha_y: 0.05", "alpha_y: 7"), ":3: params.alpha_y: 7 is outside"},
      {"nan", with("alpha_y: 0.05", "alpha_y: .nan"), ":3: params.alpha_y: must be finite"},
      {"huge", with("alpha_x: 0.1", "alpha_x: 1e300"),
       ":3: params.alpha_x: 1.0000000000000001e+300 is outside"},
      {"beyond_double", with("alpha_x: 0.1", "alpha_x: 1e999"),
       ":3: params.alpha_x: expected a number, got '1e999'"},
      {"huge_colour", with("[0.04, 0.04, 0.04]", "[0.04, 1e12, 0.04]"),
       ":5: rho_s: component 1 = 1000000000000 is outside [0, 10]"},
      {"schema_2", with("brdfnav_material: 1", "brdfnav_material: 2"),
       ":1: brdfnav_material: unsupported schema version 2"},
      // Found by tests/fuzz: yaml-cpp's LoadAll looped on a stray ',' until memory ran out.
      {"stray_comma", ",", ":1: syntax error: unexpected ','"},
      // Found by tests/fuzz: YAML cannot hold this name, so a written material did not read back.
      {"colorspace_bytes", with("lin_rec709", "\"lin\\x01\""),
       ":6: colorspace: byte 3 is not allowed"},
      {"empty", "", ":1: material: the file is empty"},
      {"binary",
       std::string("\x7f"
                   "ELF\x02\x01\x01\0\0\xff\xfe",
                   11),
       ":1: syntax error"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const fs::path path = file(c.name + ".yaml");
    write_bytes(path, c.text);
    expect_rejected(run_cli("eval --material " + path.string() + " --wi 0,0,1 --wo 0,0,1"), 3,
                    {path.string() + c.phrase});
  }
  expect_rejected(run_cli("eval --material " + root_.string() + " --wi 0,0,1 --wo 0,0,1"), 4,
                  {root_.string() + ": is a directory"});
}

TEST_F(BadInputs, InlineSpecsAndDirections) {
  const struct {
    std::string args, phrase;
  } cases[] = {
      {"--material ward:alpha_x --wi 0,0,1 --wo 0,0,1", "'alpha_x': expected key=value"},
      {"--material ward:alpha_x=nan --wi 0,0,1 --wo 0,0,1", "key 'alpha_x': value must be finite"},
      {"--material ward:alpha_x=1e999 --wi 0,0,1 --wo 0,0,1",
       "key 'alpha_x': '1e999' is not a number"},
      {"--material he:tau=1e300 --wi 0,0,1 --wo 0,0,1",
       "params.tau: 1.0000000000000001e+300 is outside"},
      {"--material ward:alpha_x=0.1,alpha_x=0.2 --wi 0,0,1 --wo 0,0,1",
       "key 'alpha_x' is given twice"},
      {"--material lafortune:rho_s=0.1/0.2/x --wi 0,0,1 --wo 0,0,1",
       "key 'rho_s': 'x' is not a number"},
      {"--material ward:colorspace= --wi 0,0,1 --wo 0,0,1", "colorspace: must not be empty"},
      {"--material \"$(printf 'ward:colorspace=a\\377')\" --wi 0,0,1 --wo 0,0,1",
       "colorspace: byte 1"},
      {"--material ward --wi 0,0,0 --wo 0,0,1", "--wi: direction has zero length"},
      {"--material ward --wi 0,0,1 --wo 0,0,0", "--wo: direction has zero length"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args);
    const bool direction = c.phrase.rfind("--w", 0) == 0;
    expect_rejected(run_cli("eval " + c.args), direction ? 2 : 3, {c.phrase});
  }
}

// Numeric options of the long-running commands are range-checked before any work starts: a
// report directory or a database is never opened for a run that cannot be valid.
TEST_F(BadInputs, NumericOptionsOutOfRange) {
  const std::string report = file("report_never_written").string();
  const struct {
    std::string args, phrase;
  } cases[] = {
      {"validate --fit-samples 0 --out " + report, "--fit-samples: Value 0 not in range 1 to"},
      {"validate --pairs 1 --out " + report, "--pairs: Value 1 not in range 2 to"},
      {"validate --res 4 --out " + report, "--res: Value 4 not in range 8 to"},
      {"bench load --db " + db().string() + " --threads 0", "--threads: Value 0 not in range"},
      {"bench load --db " + db().string() + " --queries x", "--queries: Value x not in range"},
      {"bench navigator --db " + db().string() + " --materials 0",
       "--materials: Value 0 not in range"},
      {"bench navigator --db " + db().string() + " --cache-mib 0",
       "--cache-mib: Value 0 not in range"},
      {"bench render --repeats 0", "--repeats"},
      {"bench fits --per-model 0", "--per-model"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args);
    expect_rejected(run_cli(c.args), 2, {c.phrase});
  }
  EXPECT_FALSE(fs::exists(report));
}

}  // namespace
}  // namespace brdfnav::test
