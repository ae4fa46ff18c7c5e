#include <brdfnav/renderer/render.h>

#include <brdfnav/core/parallel_for.h>
#include "geometry.h"
#include "materialx_ggx.h"
#include "quadrature.h"
#include "ward_grid.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace brdfnav {

RenderQuality RenderQuality::finer(double factor) const {
  RenderQuality q = *this;
  q.texels_per_width *= factor;
  q.hot_texels_per_width *= factor;
  q.max_node /= factor;
  q.reach *= 1 + 0.25 * std::log2(std::max(factor, 1.0));
  q.max_split = static_cast<int>(std::ceil(max_split * factor));
  q.max_nodes = static_cast<int>(std::ceil(max_nodes * factor * factor));
  return q;
}

RenderQuality quality_from_record(std::span<const std::pair<std::string, double>> record) {
  RenderQuality q;
  for (const auto& entry : record) {
    // Not a structured binding: clang 14 (the sanitized builds') cannot capture one in a lambda.
    const std::string& name = entry.first;
    const double value = entry.second;
    const auto knob = std::find_if(std::begin(kQualityKnobs), std::end(kQualityKnobs),
                                   [&](const QualityKnob& k) { return name == k.name; });
    if (knob == std::end(kQualityKnobs))
      throw RenderError("render quality: unknown knob '" + name + "'");
    if (!(value > 0) || !std::isfinite(value))
      throw RenderError("render quality: " + name + " is " + std::to_string(value) +
                        "; every knob is positive and finite");
    if (knob->real) {
      q.*(knob->real) = value;
    } else {
      if (value != std::floor(value) || value > std::numeric_limits<int>::max())
        throw RenderError("render quality: " + name + " is " + std::to_string(value) +
                          "; it is a whole number");
      q.*(knob->integer) = static_cast<int>(value);
    }
  }
  return q;
}

namespace {

// The cosine lobe's curvature (laplacian(cos) = -2 cos) is that of a Gaussian of width 1; a
// little finer keeps the diffuse image, computed once, well below the specular errors.
constexpr double kLambertWidth = 0.7;

// World up: the tangent field of anisotropic lobes follows the meridians toward it.
const Vec3 kUp(0, 1, 0);

// Per-pixel shading frame: x along the meridian through the pixel's normal (toward +y), so the
// tangent is continuous everywhere except at the poles, where from_normal_tangent falls back.
Frame pixel_frame(const SurfacePoint& p) {
  return Frame::from_normal_tangent(p.normal, kUp);
}

// Angular width of the filter of He's mirror lookup at each pixel: half the largest angle
// between the pixel's mirror direction and its covered neighbours', at least half a texel.
std::vector<double> mirror_widths(const SurfaceBuffer& s, double texel_angle) {
  const int n = s.resolution;
  std::vector<double> widths(s.points.size(), 0.0);
  auto mirror = [&](int x, int y) { return reflect(kViewDirection, s.at(x, y).normal); };
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      if (!s.at(x, y).covered) continue;
      const Vec3 m = mirror(x, y);
      double spread = 0;
      const int dx[] = {1, -1, 0, 0}, dy[] = {0, 0, 1, -1};
      for (int k = 0; k < 4; ++k) {
        const int nx = x + dx[k], ny = y + dy[k];
        if (nx < 0 || ny < 0 || nx >= n || ny >= n || !s.at(nx, ny).covered) continue;
        spread = std::max(spread, angle_between(m, mirror(nx, ny)));
      }
      widths[static_cast<std::size_t>(y) * n + x] = std::max(spread, texel_angle) / 2;
    }
  }
  return widths;
}

// The progress phase of a lobe's images: "MODEL lobe pass".
template <typename L>
std::string_view lobe_pass() {
  static const std::string pass = std::string(L::kName) + " lobe pass";
  return pass;
}

}  // namespace

