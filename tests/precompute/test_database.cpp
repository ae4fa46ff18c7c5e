#include <brdfnav/navigator/blend.h>
#include <brdfnav/navigator/database_format.h>
#include <brdfnav/navigator/image_input.h>
#include <brdfnav/precompute/database.h>
#include <brdfnav/renderer/image_output.h>
#include <brdfnav/renderer/render.h>
#include <brdfnav/studies/fit_study.h>
#include <gtest/gtest.h>

#include "database_fixture.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>

namespace brdfnav {
namespace {

namespace fs = std::filesystem;
using namespace test;

struct Interrupted {};

// A copy of the reference database to damage.
fs::path copy_of_reference(const std::string& name) {
  const fs::path dir = scratch(name);
  fs::copy(fixture().db, dir, fs::copy_options::recursive);
  return dir;
}

// Runs `open` and returns its error message (empty when it succeeds).
std::string open_error(const fs::path& dir) {
  try {
    Database::open(dir);
  } catch (const DatabaseError& e) {
    return e.what();
  }
  return "";
}

void replace_in_file(const fs::path& p, const std::string& from, const std::string& to) {
  std::string text = read_bytes(p);
  const std::size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  write_bytes(p, text.replace(at, from.size(), to));
}

TEST(Database, OpensWithTheManifestAndTablesOfItsProfile) {
  const Database db = Database::open(fixture().db);
  const Manifest& m = db.manifest();
  EXPECT_EQ(m.format_version, kDatabaseFormatVersion);
  EXPECT_EQ(m.profile, "unit");
  EXPECT_EQ(m.resolution, 8);
  EXPECT_EQ(m.scene, "sphere");
  EXPECT_EQ(m.env_pixel_sha1, fixture().env.pixel_sha1());
  EXPECT_EQ(m.q_nodes, diffuse_fraction_nodes(5));
  ASSERT_EQ(m.grids.size(), 3u);
  EXPECT_EQ(m.grids[1].grid.axis(0), (std::vector<double>{0.02, 0.3}));
  EXPECT_EQ(db.embedding(ModelId::he), nullptr);
  ASSERT_NE(db.embedding(ModelId::ward), nullptr);
  const ConversionTable* t = db.conversion(ModelId::ward, ModelId::blinn_phong);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->nodes.size(), 4u);
  EXPECT_EQ(db.conversion(ModelId::ward, ModelId::ward), nullptr);
  // The quality its images were made at, every knob in the table's order, reads back as it was.
  ASSERT_EQ(m.render_quality.size(), std::size(kQualityKnobs));
  for (std::size_t k = 0; k < m.render_quality.size(); ++k)
    EXPECT_EQ(m.render_quality[k].first, kQualityKnobs[k].name);
  const RenderQuality made = tiny_profile().quality, read = quality_from_record(m.render_quality);
  for (const QualityKnob& knob : kQualityKnobs)
    if (knob.real)
      EXPECT_EQ(read.*(knob.real), made.*(knob.real)) << knob.name;
    else
      EXPECT_EQ(read.*(knob.integer), made.*(knob.integer)) << knob.name;
}

// The stored embedding reproduces the metric between the stored images (lossless basis, nodes on
// the grid), so the tables are read back in the layout they were written in.
TEST(Database, EmbeddingReproducesTheMetricOfItsImages) {
  const Database db = Database::open(fixture().db);
  const Image diffuse = read_image(db.diffuse_path());
  const ModelEmbedding& ward = *db.embedding(ModelId::ward);
  const ModelEmbedding& phong = *db.embedding(ModelId::blinn_phong);
  Material a = default_material(ModelId::ward), b = default_material(ModelId::blinn_phong);
  a.params = ward.grid().node_values(2), b.params = phong.grid().node_values(1);
  a.rho_d = b.rho_d = Rgb::Zero(), a.rho_s = b.rho_s = Rgb::Ones();
  const double exact = image_distance(read_image(db.image_path(ModelId::ward, 2)),
                                      read_image(db.image_path(ModelId::blinn_phong, 1)));
  const double embedded = embedding_distance(ward.embed(a), phong.embed(b));
  EXPECT_NEAR(embedded, exact, 1e-4 * exact);
}

// Each conversion stores a fit inside the target's parameter ranges and the embedded distance
// between the source node and that fit.
TEST(Database, ConversionsAreFitsWithTheirImageDistance) {
  const Database db = Database::open(fixture().db);
  const ModelEmbedding& from = *db.embedding(ModelId::lafortune);
  const ModelEmbedding& to = *db.embedding(ModelId::blinn_phong);
  const ConversionTable& t = *db.conversion(ModelId::lafortune, ModelId::blinn_phong);
  for (std::size_t n = 0; n < t.nodes.size(); ++n) {
    const Conversion& c = t.nodes[n];
    ASSERT_EQ(c.params.size(), 1u);
    EXPECT_GE(c.params[0], 2.0);
    EXPECT_LE(c.params[0], 80000.0);
    EXPECT_GE(c.relative_error, 0.0);
    Material a = default_material(ModelId::lafortune), b = default_material(ModelId::blinn_phong);
    a.params = from.grid().node_values(n), b.params = c.params;
    a.rho_d = b.rho_d = Rgb::Zero(), a.rho_s = Rgb::Ones(), b.rho_s = c.scale;
    // The stored params are float32: the distance is recomputed from rounded parameters.
    EXPECT_NEAR(embedding_distance(from.embed(a), to.embed(b)), c.image_distance, 1e-3);
  }
  // cz = 1/sqrt(3) is exactly a Phong lobe: Blinn-Phong fits it far better than the tilted lobe.
  EXPECT_LT(t.nodes[1].relative_error, t.nodes[0].relative_error);
}

TEST(Database, ImageMetricFitRecoversAMaterialOfItsOwnModel) {
  const Database db = Database::open(fixture().db);
  const ModelEmbedding& ward = *db.embedding(ModelId::ward);
  Material m = default_material(ModelId::ward);
  m.params = {0.05, 0.12};
  m.rho_d = Rgb::Zero();
  m.rho_s = Rgb(0.5, 0.3, 0.2);
  const Eigen::VectorXf target = ward.embed(m);
  // Started at the wrong corner of the grid: the fit must find its way back.
  const ImageFit fit = fit_in_embedding(ward, target, {0.3, 0.02});
  EXPECT_LT(fit.distance, 1e-3 * target.norm());
  EXPECT_NEAR(std::log(fit.material.params[0]), std::log(0.05), 0.02);
  EXPECT_NEAR(std::log(fit.material.params[1]), std::log(0.12), 0.02);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(fit.material.rho_s[c], m.rho_s[c], 0.01 * m.rho_s[c]);
}

TEST(Database, ImageMetricFitsAreNoFartherThanTheBrdfSpaceFits) {
  const Database db = Database::open(fixture().db);
  const FitStudy study = fit_study(db, 4);
  ASSERT_EQ(study.pairs.size(), 6u);  // three models, every ordered pair
  for (const FitPairStudy& p : study.pairs) {
    EXPECT_EQ(p.samples, 4);
    // The BRDF-space fit is one of the image fit's starts.
    EXPECT_LE(p.image_fit, p.brdf_fit * (1 + 1e-5) + 1e-7) << model_info(p.from).name;
    EXPECT_GE(p.between, 0.0);
  }
  EXPECT_GE(study.ratio_median, 1 - 1e-5);
  EXPECT_GE(study.ratio_p90, study.ratio_median);
}

// The blend check holds, per cell, the distance between the blend of the node images and an
// exact render at the cell's midpoint (rho_d = 0, rho_s = 1), rendered as exact thumbnails are.
TEST(Database, RecordsTheBlendCheckOfEveryCell) {
  const Database db = Database::open(fixture().db);
  const Image diffuse = read_image(db.diffuse_path());
  RenderOptions options;
  options.quality = tiny_profile().quality;
  Renderer renderer(fixture().env, fixture().scene, 8, options);
  for (const ProfileGrid& g : db.manifest().grids) {
    const std::string model(model_info(g.model).name);
    ASSERT_TRUE(db.manifest().files.contains(db::blend_check_file(g.model))) << model;
    std::vector<Image> nodes;
    for (std::size_t n = 0; n < g.grid.node_count(); ++n)
      nodes.push_back(read_image(db.image_path(g.model, n)));
    for (std::size_t c = 0; c < g.grid.cell_count(); ++c) {
      Material m = default_material(g.model);
      m.params = g.grid.cell_midpoint(c);
      m.rho_d = Rgb::Zero(), m.rho_s = Rgb::Ones();
      const std::vector<ParamGrid::Corner> corners = g.grid.cubic_corners(m.params);
      std::vector<const Image*> images;
      for (const ParamGrid::Corner& k : corners) images.push_back(&nodes[k.node]);
      const double expected = image_distance(
          blend_images(diffuse, corners, images, m.rho_d, m.rho_s), renderer.render(m));
      EXPECT_GT(expected, 0.0) << model;  // between nodes the blend is not the render
      // Any material of the cell gets its cell's check, whatever its colours.
      m.rho_d = Rgb(0.2, 0.1, 0.05);
      const std::optional<double> recorded = db.blend_error(m);
      ASSERT_TRUE(recorded.has_value()) << model;
      EXPECT_NEAR(*recorded, expected, 1e-6 + 1e-5 * expected) << model << " cell " << c;
    }
  }
  // On a node in every parameter the blend is the node's image, whatever its cells' checks.
  for (const ProfileGrid& g : db.manifest().grids) {
    const std::string model(model_info(g.model).name);
    const std::size_t node = g.grid.node_count() / 2;
    Material m = default_material(g.model);
    m.params = g.grid.node_values(node);
    m.rho_d = Rgb::Zero(), m.rho_s = Rgb::Ones();
    EXPECT_EQ(db.blend_error(m), 0.0) << model;
    const std::vector<ParamGrid::Corner> corners = g.grid.cubic_corners(m.params);
    ASSERT_EQ(corners.size(), 1u) << model;
    EXPECT_EQ(corners[0].node, node) << model;
    // Just off it, a millionth of a cell along the first parameter: its cell's check.
    const std::vector<double>& axis = g.grid.axis(0);
    const std::size_t i = std::min(g.grid.multi_index(node)[0], axis.size() - 2);
    m.params[0] += 1e-6 * (axis[i + 1] - axis[i]) * (i == g.grid.multi_index(node)[0] ? 1 : -1);
    EXPECT_GT(db.blend_error(m).value_or(0), 0.0) << model;
  }
  EXPECT_FALSE(db.blend_error(default_material(ModelId::he)).has_value());  // not in the database
  // Beyond the grid (Ward's alpha_x from 0.02 to 0.3) the blend is the edge's: no cell vouches.
  Material beyond = default_material(ModelId::ward);
  beyond.params = {0.5, 0.1};
  EXPECT_FALSE(db.blend_error(beyond).has_value());
  beyond.params = {0.3, 0.1};  // on the edge: the last cell's
  EXPECT_TRUE(db.blend_error(beyond).has_value());
}

// The images are stored as ExrPixels::half_raw, the diffuse one and every node's, which the
// thumbnails read (image_output.h says why).
TEST(Database, StoresItsImagesAsUncompressedHalves) {
  const Database db = Database::open(fixture().db);
  std::vector<fs::path> images{db.diffuse_path()};
  for (const ProfileGrid& g : db.manifest().grids)
    for (std::size_t n = 0; n < g.grid.node_count(); ++n)
      images.push_back(db.image_path(g.model, n));
  for (const fs::path& path : images) {
    auto in = OIIO::ImageInput::open(path.string());
    ASSERT_TRUE(in) << path;
    EXPECT_EQ(in->spec().format, OIIO::TypeDesc::HALF) << path;
    EXPECT_EQ(in->spec().get_string_attribute("compression"), "none") << path;
  }
}

// A database built before the check opens, and vouches for no blend.
TEST(Database, OpensWithoutBlendChecks) {
  const fs::path dir = copy_of_reference("no_checks");
  std::ifstream in(dir / "manifest.yaml");
  std::string manifest, line;
  while (std::getline(in, line))
    if (line.find("previews/") == std::string::npos) manifest += line + "\n";
  in.close();
  write_bytes(dir / "manifest.yaml", manifest);
  fs::remove_all(dir / "previews");
  const Database db = Database::open(dir);
  EXPECT_FALSE(db.blend_error(default_material(ModelId::ward)).has_value());
}

// A blend check holds for the spline it was measured with. Version 2 databases measured theirs
// with Catmull-Rom in grid coordinates, before the spline followed graded nodes and quadratic
// ends: such a database opens, its embedding and images as they were, but vouches for no blend.
TEST(Database, IgnoresTheBlendCheckOfAnEarlierSpline) {
  const fs::path dir = copy_of_reference("version_2");
  replace_in_file(dir / "manifest.yaml",
                  "brdfnav_database: " + std::to_string(kDatabaseFormatVersion),
                  "brdfnav_database: 2");
  const Database db = Database::open(dir), current = Database::open(fixture().db);
  EXPECT_EQ(db.manifest().format_version, 2);
  for (ModelId id : {ModelId::blinn_phong, ModelId::ward, ModelId::lafortune}) {
    EXPECT_FALSE(current.blend_checks(id).empty());
    EXPECT_TRUE(db.blend_checks(id).empty());
    EXPECT_FALSE(db.blend_error(default_material(id)).has_value());
    EXPECT_EQ(db.embedding(id)->coefficients(), current.embedding(id)->coefficients());
  }
}

// A check of another grid's shape, or with a distance that is not one, is refused by name.
TEST(Database, RejectsABlendCheckOfTheWrongShapeOrValue) {
  const fs::path dir = copy_of_reference("bad_check");
  const fs::path check = dir / db::blend_check_file(ModelId::ward);
  const auto replace = [&](const db::Table& t) {
    const std::string old_sha = file_sha1(check);
    db::write_table(check, t);
    replace_in_file(dir / "manifest.yaml", old_sha, file_sha1(check));
  };
  replace({2, 1, {0.001f, 0.002f}});  // the grid has one cell
  std::string error = open_error(dir);
  EXPECT_NE(error.find("previews/ward.f32"), std::string::npos) << error;
  replace({1, 1, {std::nanf("")}});
  error = open_error(dir);
  EXPECT_NE(error.find("previews/ward.f32: cell 0"), std::string::npos) << error;
  replace({1, 1, {-0.5f}});
  EXPECT_NE(open_error(dir).find("not a finite value >= 0"), std::string::npos);
}

TEST(Database, RejectsAFlippedByteNamingTheFile) {
  const fs::path dir = copy_of_reference("corrupt");
  std::string bytes = read_bytes(dir / "embedding/ward.f32");
  bytes[bytes.size() / 2] ^= 0x01;
  write_bytes(dir / "embedding/ward.f32", bytes);
  const std::string error = open_error(dir);
  EXPECT_NE(error.find("embedding/ward.f32"), std::string::npos) << error;
  EXPECT_NE(error.find("checksum"), std::string::npos) << error;
}

TEST(Database, RejectsAnotherFormatVersion) {
  const fs::path dir = copy_of_reference("version");
  const std::string current = "brdfnav_database: " + std::to_string(kDatabaseFormatVersion);
  for (int version : {kOldestDatabaseFormatVersion - 1, kDatabaseFormatVersion + 1}) {
    const std::string other = "brdfnav_database: " + std::to_string(version);
    replace_in_file(dir / "manifest.yaml", current, other);
    const std::string error = open_error(dir);
    EXPECT_NE(error.find("manifest.yaml"), std::string::npos) << error;
    EXPECT_NE(error.find("format version " + std::to_string(version)), std::string::npos) << error;
    replace_in_file(dir / "manifest.yaml", other, current);
  }
}

// Format version 1 stored each model's embedding as the k x columns matrix (a column's
// coefficients strided); version 2 stores one row per column and maps it. A database of version
// 1 still opens, to the same coefficients.
TEST(Database, OpensAVersionOneDatabaseToTheSameEmbedding) {
  const fs::path dir = copy_of_reference("version1");
  const Database current = Database::open(fixture().db);
  for (const ProfileGrid& g : current.manifest().grids) {
    const fs::path file = dir / db::coefficients_file(g.model);
    const auto [rows, cols] = db::read_table_shape(file);
    const db::Table v2 = db::read_table(file, rows, cols);
    db::Table v1{v2.cols, v2.rows, std::vector<float>(v2.values.size())};
    for (std::uint32_t r = 0; r < v2.rows; ++r)
      for (std::uint32_t c = 0; c < v2.cols; ++c) v1.values[c * v1.cols + r] = v2.at(r, c);
    const std::string old_sha = file_sha1(file);
    db::write_table(file, v1);
    replace_in_file(dir / "manifest.yaml", old_sha, file_sha1(file));
  }
  replace_in_file(dir / "manifest.yaml",
                  "brdfnav_database: " + std::to_string(kDatabaseFormatVersion),
                  "brdfnav_database: 1");
  const Database old = Database::open(dir);
  EXPECT_EQ(old.manifest().format_version, 1);
  for (const ProfileGrid& g : current.manifest().grids) {
    const ModelEmbedding::Coefficients &a = current.embedding(g.model)->coefficients(),
                                       &b = old.embedding(g.model)->coefficients();
    ASSERT_EQ(a.rows(), b.rows());
    ASSERT_EQ(a.cols(), b.cols());
    EXPECT_TRUE(a == b) << model_info(g.model).name;
  }
}

// The mapped table is checked as a read one is: its header's shape, then its size.
TEST(Database, RefusesAnEmbeddingTableOfTheWrongShapeOrSize) {
  const fs::path dir = copy_of_reference("mapped");
  const Manifest m = Database::open(dir).manifest();
  const ProfileGrid& ward = m.grids[1];
  const fs::path file = dir / db::coefficients_file(ward.model);
  const auto [rows, cols] = db::read_table_shape(file);
  const db::Table table = db::read_table(file, rows, cols);
  const auto error = [&] {
    try {
      db::read_model_embedding(dir, m.q_nodes, m.components, ward, kDatabaseFormatVersion);
    } catch (const DatabaseError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  db::write_table(file, {cols, rows, table.values});  // transposed: version 1's shape
  EXPECT_NE(error().find("embedding/ward.f32: table is"), std::string::npos) << error();
  db::write_table(file, table);
  fs::resize_file(file, fs::file_size(file) - 4);
  EXPECT_NE(error().find("embedding/ward.f32: table size does not match"), std::string::npos)
      << error();
  write_bytes(file, "BNAV");
  EXPECT_NE(error().find("embedding/ward.f32: not a brdfnav table"), std::string::npos) << error();
}

// Releasing a mapped embedding's pages gives the process's copy back; the next read maps the
// same coefficients again.
TEST(Database, AnEmbeddingReadsTheSameAfterItsPagesAreReleased) {
  const Database db = Database::open(fixture().db);
  const ModelEmbedding& ward = *db.embedding(ModelId::ward);
  Material m = default_material(ModelId::ward);
  m.params = {0.05, 0.1};
  const Eigen::VectorXf before = ward.embed(m);
  ward.release_pages();
  EXPECT_TRUE(ward.embed(m) == before);
}

TEST(Database, RejectsAMissingFile) {
  const fs::path dir = copy_of_reference("missing");
  fs::remove(dir / "images/ward/00001.exr");
  const std::string error = open_error(dir);
  EXPECT_NE(error.find("images/ward/00001.exr: missing"), std::string::npos) << error;
  EXPECT_NE(open_error(scratch("nothing")).find("manifest.yaml: no such file"), std::string::npos);
}

// An image rendered under another environment does not belong, even with its checksum updated
// in the manifest (someone "repairing" a database by hand).
TEST(Database, RejectsAnImageFromAnotherEnvironment) {
  const fs::path dir = copy_of_reference("swapped");
  const EnvMap grey(8, 4, std::vector<float>(8 * 4 * 3, 0.5f), "synthetic grey");
  Renderer renderer(grey, fixture().scene, 8);
  const Material m = default_material(ModelId::ward);
  const fs::path swapped = dir / "images/ward/00003.exr";
  const std::string old_sha = file_sha1(swapped);
  write_exr(renderer.specular(make_lobe(m.model, m.params)), swapped,
            render_metadata(renderer, &m));
  std::string error = open_error(dir);
  EXPECT_NE(error.find("images/ward/00003.exr: checksum mismatch"), std::string::npos) << error;
  replace_in_file(dir / "manifest.yaml", old_sha, file_sha1(swapped));
  error = open_error(dir);
  EXPECT_NE(error.find("images/ward/00003.exr: rendered under another environment"),
            std::string::npos)
      << error;
}

TEST(Database, RefusesToOverwriteAnExistingDirectory) {
  const Fixture& f = fixture();
  EXPECT_THROW(precompute_database({tiny_profile(), f.db, false, 0, {}}, f.env, f.scene),
               DatabaseError);
}

// Starts the tiny build into `dir` and interrupts it once the first image is written.
void interrupt_after_the_first_image(const fs::path& dir) {
  const Fixture& f = fixture();
  PrecomputeRequest request{tiny_profile(), dir, false, 0, {}};
  request.observer.progress = [](std::string_view phase, std::size_t done, std::size_t) {
    if (phase == "render" && done == 1) throw Interrupted{};
  };
  EXPECT_THROW(precompute_database(request, f.env, f.scene), Interrupted);
}

// An interrupted build whose work directory holds some finished units (copied from the
// reference, as a build that got further would have left them) resumes to a database
// byte-identical to the uninterrupted one; a resume with other settings is refused.
TEST(Database, ResumeReusesFinishedWorkAndIsByteIdentical) {
  const Fixture& f = fixture();
  const fs::path dir = scratch("resumed"), work = dir.string() + ".partial";
  interrupt_after_the_first_image(dir);
  ASSERT_TRUE(fs::exists(work / "diffuse.exr"));
  ASSERT_FALSE(fs::exists(dir));
  fs::copy(f.db, work, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  for (const char* unit : {"manifest.yaml", "images/ward/00002.exr", "embedding/basis.f32",
                           "conversions/ward_to_lafortune.f32"})
    fs::remove(work / unit);

  PrecomputeRequest other{tiny_profile(), dir, true, 0, {}};
  other.profile.resolution = 16;
  try {
    precompute_database(other, f.env, f.scene);
    ADD_FAILURE() << "resumed with another resolution";
  } catch (const DatabaseError& e) {
    EXPECT_NE(std::string(e.what()).find("settings.yaml"), std::string::npos) << e.what();
  }

  std::vector<std::string> log;
  PrecomputeRequest resume{tiny_profile(), dir, true, 0, {}};
  resume.observer.log = [&](const std::string& line) { log.push_back(line); };
  precompute_database(resume, f.env, f.scene);
  EXPECT_FALSE(fs::exists(work));
  EXPECT_NE(std::find(log.begin(), log.end(), "render: 11 images, 10 reused"), log.end());
  EXPECT_EQ(tree(dir), tree(f.db));
}

// A work directory whose settings cannot be read is refused as what it is, naming the file, not
// taken for a build with other settings.
TEST(Database, ResumeNamesSettingsItCannotRead) {
  const Fixture& f = fixture();
  const fs::path dir = scratch("unreadable_settings"), work = dir.string() + ".partial";
  interrupt_after_the_first_image(dir);
  const fs::path settings = work / "settings.yaml";
  fs::remove(settings);
  fs::create_directory(settings);
  try {
    precompute_database({tiny_profile(), dir, true, 0, {}}, f.env, f.scene);
    ADD_FAILURE() << "resumed without reading its settings";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::io) << e.what();
    EXPECT_NE(std::string(e.what()).find(settings.string() + ": is a directory"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(dir));
}

// A build started by a brdfnav whose renderer made other images (another kRendererRevision) is
// not resumed: its images would not mix with this renderer's.
TEST(Database, ResumeRefusesTheWorkOfAnotherRendererRevision) {
  const Fixture& f = fixture();
  const fs::path dir = scratch("revision"), work = dir.string() + ".partial";
  interrupt_after_the_first_image(dir);
  const fs::path settings = work / "settings.yaml";
  std::ifstream in(settings, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string current = "renderer_revision: " + std::to_string(kRendererRevision);
  const std::size_t at = text.find(current);
  ASSERT_NE(at, std::string::npos) << text;
  text.replace(at, current.size(), "renderer_revision: " + std::to_string(kRendererRevision - 1));
  std::ofstream(settings, std::ios::binary) << text;
  PrecomputeRequest resume{tiny_profile(), dir, true, 0, {}};
  try {
    precompute_database(resume, f.env, f.scene);
    ADD_FAILURE() << "resumed the work of another renderer";
  } catch (const DatabaseError& e) {
    EXPECT_NE(std::string(e.what()).find("renderer revision"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir));
}

// The render phase writes a unit's images while the next one renders; an image's progress is
// reported once its file is in place, every image once, up to the total.
TEST(Database, RenderProgressFollowsTheWrittenImages) {
  const Fixture& f = fixture();
  const fs::path dir = scratch("progress"), work = dir.string() + ".partial";
  std::vector<std::size_t> reported;
  std::size_t render_total = 0;
  PrecomputeRequest request{tiny_profile(), dir, false, 0, {}};
  request.observer.progress = [&](std::string_view phase, std::size_t done, std::size_t total) {
    if (phase != "render" || done == 0) return;
    std::size_t files = 0;
    for (const auto& e : fs::recursive_directory_iterator(work))
      files += e.path().extension() == ".exr";
    EXPECT_GE(files, done) << "progress " << done << " before its image was written";
    reported.push_back(done);
    render_total = total;
  };
  precompute_database(request, f.env, f.scene);
  ASSERT_EQ(reported.size(), render_total);
  for (std::size_t i = 0; i < reported.size(); ++i) EXPECT_EQ(reported[i], i + 1);
}

}  // namespace
}  // namespace brdfnav
