// precompute_database(): the build of a database in four resumable phases (render, embed, fit,
// blend check) and its atomic completion (manifest, rename); a shard's build (its share of the
// node images and of the blend check's renders) and the merge of the shards.
#include <brdfnav/precompute/database.h>

#include <brdfnav/core/atomic_file.h>
#include <brdfnav/core/parallel_for.h>
#include <brdfnav/navigator/blend.h>
#include <brdfnav/navigator/database_format.h>
#include <brdfnav/navigator/image_input.h>
#include <brdfnav/renderer/render.h>
#include "image_writer.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <mutex>
#include <optional>

namespace brdfnav {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// How a build with these inputs is made, as the manifest records it.
db::BuildSettings build_settings(const Profile& p, const EnvMap& env, const Scene& scene) {
  db::BuildSettings s;
  s.generator = "brdfnav " BRDFNAV_VERSION;
  s.renderer_revision = kRendererRevision;
  s.profile = p.name;
  s.resolution = p.resolution;
  s.scene = scene.description();
  s.env_path = env.source();
  s.env_pixel_sha1 = env.pixel_sha1();
  s.env_width = env.width();
  s.env_height = env.height();
  s.q_nodes = diffuse_fraction_nodes(p.q_nodes);
  s.grids = p.grids;
  db::SettingsGroup quality{"render_quality", {}};
  for (const QualityKnob& knob : kQualityKnobs)
    quality.values.emplace_back(
        knob.name, knob.real ? db::SettingValue{p.quality.*(knob.real)}
                             : db::SettingValue{std::int64_t{p.quality.*(knob.integer)}});
  s.options = {std::move(quality),
               {"pca",
                {{"components", std::int64_t{p.pca.components}},
                 {"oversample", std::int64_t{p.pca.oversample}},
                 {"power_iterations", std::int64_t{p.pca.power_iterations}},
                 {"seed", std::uint64_t{p.pca.seed}}}},
               {"fit",
                {{"n_wo", std::int64_t{p.fit.n_wo}},
                 {"n_wi", std::int64_t{p.fit.n_wi}},
                 {"starts", std::int64_t{p.fit.starts}},
                 {"max_iterations", std::int64_t{p.fit.max_iterations}}}}};
  return s;
}

// The material of a grid node's specular image: rho_d = 0, rho_s = 1.
Material node_material(ModelId id, std::vector<double> params, Rgb rho_s = Rgb::Ones()) {
  Material m = default_material(id);
  m.params = std::move(params);
  m.rho_d = Rgb::Zero();
  m.rho_s = rho_s;
  return m;
}

// An image's header: how it was made, and no time stamp (OpenImageIO writes the current time
// as DateTime unless the attribute is set; an empty value leaves it out), so that rebuilding a
// database gives the same bytes.
ImageMetadata image_metadata(const Renderer& renderer, const Material* material) {
  ImageMetadata m = render_metadata(renderer, material);
  m.emplace_back("DateTime", "");
  return m;
}

// A shard's render of a grid cell's midpoint for the blend check, which the merge measures: not
// a database file. Full floats, so that the merge's distances are the single-machine build's.
constexpr const char* kCellsDir = "cells";
std::string cell_image_file(ModelId id, std::size_t cell) {
  char name[32];
  std::snprintf(name, sizeof name, "%05zu.exr", cell);
  return std::string(kCellsDir) + "/" + std::string(model_info(id).name) + "/" + name;
}

// The midpoints of a grid's cells as the blend check renders them: their materials (rho_d = 0,
// rho_s = 1) and lobes, in the groups rendered in one pass (those that share their quadrature:
// He's cells along eta, Cook-Torrance's along f0), each image as Renderer::render() gives it alone.
struct GridCells {
  std::vector<Material> materials;
  std::vector<Lobe> lobes;
  std::vector<std::vector<std::size_t>> groups;