struct Renderer::Impl {
  const EnvMap& env;
  const Scene& scene;
  int resolution;
  RenderOptions options;
  EnvPyramid pyramid;
  SurfaceBuffer surface;
  std::vector<double> mirror_width;
  std::optional<Image> diffuse;
  // He's mirror term without its weight, per pixel: the same for every He material.
  std::optional<std::vector<Rgb>> mirrored;

  Impl(const EnvMap& e, const Scene& s, int res, RenderOptions o)
      : env(e), scene(s), resolution(res), options(std::move(o)), pyramid(e) {
    if (res < 1) throw RenderError("resolution must be at least 1");
    const RenderQuality& q = options.quality;
    if (!(q.texels_per_width > 0) || !(q.hot_texels_per_width > 0) || !(q.max_node > 0) ||
        !(q.reach > 0) || q.max_split < 1 || q.max_nodes < 1)
      throw RenderError("render quality: every knob must be positive");
    surface = scene.trace_camera(res);
    mirror_width = mirror_widths(surface, kPi / env.height());
  }

  int threads() const { return worker_threads(options.threads); }

  // pixel(point, index, scratch) at every covered pixel, zero elsewhere.
  template <typename V = Rgb, typename Pixel>
  std::vector<V> pixel_values(Pixel pixel, std::string_view pass, const ProgressSink& progress) {
    std::vector<V> values(surface.points.size(), zero<V>());
    std::vector<QuadratureScratch> scratch(threads());
    const auto row = [&](std::size_t y, int worker) {
      for (int x = 0; x < resolution; ++x) {
        const std::size_t i = y * resolution + x;
        if (surface.points[i].covered) values[i] = pixel(surface.points[i], i, scratch[worker]);
      }
    };
    const auto rows = std::size_t(resolution);
    parallel_for(rows, threads(), row, [&](std::size_t done) {
      if (progress) progress(pass, done, rows);
    });
    return values;
  }

  // Image whose covered pixels hold channels 3 lane .. 3 lane + 2 of `values`.
  template <typename V>
  Image image_of(const std::vector<V>& values, int lane = 0) const {
    Image image(resolution, resolution);
    for (int y = 0; y < resolution; ++y) {
      for (int x = 0; x < resolution; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * resolution + x;
        if (!surface.points[i].covered) continue;
        float* out = image.pixel(x, y);
        for (int c = 0; c < 3; ++c) out[c] = static_cast<float>(values[i][3 * lane + c]);
        out[3] = 1.f;
      }
    }
    return image;
  }

  // Image whose covered pixels hold pixel(point, index, scratch).
  template <typename Pixel>
  Image render_pass(std::string_view pass, Pixel pixel) {
    return image_of(pixel_values(pixel, pass, options.progress));
  }

  // `horizon`: see Quadrature.
  template <typename Kernel>
  auto integrate(const Kernel& kernel, const KernelShape& shape, const Vec3& horizon,
                 const SurfacePoint& p, QuadratureScratch& s) const {
    if (scene.convex())
      return Quadrature(pyramid, kernel, shape, horizon, options.quality).integrate(s);
    auto visible = [&](const Vec3& w) { return !scene.occluded(p, w); };
    return Quadrature(pyramid, kernel, shape, horizon, options.quality, visible).integrate(s);
  }

  // The environment filtered over each pixel's footprint around its mirror direction (no
  // progress of its own: it takes about a tenth of one He image). Kept only once complete: a
  // stopped pass leaves `mirrored` empty.
  void compute_mirror_lookups() {
    if (mirrored) return;
    auto lookup = [&](const SurfacePoint& p, std::size_t i, QuadratureScratch& s) {
      const Vec3 mirror = reflect(kViewDirection, p.normal);
      const double width = mirror_width[i];
      return integrate(MirrorKernel(mirror, width), KernelShape::isotropic(mirror, width),
                       Vec3::Zero(), p, s);
    };
    mirrored = pixel_values(lookup, "", {});
  }

  Rgb diffuse_pixel(const SurfacePoint& p, QuadratureScratch& s) const {
    return integrate(LambertKernel{p.normal}, KernelShape::isotropic(p.normal, kLambertWidth),
                     p.normal, p, s);
  }

