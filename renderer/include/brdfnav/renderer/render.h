// The pre-renderer: BRDF images of a scene under an environment map (paper, sections 2.1, 3.1).
//
// Every pixel is the integral of L_env(wi) f(wi, wo) cos(theta_i) over the hemisphere, kept in
// its linear parts so that any material's image is exactly rho_d * I_diffuse + rho_s * I_spec:
//   I_diffuse: Lambert with rho_d = 1 (independent of the model, computed once and cached);
//   I_spec:    the model's lobe with rho_s = 1, plus He's mirror term as a filtered lookup.
// The integral is a deterministic quadrature over a pyramid of the environment restricted to the
// lobe, with the brightest texels integrated apart (docs/RENDERER.md): images are bit-identical
// for the same inputs whatever the thread count.
#pragma once

#include <brdfnav/core/error.h>
#include <brdfnav/core/grid.h>
#include <brdfnav/core/image.h>
#include <brdfnav/core/material.h>
#include <brdfnav/core/progress.h>
#include <brdfnav/renderer/env_map.h>
#include <brdfnav/renderer/scene.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace brdfnav {

// A render asked for with arguments that cannot be rendered: a resolution below 1, a quality knob
// that is not positive, a Ward grid's alphas that are empty, not positive or decreasing.
using RenderError = LayerError<struct RenderErrorTag, ErrorCode::invalid_argument>;

// Bumped whenever the renderer's images change beyond rounding (a new quadrature rule, a lobe's
// formula). A database's settings record it, so that a resumed build or a merge of shards never
// mixes the images of two renderers; Render.ImagesAreThoseOfThisRevision holds it to reference
// values of a few images.
inline constexpr int kRendererRevision = 5;

// Knobs of the quadrature (docs/RENDERER.md). The defaults meet the accuracy target: the error is
// at most a tenth of the change a 10% parameter step makes. finer(4) is the reference.
struct RenderQuality {
  double texels_per_width = 1.25;   // quadrature nodes per lobe width (its narrowest sigma)
  double hot_texels_per_width = 5;  // ... for the pieces of the hot texels (lamps)
  double max_node = 0.2;            // radians: the largest node, whatever the lobe's width
  double reach = 3.5;               // the window around the lobe's peak, in lobe widths
  int max_split = 16;               // a texel is cut into at most max_split^2 pieces
  int max_nodes = 16384;            // per pixel and term: beyond, nodes are made coarser

  // The same quadrature `factor` times finer in angle, over a wider window.
  RenderQuality finer(double factor) const;
};

// The knobs by name, in the order every record of them lists them (an image's brdfnav:quality
// header, a database's render_quality): one table that writes and reads them. Each is a double
// or an int of RenderQuality.
struct QualityKnob {
  const char* name;
  double RenderQuality::*real = nullptr;
  int RenderQuality::*integer = nullptr;
};
inline constexpr QualityKnob kQualityKnobs[] = {
    {"texels_per_width", &RenderQuality::texels_per_width},
    {"hot_texels_per_width", &RenderQuality::hot_texels_per_width},
    {"max_node", &RenderQuality::max_node},
    {"reach", &RenderQuality::reach},
    {"max_split", nullptr, &RenderQuality::max_split},
    {"max_nodes", nullptr, &RenderQuality::max_nodes},
};
// A quality as a record of its knobs lists it, `name: value`; knobs the record leaves out keep
// RenderQuality's defaults (records written before the knob existed). RenderError naming the knob
// for a name not in kQualityKnobs, a value that is not positive and finite, or one that is not a
// whole number where the knob is an int.
RenderQuality quality_from_record(std::span<const std::pair<std::string, double>> record);

// RenderOptions::progress (core/progress.h) is called with (pass, rows done, rows total): the
// passes are "diffuse pass", "MODEL lobe pass", "ward grid pass" and "materialx ggx pass", each
// reported after each of the calling thread's rows and once at its end. An exception it throws
// stops the render (no new row starts; it is rethrown once the rows under way are done). What the
// renderer caches (diffuse(), prepare()) is kept only once complete, so the next image is the one
// a fresh renderer makes.

struct RenderOptions {
  int threads = 0;  // 0: every hardware thread
  RenderQuality quality;
  ProgressSink progress;  // may be empty
};

