// The paper's evaluation of its metric (section 2.2, Figures 2, 3, 8 and 9) and of the embedding
// (section 3.2), as computations on rendered images: `brdfnav validate` reports and plots them
// (docs/VALIDATION.md). Every study renders with the renderer it is given, so its scale (the
// resolution) is the caller's choice.
#pragma once

#include <brdfnav/core/image.h>
#include <brdfnav/core/material.h>
#include <brdfnav/precompute/database.h>
#include <brdfnav/renderer/render.h>

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace brdfnav {

// --- Metrics the paper compares its own (image_distance) with --------------------------------

// RMS over covered pixels and the 3 channels of the linear difference A - B (no cube root).
double rgb_distance(const Image& a, const Image& b);
// RMS over covered pixels of the CIE 1976 colour difference (lab_from_rec709 in core/cielab.h)
// with the D65 white scaled to luminance `white_y`. HDR pixels brighter than the white get
// L* > 100, which the cube-root law extends to without a break.
double lab_distance(const Image& a, const Image& b, double white_y);
// Mean Rec. 709 luminance over the covered pixels (the CIELAB white of a scene: the diffuse
// image's, i.e. what a white Lambertian sphere shows on average).
double mean_luminance(const Image& image);
// The cosine-weighted BRDF-space L2 distance (paper, section 2; fit.h's metric):
//   sqrt(sum_k w_k mean_c |f_A,c - f_B,c|^2)
// over make_fit_quadrature() of the material whose own norm is larger, which resolves the sharper
// lobe (the broader one is covered by the quadrature's cosine half). Delta terms are left out.
double brdf_distance(const Material& a, const Material& b);

// --- Fitting helpers ---------------------------------------------------------------------------

struct LineFit {
  double intercept = 0, slope = 0;
  double r2 = 0;  // coefficient of determination (1 for a perfect line)
};
// Least-squares line y = intercept + slope x. Needs two distinct x.
LineFit fit_line(std::span<const double> x, std::span<const double> y);
// The s minimising sum (s v_i - r_i)^2; 0 when v is all zero.
double least_squares_scale(std::span<const double> values, std::span<const double> reference);
// {0, s0, s0 + s1, ...}: the distance walked along a series of steps.
std::vector<double> cumulative(std::span<const double> steps);
// Standard deviation / mean (population); 0 for an empty series.
double coefficient_of_variation(std::span<const double> values);
// `count` abscissae that split a non-decreasing cumulative curve (values at `x`) into equal
// steps, by linear interpolation between the samples; the first and last are x's ends.
std::vector<double> equal_steps(std::span<const double> x, std::span<const double> curve,
                                int count);

// --- Figure 2: Pellacini et al.'s gloss stimuli ------------------------------------------------

// Isotropic Ward with alpha_x = alpha_y = alpha and grey rho_d = rho_s = 0.1, as in the figures.
Material ward_sample(double alpha);

// Rec. 709 luminance of an environment map: its brightest texel, and its mean over the sphere of
// directions (each texel weighted by its solid angle). Their ratio is what bends Figure 2's
// curve: the sharper a lobe, the more it shows a small, very bright source as a small, very bright
// spot (docs/VALIDATION.md).
struct EnvLuminance {
  double peak = 0, mean = 0;
};
EnvLuminance env_luminance(const EnvMap& env);

struct CumulativeCurve {
  std::string metric;          // cube_root, cielab, rgb, brdf_l2
  std::vector<double> values;  // cumulative distance at each stimulus, from 0
  LineFit fit;                 // against d
};

struct PellaciniStudy {
  std::vector<double> d;                // distinctness of image d = 1 - alpha, 0.80 .. 0.99
  double white_y = 0;                   // the CIELAB white (mean_luminance of the diffuse image)
  std::vector<CumulativeCurve> curves;  // cube_root, cielab, rgb, brdf_l2, in that order
  EnvLuminance env;                     // of the renderer's map
};

// 11 stimuli evenly spaced in d from 0.8 to 0.99; the cumulative distance of successive stimuli
// under each metric, and how straight each curve is in d (the subjects' ratings are linear in d).
PellaciniStudy pellacini_study(Renderer& renderer);

// --- Figure 3: dependence on the environment ---------------------------------------------------

// Every ordered pair's distance between `samples` (symmetric, zero diagonal).
Eigen::MatrixXd image_distances(Renderer& renderer, const std::vector<Material>& samples);
Eigen::MatrixXd brdf_distances(const std::vector<Material>& samples);

struct Agreement {
  double scale = 0;   // least-squares scale of `other` onto `reference` over the n (n - 1) pairs
  double within = 0;  // fraction of pairs with |scale * other - reference| <= tolerance * reference
};
Agreement compare_distances(const Eigen::MatrixXd& reference, const Eigen::MatrixXd& other,
                            double tolerance);

// Figure 3's samples: 25 grey Ward lobes (ward_sample), alpha 0.01 .. 0.36 evenly spaced.
struct SceneSamples {
  std::vector<double> alpha;
  std::vector<Material> materials;
  std::size_t reference_sample = 0;  // the sample nearest alpha = 0.07 (the paper's Figure 3)
};
SceneSamples scene_samples();

// The name of the BRDF-space metric's entry in a SceneStudy.
inline const std::string kBrdfL2Entry = "brdf_l2";

struct SceneEntry {
  std::string name;           // the environment's name, or kBrdfL2Entry
  Eigen::MatrixXd distances;  // unscaled
  Agreement agreement;        // with the first entry's distances
};

struct SceneStudy {
  std::vector<double> alpha;  // SceneSamples::alpha
  std::size_t reference_sample = 0;
  double tolerance = 0.2;
  std::vector<SceneEntry> entries;  // one per environment, in order, then brdf_l2
  // within(i, j): the agreement of entry j with entry i taken as the reference (row 0 holds the
  // entries' own `agreement.within`): how alike any two maps see the samples.
  Eigen::MatrixXd within;
};

// `maps`: the image_distances of the samples under each environment, the reference first; the
// others (e.g. a constant environment, which the paper expects to fail) and the BRDF-space
// metric, appended here, are compared with it. The caller renders one map at a time, so that only
// one renderer (a map's largest allocation) need be alive.
SceneStudy scene_study(const SceneSamples& samples, std::vector<SceneEntry> maps);

// How representative each map is of the others (docs/VALIDATION.md, "Choosing the default map").
// Two maps agree when each one's distances, scaled onto the other's, are within the tolerance on
// at least kAgreeingWithin of the pairs: both ways, since an artist's steps measured under one
// map should hold under the lighting they render in, and the other way round.
inline constexpr double kAgreeingWithin = 0.85;  // the paper's "over 85%" (Figure 3)
// Mean agreements this close count as equal: one percentage point, 3 of the 300 pairs of samples
// per comparison, below what the image resolution alone moves them (64, 128, 256 px: up to 0.06).
inline constexpr double kMeanAgreementTie = 0.01;

struct MapAgreement {
  std::size_t agreeing = 0;  // other maps it agrees with, both ways (>= kAgreeingWithin)
  double mean = 0;           // mean over the other maps of min(within(i, j), within(j, i))
};

// For each of the first `maps` entries of `within` (SceneStudy::within; the natural maps, the
// constant environment and the BRDF-space metric after them are not counted).
std::vector<MapAgreement> map_agreements(const Eigen::MatrixXd& within, std::size_t maps);

// The index of the most representative map: the most others agreeing; among those, the highest
// mean agreement, means within kMeanAgreementTie of the highest counting as equal; among those,
// the highest `r2` (Figure 2's R^2 of the cube-root metric under each map, same order).
std::size_t most_representative(const std::vector<MapAgreement>& maps,
                                const std::vector<double>& r2);

// --- Figures 8 and 9: uniform spacing ----------------------------------------------------------

// A one-parameter family of materials (e.g. Ward's alpha, Lafortune's cz at fixed n).
using MaterialFamily = std::function<Material(double)>;

// What the image metric's spacing is compared with: equal steps of the BRDF-space L2 metric
// (Figure 8) or of the parameter itself (Figure 9).
enum class Baseline { brdf_l2, linear };

struct SpacedRow {
  std::string spacing;         // brdf_l2, linear or image
  std::vector<double> values;  // the parameter of each sample
  std::vector<Image> images;
  std::vector<double> steps;  // image_distance between successive samples
  double cv = 0;              // coefficient_of_variation(steps): 0 is perfectly uniform
};

struct SpacingStudy {
  std::vector<double> fine;              // where the curves are measured (the grid, refined)
  std::vector<double> cumulative_image;  // along `fine`
  std::vector<double> cumulative_baseline;
  SpacedRow baseline, image;
};

// Measures both cumulative curves on `fine` (increasing), bisecting its segments wherever one
// holds more than a quarter of a row's step of either curve (up to 128 samples), places `count`
// samples at equal steps of each curve, renders the two rows and measures their image steps.
SpacingStudy spacing_study(Renderer& renderer, const MaterialFamily& family,
                           const std::vector<double>& fine, Baseline baseline, int count);

// --- The embedding (section 3.2) ---------------------------------------------------------------

// The distance between two embeddings keeping only the first `k` coefficients of each channel
// (ModelEmbedding::embed's layout: three blocks of components() coefficients).
double truncated_distance(const Eigen::VectorXf& a, const Eigen::VectorXf& b, int k);

struct EmbeddingErrors {
  int coefficients = 0;        // k per channel
  double median = 0, p95 = 0;  // of |embedded - exact| / exact
};

struct EmbeddingStudy {
  int pairs = 0;  // of each kind
  // k = 4, 8, 16, ... and the database's full count, for pairs of materials
  std::vector<EmbeddingErrors> anywhere;  // anywhere in the grids: interpolation and truncation
  std::vector<EmbeddingErrors> on_nodes;  // on grid nodes, q included: truncation alone
};

// `pairs` pairs of random materials of the database's models (from a fixed seed) of each kind:
//   anywhere: parameters uniform in grid coordinates, rho_d in [0, 0.5] and rho_s in [0, 1];
//   on_nodes: parameters on grid nodes, rho_d + rho_s in [0, 1] split at a q node;
// per channel. The relative error of the embedded distance against the exact image_distance of
// renderings by `renderer`, which must match the database (its env, scene and resolution).
EmbeddingStudy embedding_study(const Database& db, Renderer& renderer, int pairs,
                               std::uint32_t seed = 1);

}  // namespace brdfnav