  // A lobe's integral at pixel p, in the pixel's frame and shaped as `shaping` at wo there, plus
  // its mirror term: kernel(frame, wo) is the lobe's kernel, add_mirror(sum, wo) adds the mirror
  // term to the sum.
  template <typename Value, typename MakeKernel, typename AddMirror>
  Value lobe_pixel(const Lobe& shaping, const SurfacePoint& p, QuadratureScratch& s,
                   MakeKernel kernel, AddMirror add_mirror) const {
    const Frame frame = pixel_frame(p);
    const Vec3 wo = frame.to_local(kViewDirection);
    if (wo.z() <= 0) return zero<Value>();
    const KernelShape shape = lobe_shape(shaping, wo).to_world(frame);
    Value sum = integrate(kernel(frame, wo), shape, p.normal, p, s);
    add_mirror(sum, wo);
    return sum;
  }

  template <typename L>
  Rgb specular_pixel(const L& lobe, const Lobe& any, const SurfacePoint& p, std::size_t i,
                     QuadratureScratch& s) const {
    return lobe_pixel<Rgb>(
        any, p, s,
        [&](const Frame& frame, const Vec3& wo) { return LobeKernel<L>(lobe, frame, wo); },
        [&](Rgb& sum, const Vec3& wo) {
          if constexpr (MirrorLobe<L>) sum += lobe.mirror_weight(wo) * (*mirrored)[i];
        });
  }

  // specular_pixel() of the lobes `lobe` with its kFresnelParameter = params[k] in lane k, k <
  // kFresnelBatch (that parameter does not shape the lobe).
  template <typename L>
  BatchValue batch_pixel(const L& lobe, std::span<const double> params, const SurfacePoint& p,
                         std::size_t i, QuadratureScratch& s) const {
    return lobe_pixel<BatchValue>(
        lobe, p, s,
        [&](const Frame& frame, const Vec3& wo) {
          return FresnelBatchKernel<L>(lobe, params, frame, wo);
        },
        [&](BatchValue& sum, const Vec3& wo) {
          if constexpr (MirrorLobe<L>)
            for (std::size_t k = 0; k < params.size(); ++k) {
              L each = lobe;
              each.*kFresnelParameter<L> = params[k];
              sum.segment<3>(3 * static_cast<Eigen::Index>(k)) +=
                  each.mirror_weight(wo) * (*mirrored)[i];
            }
        });
  }

  // Renderer::ward_grid().
  std::vector<Image> ward_grid_images(std::span<const double> alpha_x,
                                      std::span<const double> alpha_y) {
    const WardGridQuadrature quadrature(pyramid, alpha_x, alpha_y, options.quality);
    const std::size_t count = quadrature.nx() * quadrature.ny();
    std::vector<Image> images(count, Image(resolution, resolution));
    std::vector<WardGridScratch> scratch(threads());
    std::vector<std::vector<double>> values(threads(), std::vector<double>(3 * count));
    const auto row = [&](std::size_t y, int worker) {
      for (int x = 0; x < resolution; ++x) {
        const SurfacePoint& p = surface.points[y * resolution + x];
        if (!p.covered) continue;
        const Frame frame = pixel_frame(p);
        std::function<bool(const Vec3&)> visible;
        if (!scene.convex()) visible = [&](const Vec3& w) { return !scene.occluded(p, w); };
        double* v = values[worker].data();
        quadrature.integrate(frame, frame.to_local(kViewDirection), visible, scratch[worker], v);
        for (std::size_t k = 0; k < count; ++k) {
          float* out = images[k].pixel(x, int(y));
          for (int c = 0; c < 3; ++c) out[c] = static_cast<float>(v[3 * k + c]);
          out[3] = 1.f;
        }
      }
    };
    parallel_for(std::size_t(resolution), threads(), row, [&](std::size_t done) {
      if (options.progress) options.progress("ward grid pass", done, std::size_t(resolution));
    });
    return images;
  }