  explicit GridCells(const ProfileGrid& g) {
    for (std::size_t c = 0; c < g.grid.cell_count(); ++c) {
      materials.push_back(node_material(g.model, g.grid.cell_midpoint(c)));
      lobes.push_back(make_lobe(g.model, materials.back().params));
    }
    groups = quadrature_groups(lobes, kFresnelBatch);
  }
  std::vector<Lobe> batch(const std::vector<std::size_t>& group) const {
    std::vector<Lobe> b;
    for (std::size_t c : group) b.push_back(lobes[c]);
    return b;
  }
};

class Job {
 public:
  Job(const PrecomputeRequest& request, const EnvMap& env, const Scene& scene)
      : r_(request),
        p_(request.profile),
        env_(env),
        scene_(scene),
        work_(request.out.string() + ".partial"),
        threads_(worker_threads(request.threads)) {}

  void run() {
    prepare();
    timed("render", [&] { render_images(); });
    if (r_.shard_count > 1) {
      timed("cells", [&] { render_cells(); });
      finish_shard();
      return;
    }
    timed("embedding", [&] { embed(); });
    timed("fits", [&] { fit_conversions(); });
    timed("blend check", [&] { check_blends(); });
    timed("manifest", [&] { finish(); });
  }

 private:
  template <typename F>
  void timed(const std::string& phase, F&& work) {
    const auto start = Clock::now();
    work();
    char line[128];
    std::snprintf(line, sizeof line, "%s: %.2f s", phase.c_str(), seconds_since(start));
    log(line);
  }
  void log(const std::string& line) const {
    if (r_.observer.log) r_.observer.log(line);
  }
  void progress(std::string_view phase, std::size_t done, std::size_t total) const {
    if (r_.observer.progress) r_.observer.progress(phase, done, total);
  }
  fs::path at(const std::string& relative) const { return work_ / relative; }

  // One renderer for every phase that renders, made when the first needs it (a merge whose
  // shards rendered everything needs none).
  Renderer& renderer() {
    if (!renderer_) {
      RenderOptions options;
      options.threads = r_.threads;
      options.quality = p_.quality;
      renderer_.emplace(env_, scene_, p_.resolution, options);
    }
    return *renderer_;
  }
  // Whether the next unit of work (the diffuse image, then every grid's render units, then, in a
  // shard, every grid's cell groups) is this shard's: units are dealt round robin.
  bool next_unit_mine() {
    return unit_++ % std::size_t(r_.shard_count) == std::size_t(r_.shard_index);
  }

  // The work directory, fresh or (with --resume) checked against the settings it was started with.
  void prepare() {
    if (fs::exists(r_.out))
      throw DatabaseError(r_.out.string() + ": already exists; remove it or choose another --out");
    const std::string settings = db::settings_yaml(build_settings(p_, env_, scene_));
    const fs::path settings_path = at(db::kSettingsFile);
    if (fs::exists(work_) && r_.resume && fs::exists(settings_path)) {
      if (read_file(settings_path) != settings)
        throw DatabaseError(settings_path.string() +
                            ": the unfinished database was started with other settings (profile, "
                            "environment, scene, resolution or renderer revision); remove " +
                            work_.string() + " or run without --resume");
      log("resuming in " + work_.string());
    } else {
      fs::remove_all(work_);
    }
    for (const char* dir : {"images", "embedding", "conversions", "previews"})
      fs::create_directories(at(dir));
    for (const ProfileGrid& g : p_.grids)
      fs::create_directories(at("images/" + std::string(model_info(g.model).name)));
    write_file_atomic(settings_path, settings);
  }

  // A finished image is reused when it reads back at the profile's size; anything else (a file
  // damaged outside brdfnav) is rendered again.
  bool reusable_image(const fs::path& path) const {
    if (!fs::exists(path)) return false;
    try {
      const Image image = read_image(path);
      if (image.width == p_.resolution && image.height == p_.resolution) return true;
    } catch (const ImageError&) {
    }
    log(path.string() + ": unreadable or of the wrong size; rendering it again");
    return false;
  }

  // A unit of work to render: its items (nodes or cells), each one's file and material, how the
  // unit renders a subset of them together, and how their files store the pixels.
  struct RenderUnit {
    const std::vector<std::size_t>& items;
    std::function<std::string(std::size_t)> file;
    std::function<Material(std::size_t)> material;
    std::function<std::vector<Image>(const std::vector<std::size_t>&)> render;
    ExrPixels pixels;
  };