class Renderer {
 public:
  // Keeps references to `env` and `scene`: both must outlive the renderer. Traces the camera and
  // builds the environment's quadtree once. RenderError for a resolution below 1 or a quality
  // knob that is not positive.
  Renderer(const EnvMap& env, const Scene& scene, int resolution, RenderOptions options = {});
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  int resolution() const;
  const EnvMap& env() const;
  const Scene& scene() const;
  const RenderOptions& options() const;
  void set_progress(ProgressSink progress);

  // Lambert, rho_d = 1; alpha is coverage. Computed on first use, then cached.
  const Image& diffuse();
  // What every image of the lobe's model shares, computed on first use, then cached: He's
  // mirror lookups (the environment filtered around each pixel's mirror direction). specular()
  // calls it; call it first to time specular() per image alone.
  void prepare(const Lobe& lobe);
  // The lobe with rho_s = 1 (He's mirror term included).
  Image specular(const Lobe& lobe);
  // specular() of each lobe, to the bit, in order. Lobes that shares_quadrature() are rendered
  // together, up to kFresnelBatch in a pass that costs little more than one of them.
  std::vector<Image> specular(std::span<const Lobe> lobes);
  // Ward lobes with rho_s = 1 at every pair of alpha_x[i] and alpha_y[j], as
  // images[i * alpha_y.size() + j], integrated together over one set of nodes per pixel, fine
  // enough for each lobe where it reaches (renderer/src/ward_grid.h): over the paper's 15 x 15
  // grid, a small part of the time of specular() of each. The nodes depend on the smallest and
  // largest alpha of each list, so an image differs from specular()'s, and from the same lobe's
  // in another grid, within the accuracy target. RenderError for an empty list, an alpha that
  // is not positive and finite, or a list that decreases.
  std::vector<Image> ward_grid(std::span<const double> alpha_x, std::span<const double> alpha_y);
  // The images (rho_s = 1) of `nodes` of a grid of `model`'s lobes, in order: the nodes of one
  // unit of grid_render_units(model, grid), or several. How they are rendered is the renderer's
  // choice: Ward's whole grid in one pass (ward_grid(), so an image depends on the grid's alphas
  // and a resumed build renders it as a fresh one did), else specular() of the nodes' lobes.
  std::vector<Image> grid_images(ModelId model, const ParamGrid& grid,
                                 std::span<const std::size_t> nodes);
  // rho_d * diffuse() + rho_s * specular(lobe); validates the material (MaterialError).
  Image render(const Material& material);
  // A GGX lobe with MaterialX's terms instead of Cycles' (renderer/src/materialx_ggx.h),
  // integrated in the lobe's own windows: the part of a MaterialX renderer's image that rho_s
  // scales (`compensation` false) or that rho_s^2 scales (true). docs/HOSTS.md, MaterialX.
  Image materialx_ggx(const Ggx& lobe, bool compensation);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The most lobes that Renderer::specular() of a span renders in one pass (kernels.h's
// FresnelBatchKernel carries one lane per lobe). Ten: the default profile's He nodes along eta
// in one pass (its cost against a pass of five: docs/RENDERER.md, Speed).
inline constexpr int kFresnelBatch = 10;

// Whether the renderer integrates the two lobes over the same nodes at every pixel and can
// render them together: lobes of one model that differ in its Fresnel parameter alone (He's eta,
// Cook-Torrance's f0; kernels.h), the one factor that changes.
bool shares_quadrature(const Lobe& a, const Lobe& b);
// The lobes' indices in groups that shares_quadrature() with their first, of at most max_size,
// in the order of their first indices.
std::vector<std::vector<std::size_t>> quadrature_groups(std::span<const Lobe> lobes,
                                                        std::size_t max_size = SIZE_MAX);

// A grid's nodes in the units Renderer::grid_images() renders together, in the order of their
// first nodes: Ward's whole grid; else the nodes whose lobes shares_quadrature() (He's along eta,
// Cook-Torrance's along f0); else one node each.
std::vector<std::vector<std::size_t>> grid_render_units(ModelId model, const ParamGrid& grid);
// Whether grid_images() of a node differs from specular() of its lobe (Ward's one pass over
// shared nodes), so that an accuracy study measures both.
bool grid_images_differ(ModelId model);

// EXR header attributes recording how an image was made (material, env path and pixel hash,
// scene, resolution, quality) under database_format.h's keys, for write_exr() (image_output.h).
ImageMetadata render_metadata(const Renderer& renderer, const Material* material);

}  // namespace brdfnav