  // specular() of each of `lobe` with kFresnelParameter = params[k], in one pass.
  template <typename L>
  std::vector<Image> batch_images(const L& lobe, std::span<const double> params) {
    if constexpr (MirrorLobe<L>) compute_mirror_lookups();
    const auto values = pixel_values<BatchValue>(
        [&](const SurfacePoint& p, std::size_t i, QuadratureScratch& s) {
          return batch_pixel(lobe, params, p, i, s);
        },
        lobe_pass<L>(), options.progress);
    std::vector<Image> images;
    for (std::size_t k = 0; k < params.size(); ++k) images.push_back(image_of(values, int(k)));
    return images;
  }
};

Renderer::Renderer(const EnvMap& env, const Scene& scene, int resolution, RenderOptions options)
    : impl_(std::make_unique<Impl>(env, scene, resolution, std::move(options))) {}
Renderer::~Renderer() = default;

int Renderer::resolution() const {
  return impl_->resolution;
}
const EnvMap& Renderer::env() const {
  return impl_->env;
}
const Scene& Renderer::scene() const {
  return impl_->scene;
}
const RenderOptions& Renderer::options() const {
  return impl_->options;
}
void Renderer::set_progress(ProgressSink progress) {
  impl_->options.progress = std::move(progress);
}

const Image& Renderer::diffuse() {
  if (!impl_->diffuse) {
    impl_->diffuse = impl_->render_pass(
        "diffuse pass", [&](const SurfacePoint& p, std::size_t, QuadratureScratch& s) {
          return impl_->diffuse_pixel(p, s);
        });
  }
  return *impl_->diffuse;
}

void Renderer::prepare(const Lobe& lobe) {
  if (std::visit([](const auto& l) { return MirrorLobe<std::decay_t<decltype(l)>>; }, lobe))
    impl_->compute_mirror_lookups();
}

Image Renderer::specular(const Lobe& lobe) {
  prepare(lobe);  // before the pass reads it
  return std::visit(
      [&](const auto& l) {
        using L = std::decay_t<decltype(l)>;
        return impl_->render_pass(lobe_pass<L>(),
                                  [&](const SurfacePoint& p, std::size_t i, QuadratureScratch& s) {
                                    return impl_->specular_pixel(l, lobe, p, i, s);
                                  });
      },
      lobe);
}

bool shares_quadrature(const Lobe& a, const Lobe& b) {
  if (a.index() != b.index()) return false;
  return std::visit(
      [&](const auto& lobe_a) {
        using L = std::decay_t<decltype(lobe_a)>;
        if constexpr (kFresnelParameter<L> == nullptr) {
          return false;
        } else {
          // b with a's Fresnel parameter: equal to a when nothing else differs.
          L b_at_a = std::get<L>(b);
          b_at_a.*kFresnelParameter<L> = lobe_a.*kFresnelParameter<L>;
          return b_at_a == lobe_a;
        }
      },
      a);
}

std::vector<std::vector<std::size_t>> quadrature_groups(std::span<const Lobe> lobes,
                                                        std::size_t max_size) {
  std::vector<std::vector<std::size_t>> groups;
  std::vector<bool> placed(lobes.size(), false);
  for (std::size_t first = 0; first < lobes.size(); ++first) {
    if (placed[first]) continue;
    groups.push_back({first});
    for (std::size_t j = first + 1; j < lobes.size() && groups.back().size() < max_size; ++j) {
      if (placed[j] || !shares_quadrature(lobes[first], lobes[j])) continue;
      groups.back().push_back(j);
      placed[j] = true;
    }
  }
  return groups;
}

std::vector<Image> Renderer::specular(std::span<const Lobe> lobes) {
  std::vector<Image> images(lobes.size());
  for (const std::vector<std::size_t>& group : quadrature_groups(lobes, kFresnelBatch)) {
    if (group.size() == 1) {
      images[group[0]] = specular(lobes[group[0]]);
      continue;
    }
    std::vector<Image> rendered = std::visit(
        [&](const auto& first) -> std::vector<Image> {
          using L = std::decay_t<decltype(first)>;
          if constexpr (kFresnelParameter<L> != nullptr) {
            std::vector<double> params;
            for (std::size_t j : group)
              params.push_back(std::get<L>(lobes[j]).*kFresnelParameter<L>);
            return impl_->batch_images(first, params);
          } else {
            throw Error(ErrorCode::internal,
                        "shares_quadrature() grouped lobes without a Fresnel parameter");
          }
        },
        lobes[group[0]]);
    for (std::size_t k = 0; k < group.size(); ++k) images[group[k]] = std::move(rendered[k]);
  }
  return images;
}