  // Renders the unit's items not finished yet (none when the unit is another shard's) and hands
  // them to `writer`; calls `skipped` for every other item, in order, and returns how many.
  std::size_t render_unit(const RenderUnit& u, ImageWriter& writer,
                          const std::function<void()>& skipped) {
    std::vector<std::size_t> pending;
    const bool assigned = next_unit_mine();
    for (std::size_t i : u.items) {
      if (assigned && !reusable_image(at(u.file(i))))
        pending.push_back(i);
      else
        skipped();
    }
    if (pending.empty()) return u.items.size();
    std::vector<Image> images = u.render(pending);
    std::vector<PendingFile> files;
    for (std::size_t k = 0; k < pending.size(); ++k) {
      const Material m = u.material(pending[k]);
      files.push_back(
          {std::move(images[k]), at(u.file(pending[k])), image_metadata(renderer(), &m), u.pixels});
    }
    writer.write(std::move(files));
    return u.items.size() - pending.size();
  }

  void render_images() {
    const std::size_t total = p_.image_count();
    std::size_t done = 0, reused = 0;
    ImageWriter writer([&] { progress("render", ++done, total); });
    progress("render", 0, total);
    if (!next_unit_mine() || reusable_image(at(db::kDiffuseFile))) {
      ++reused;
    } else {
      write_exr(renderer().diffuse(), at(db::kDiffuseFile), image_metadata(renderer(), nullptr),
                ExrPixels::half_raw);
    }
    progress("render", ++done, total);
    for (const ProfileGrid& g : p_.grids) {
      for (const std::vector<std::size_t>& nodes : grid_render_units(g.model, g.grid))
        reused += render_unit(
            {nodes, [&](std::size_t n) { return db::image_file(g.model, n); },
             [&](std::size_t n) { return node_material(g.model, g.grid.node_values(n)); },
             [&](const std::vector<std::size_t>& p) {
               return renderer().grid_images(g.model, g.grid, p);
             },
             ExrPixels::half_raw},
            writer, [&] { progress("render", ++done, total); });
    }
    writer.finish();
    log("render: " + std::to_string(total) + " images, " + std::to_string(reused) +
        (r_.shard_count > 1 ? " reused or left to other shards" : " reused"));
  }

  // A shard's part of the blend check: the renders of its cell groups' midpoints
  // (cell_image_file()), which the merge measures once it has every node image. Without them the
  // merge alone would render every cell, about as long as the whole render phase on its CPUs.
  void render_cells() {
    std::size_t total = 0, done = 0, reused = 0;
    for (const ProfileGrid& g : p_.grids) total += g.grid.cell_count();
    ImageWriter writer([&] { progress("cells", ++done, total); });
    progress("cells", 0, total);
    for (const ProfileGrid& g : p_.grids) {
      fs::create_directories(at(cell_image_file(g.model, 0)).parent_path());
      const GridCells cells(g);
      for (const std::vector<std::size_t>& group : cells.groups)
        reused += render_unit(
            {group, [&](std::size_t c) { return cell_image_file(g.model, c); },
             [&](std::size_t c) { return cells.materials[c]; },
             [&](const std::vector<std::size_t>& p) { return renderer().specular(cells.batch(p)); },
             ExrPixels::float_zip},
            writer, [&] { progress("cells", ++done, total); });
    }
    writer.finish();
    log("cells: " + std::to_string(total) + " cell midpoints, " + std::to_string(reused) +
        " reused or left to other shards");
  }

  // A shard: its images, its cells' renders and shard.yaml (the settings, i/N and the files'
  // checksums).
  void finish_shard() {
    db::FileSums sums;
    for (const std::string& f : db::database_files(p_.grids))
      if (f.ends_with(".exr") && fs::exists(at(f))) sums[f] = file_sha1(at(f));
    for (const ProfileGrid& g : p_.grids)
      for (std::size_t c = 0; c < g.grid.cell_count(); ++c)
        if (const std::string f = cell_image_file(g.model, c); fs::exists(at(f)))
          sums[f] = file_sha1(at(f));
    const std::string text =
        db::shard_yaml(build_settings(p_, env_, scene_), r_.shard_index, r_.shard_count, sums);
    write_file_atomic(at(db::kShardFile), text);
    fs::remove(at(db::kSettingsFile));
    std::error_code ec;
    fs::rename(work_, r_.out, ec);
    if (ec)
      throw DatabaseError(r_.out.string() + ": cannot move the shard into place: " + ec.message());
    log("shard written to " + r_.out.string());
  }