std::vector<Image> Renderer::ward_grid(std::span<const double> alpha_x,
                                       std::span<const double> alpha_y) {
  return impl_->ward_grid_images(alpha_x, alpha_y);
}

bool grid_images_differ(ModelId model) {
  return model == ModelId::ward;
}

std::vector<std::vector<std::size_t>> grid_render_units(ModelId model, const ParamGrid& grid) {
  if (grid_images_differ(model)) {
    std::vector<std::size_t> all(grid.node_count());
    for (std::size_t node = 0; node < all.size(); ++node) all[node] = node;
    return {all};
  }
  std::vector<Lobe> lobes;
  for (std::size_t node = 0; node < grid.node_count(); ++node)
    lobes.push_back(make_lobe(model, grid.node_values(node)));
  return quadrature_groups(lobes);
}

std::vector<Image> Renderer::grid_images(ModelId model, const ParamGrid& grid,
                                         std::span<const std::size_t> nodes) {
  if (nodes.empty()) return {};
  if (grid_images_differ(model)) {
    std::vector<Image> all = ward_grid(grid.axis(0), grid.axis(1));
    std::vector<Image> images;
    for (std::size_t node : nodes) {
      const std::vector<std::size_t> at = grid.multi_index(node);
      images.push_back(std::move(all[at[0] * grid.axis(1).size() + at[1]]));
    }
    return images;
  }
  std::vector<Lobe> lobes;
  for (std::size_t node : nodes) lobes.push_back(make_lobe(model, grid.node_values(node)));
  return specular(lobes);
}

Image Renderer::render(const Material& material) {
  validate(material);
  require_render_colorspace(material);
  const Lobe lobe = make_lobe(material.model, material.params);
  // The diffuse pass first, as its progress reports say (arguments are evaluated in any order).
  const Image& lambert = diffuse();
  return compose(lambert, specular(lobe), material.rho_d, material.rho_s);
}

Image Renderer::materialx_ggx(const Ggx& lobe, bool compensation) {
  const MaterialxGgx terms{lobe.alpha_x, lobe.alpha_y, compensation};
  const Lobe shaping = lobe;
  return impl_->render_pass("materialx ggx pass",
                            [&](const SurfacePoint& p, std::size_t i, QuadratureScratch& s) {
                              return impl_->specular_pixel(terms, shaping, p, i, s);
                            });
}

ImageMetadata render_metadata(const Renderer& renderer, const Material* material) {
  const RenderQuality& q = renderer.options().quality;
  std::string quality;  // "texels_per_width=1.25 ... max_nodes=16384"
  for (const QualityKnob& knob : kQualityKnobs) {
    char value[32];
    if (knob.real)
      std::snprintf(value, sizeof value, "%g", q.*(knob.real));
    else
      std::snprintf(value, sizeof value, "%d", q.*(knob.integer));
    quality += (quality.empty() ? "" : " ") + std::string(knob.name) + "=" + value;
  }
  ImageMetadata m{{db::kHeaderEnv, renderer.env().source()},
                  {db::kHeaderEnvSha1, renderer.env().pixel_sha1()},
                  {db::kHeaderScene, renderer.scene().description()},
                  {db::kHeaderResolution, std::to_string(renderer.resolution())},
                  {db::kHeaderRendererRevision, std::to_string(kRendererRevision)},
                  {db::kHeaderQuality, quality}};
  if (material) m.emplace_back(db::kHeaderMaterial, format_material_spec(*material));
  return m;
}

}  // namespace brdfnav