  bool embedding_done() const {
    if (!fs::exists(at(db::kSingularValuesFile)) || !fs::exists(at(db::kBasisFile))) return false;
    for (const ProfileGrid& g : p_.grids)
      if (!fs::exists(at(db::coefficients_file(g.model)))) return false;
    return true;
  }

  void embed() {
    if (embedding_done()) {
      log("embedding: reused");
      return;
    }
    const std::size_t total = p_.image_count();
    std::size_t done = 0;
    progress("load images", 0, total);
    const Image diffuse = read_image(at(db::kDiffuseFile));
    progress("load images", ++done, total);
    std::vector<ModelImages> images;
    for (const ProfileGrid& g : p_.grids) {
      images.push_back({g.model, g.grid, {}});
      for (std::size_t node = 0; node < g.grid.node_count(); ++node) {
        images.back().specular.push_back(read_image(at(db::image_file(g.model, node))));
        progress("load images", ++done, total);
      }
    }
    progress("embedding", 0, 1);
    const std::vector<double> q = diffuse_fraction_nodes(p_.q_nodes);
    PcaOptions pca = p_.pca;
    pca.threads = threads_;
    const Embedding e = build_embedding(diffuse, images, q, pca);
    write_embedding(e);
    progress("embedding", 1, 1);
  }

  void write_embedding(const Embedding& e) const {
    const Eigen::MatrixXf& v = e.basis.vectors;
    db::Table basis{std::uint32_t(v.rows()), std::uint32_t(v.cols()), {}};
    for (Eigen::Index i = 0; i < v.rows(); ++i)
      for (Eigen::Index j = 0; j < v.cols(); ++j) basis.values.push_back(v(i, j));
    db::write_table(at(db::kBasisFile), basis);
    db::Table singular{1, std::uint32_t(v.cols()), {}};
    for (double s : e.basis.singular_values) singular.values.push_back(float(s));
    db::write_table(at(db::kSingularValuesFile), singular);
    for (const ModelEmbedding& m : e.models)
      db::write_table(at(db::coefficients_file(m.model())), db::embedding_table(m));
  }

  int components() const { return int(db::read_table_shape(at(db::kSingularValuesFile)).second); }

  ModelEmbedding load_embedding(const ProfileGrid& g) const {
    return db::read_model_embedding(work_, diffuse_fraction_nodes(p_.q_nodes), components(), g,
                                    kDatabaseFormatVersion);
  }

  void fit_conversions() {
    std::vector<ModelEmbedding> embeddings;
    for (const ProfileGrid& g : p_.grids) embeddings.push_back(load_embedding(g));
    std::size_t total = 0, done = 0, fitted = 0;
    for (const ProfileGrid& a : p_.grids) total += a.grid.node_count() * (p_.grids.size() - 1);
    const auto start = Clock::now();
    progress("fits", 0, total);
    for (std::size_t ai = 0; ai < p_.grids.size(); ++ai) {
      for (std::size_t bi = 0; bi < p_.grids.size(); ++bi) {
        if (ai == bi) continue;
        const ProfileGrid& a = p_.grids[ai];
        const fs::path path = at(db::conversion_file(a.model, p_.grids[bi].model));
        if (!fs::exists(path)) {
          fit_table(embeddings[ai], embeddings[bi], path, done, total);
          fitted += a.grid.node_count();
        } else {
          done += a.grid.node_count();
        }
        progress("fits", done, total);
      }
    }
    char line[160];
    std::snprintf(line, sizeof line, "fits: %zu of %zu fitted, %.1f ms per fit on %d threads",
                  fitted, total, fitted ? 1e3 * seconds_since(start) * threads_ / fitted : 0.0,
                  threads_);
    log(line);
  }

  // One conversion table: every node of `a` fitted by `b`'s model, nodes spread over threads.
  void fit_table(const ModelEmbedding& a, const ModelEmbedding& b, const fs::path& path,
                 std::size_t& done, std::size_t total) const {
    const std::size_t nodes = a.grid().node_count(), cols = db::conversion_columns(b.model());
    db::Table t{std::uint32_t(nodes), std::uint32_t(cols), std::vector<float>(nodes * cols)};
    std::mutex mutex;
    parallel_for(nodes, threads_, [&](std::size_t n) {
      const Material source = node_material(a.model(), a.grid().node_values(n));
      const LobeFit fit = fit_lobe(make_lobe(source.model, source.params), b.model(), p_.fit);
      const Material fitted = node_material(b.model(), fit.params, fit.scale);
      const Conversion c{fit.params, fit.scale, fit.relative_error,
                         embedding_distance(a.embed(source), b.embed(fitted))};
      db::write_conversion_row(c, b.model(), {&t.values[n * cols], cols});
      const std::lock_guard lock(mutex);
      progress("fits", ++done, total);
    });
    db::write_table(path, t);
  }

  // The blend check (db::blend_check_file()): per cell of each grid, how far the thumbnails'
  // blend of the node images is from an exact render at the cell's midpoint, the image the
  // navigator's exact thumbnails render (Renderer::render, here several lobes a pass). Lets a
  // server show the blend as the final image where it is faithful (docs/NAVIGATION.md). A model's
  // table is written once all its cells are measured; a resumed build keeps the finished ones.
  void check_blends() {
    const Image diffuse = read_image(at(db::kDiffuseFile));
    std::size_t total = 0, done = 0, rendered = 0;
    for (const ProfileGrid& g : p_.grids) total += g.grid.cell_count();
    progress("blend check", 0, total);
    for (const ProfileGrid& g : p_.grids) {
      const fs::path path = at(db::blend_check_file(g.model));
      if (fs::exists(path)) {
        done += g.grid.cell_count();
        progress("blend check", done, total);
        continue;
      }
      std::vector<Image> nodes;
      for (std::size_t n = 0; n < g.grid.node_count(); ++n)
        nodes.push_back(read_image(at(db::image_file(g.model, n))));
      const GridCells cells(g);
      db::Table t{std::uint32_t(g.grid.cell_count()), 1, std::vector<float>(cells.lobes.size())};
      for (const std::vector<std::size_t>& group : cells.groups) {
        const std::vector<Image> exact = cell_images(g.model, cells, group, rendered);
        for (std::size_t k = 0; k < group.size(); ++k) {
          const Material& m = cells.materials[group[k]];
          const std::vector<ParamGrid::Corner> corners = g.grid.cubic_corners(m.params);
          std::vector<const Image*> images;
          for (const ParamGrid::Corner& n : corners) images.push_back(&nodes[n.node]);
          const Image blend = blend_images(diffuse, corners, images, m.rho_d, m.rho_s);
          t.values[group[k]] =
              float(image_distance(blend, compose(diffuse, exact[k], m.rho_d, m.rho_s)));
          progress("blend check", ++done, total);
        }
      }
      db::write_table(path, t);
    }
    log("blend check: " + std::to_string(total) + " cells, " + std::to_string(rendered) +
        " midpoints rendered here" + (rendered < total ? " (the others by the shards)" : ""));
  }

  // A cell group's midpoint renders: the shards' (merged into cells/) when they made every one
  // of the group, else rendered here, as the shards render them.
  std::vector<Image> cell_images(ModelId model, const GridCells& cells,
                                 const std::vector<std::size_t>& group, std::size_t& rendered) {
    const auto from_shard = [&](std::size_t c) {
      return fs::exists(at(cell_image_file(model, c)));
    };
    if (std::all_of(group.begin(), group.end(), from_shard)) {
      std::vector<Image> images;
      for (std::size_t c : group) images.push_back(read_image(at(cell_image_file(model, c))));
      return images;
    }
    rendered += group.size();
    return renderer().specular(cells.batch(group));
  }

  // Checksums every file, writes the manifest, drops what is not part of the database (the
  // settings, temporaries of an interrupted run) and renames the directory into place.
  void finish() {
    fs::remove_all(at(kCellsDir));  // the shards' midpoint renders, measured by the blend check
    std::vector<std::string> files = db::database_files(p_.grids);
    for (const std::string& f : db::optional_database_files(p_.grids))
      if (fs::exists(at(f))) files.push_back(f);
    db::FileSums sums;
    std::size_t done = 0;
    for (const std::string& f : files) {
      sums[f] = file_sha1(at(f));
      progress("checksums", ++done, files.size());
    }
    const fs::path manifest = at(db::kManifestFile);
    write_file_atomic(manifest,
                      db::manifest_yaml(build_settings(p_, env_, scene_), components(), sums));
    std::vector<fs::path> stray;
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(work_)) {
      const std::string rel = fs::relative(e.path(), work_).generic_string();
      if (e.is_regular_file() && rel != db::kManifestFile && !sums.contains(rel))
        stray.push_back(e.path());
    }
    for (const fs::path& f : stray) fs::remove(f);
    std::error_code ec;
    fs::rename(work_, r_.out, ec);
    if (ec)
      throw DatabaseError(r_.out.string() +
                          ": cannot move the finished database into place: " + ec.message());
    log("database written to " + r_.out.string());
  }

  const PrecomputeRequest& r_;
  const Profile& p_;
  const EnvMap& env_;
  const Scene& scene_;
  fs::path work_;
  int threads_;
  std::optional<Renderer> renderer_;
  std::size_t unit_ = 0;
};

}  // namespace

void precompute_database(const PrecomputeRequest& request, const EnvMap& env, const Scene& scene) {
  if (request.shard_count < 1 || request.shard_index < 0 ||
      request.shard_index >= request.shard_count)
    throw DatabaseError("shard " + std::to_string(request.shard_index) + "/" +
                        std::to_string(request.shard_count) + ": expected i/N with 0 <= i < N");
  Job(request, env, scene).run();
}

namespace {

// Copies a shard's images into the work directory after checking the shard belongs to the build.
void take_shard(const fs::path& shard, const std::string& settings, const fs::path& work,
                std::vector<bool>& seen) {
  const ShardOrigin o = read_shard_origin(shard);
  const std::string file = (shard / db::kShardFile).string();
  if (read_file(file).rfind(settings, 0) != 0)
    throw DatabaseError(file + ": the shard was made with other settings than " +
                        "the first shard (profile, environment, scene, resolution or renderer "
                        "revision)");
  const std::string name = std::to_string(o.shard_index) + "/" + std::to_string(o.shard_count);
  if (seen.empty()) seen.assign(std::size_t(o.shard_count), false);
  if (std::size_t(o.shard_count) != seen.size())
    throw DatabaseError(file + ": shard " + name + ", but the other shards are of " +
                        std::to_string(seen.size()));
  if (seen[std::size_t(o.shard_index)])
    throw DatabaseError(file + ": shard " + name + " given twice");
  seen[std::size_t(o.shard_index)] = true;
  for (const auto& [relative, sha] : o.files) {
    // A shard names files inside itself: nothing may be copied outside the work directory.
    const fs::path rel(relative);
    if (rel.is_absolute() || rel.empty() ||
        std::any_of(rel.begin(), rel.end(), [](const fs::path& part) { return part == ".."; }))
      throw DatabaseError(file + ": '" + relative + "' is not a path inside the shard");
    if (file_sha1(shard / relative) != sha)
      throw DatabaseError((shard / relative).string() + ": checksum mismatch");
    fs::create_directories((work / relative).parent_path());
    fs::copy_file(shard / relative, work / relative, fs::copy_options::overwrite_existing);
  }
}

}  // namespace

void merge_shards(const std::vector<fs::path>& shards, const PrecomputeRequest& request,
                  const EnvMap& env, const Scene& scene) {
  if (fs::exists(request.out))
    throw DatabaseError(request.out.string() +
                        ": already exists; remove it or choose another --out");
  const std::string settings = db::settings_yaml(build_settings(request.profile, env, scene));
  const fs::path work = request.out.string() + ".partial";
  fs::remove_all(work);
  fs::create_directories(work);
  std::vector<bool> seen;
  for (const fs::path& shard : shards) take_shard(shard, settings, work, seen);
  for (std::size_t i = 0; i < seen.size(); ++i)
    if (!seen[i])
      throw DatabaseError("shard " + std::to_string(i) + "/" + std::to_string(seen.size()) +
                          " is missing from the merge");
  write_file_atomic(work / db::kSettingsFile, settings);
  PrecomputeRequest whole = request;
  whole.resume = true;  // every image is there: the build goes on with the embedding
  whole.shard_index = 0, whole.shard_count = 1;
  Job(whole, env, scene).run();
}

}  // namespace brdfnav
