// The neighbour service of the navigation interface (paper, sections 3.3 and 4): for a material and
// a radius eps in the units of the cube-root RMS metric, the variations at embedded distance eps in
// each tab of the interface, read from a precomputed database (docs/DATABASE.md). The algorithms
// and their choices are in docs/NAVIGATION.md.
//
// A Navigator is immutable once built: any number of threads may query one concurrently; every
// query allocates its own working memory.
#pragma once

#include <brdfnav/core/error.h>
#include <brdfnav/core/material.h>
#include <brdfnav/navigator/database.h>

#include <Eigen/Core>

#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace brdfnav {

// A query the database cannot answer (a model it does not hold, a colour space other than its
// lin_rec709) or that makes no sense (a radius that is not finite or below kMinRadius, k < 1).
// The message names the argument.
using NavigatorError = LayerError<struct NavigatorErrorTag, ErrorCode::invalid_argument>;

// The smallest radius a query may ask for. Embedded distances carry single-precision noise of
// about 1e-7 (measured on the test database); at 1e-4 that is 0.1% of the radius, while below
// 1e-7 the walks would stop at noise, far from the radius. The navigator page starts at 0.002.
inline constexpr double kMinRadius = 1e-4;

// The k of the models and gallery tabs when a caller gives none: the paper's 8.
inline constexpr int kDefaultClusters = 8;

// Whether `radius` is one a query may ask for, and what every front end says of one that is not
// ("must be a finite distance of at least 0.0001").
inline bool valid_radius(double radius) {
  return std::isfinite(radius) && radius >= kMinRadius;
}
std::string radius_requirement();

// The tabs of the interface. `gallery` is the start gallery: the most different materials of
// the database, whatever the current material.
enum class Tab { lobe, diffuse, specular, models, gallery };
inline constexpr Tab kTabs[] = {Tab::lobe, Tab::diffuse, Tab::specular, Tab::models, Tab::gallery};
// "lobe", "diffuse", "specular", "models", "gallery".
std::string_view tab_name(Tab tab);
std::optional<Tab> find_tab(std::string_view name);

// One offer of a tab. neighbors() returns a tab's offers in ring order: each pair of opposite
// directions as i and i + n/2 when every offer has its opposite (the lobe and colour tabs), so
// that a front end placing offer i at angle 2 pi i / n puts each pair on one line through the
// current material; offers without an opposite (models, gallery) after the pairs.
struct Neighbor {
  Tab tab;
  // lobe: "<param>+" / "<param>-" (and Ward's "alpha+" / "alpha-", both slopes by one factor);
  // diffuse, specular: "L+", "L-", "ab+0", "ab+45", ..., "ab+315"; models, gallery: the model.
  std::string label;
  Material material;
  double distance = 0;  // embedded distance from the current material, or exact (ExactSteps)
  // The walk reached the end of a parameter's database range before distance eps (lobe and
  // models tabs): the neighbour is at that end.
  bool at_boundary = false;
  // The colour left the valid range (rho_d in [0, 1], rho_s in [0, 10]) before distance eps
  // (colour tabs): the neighbour is the farthest valid colour in that direction.
  bool clamped = false;
  // Models tab: the model cannot come within eps of the current material (the closest it comes
  // in the metric, searched from its best fit, is farther); the offer is that closest material,
  // at `distance`.
  bool beyond_radius = false;
  // What the offer looks like in an artist's words ("sharper", "lighter", "towards red",
  // "as Ward (anisotropic)"), and the parameter change for a tooltip ("alpha_x 0.1 -> 0.0707").
  std::string words = {}, change = {};
  // The index of the opposite offer in the same list, -1 when it has none.
  int opposite = -1;
};

// The names of a neighbour's flags, in this order: "at_boundary", "clamped", "beyond_radius"
// (the `flags` list of its YAML and JSON forms).
std::vector<std::string_view> flag_names(const Neighbor& n);

// A material's best fit by another model (the database's conversion tables, interpolated).
struct Equivalent {
  Material material;
  double residual = 0;  // embedded distance between the material and the fit
};

// Steps measured by rendering: the embedding places each offer at eps to within its own error
// (a few percent, more for sharp lobes between grid nodes); a caller with a renderer (the server,
// the CLI; the navigator has none) hands its distance here and neighbors() moves every offer
// along its path until the rendered distance is at eps.
struct ExactSteps {
  // The distance in the image metric from the query's current material to `m`.
  std::function<double(const Material& m)> distance;
  double tolerance = 0.02;  // |distance / eps - 1| at which an offer stops moving
  int renders = 8;          // at most, per offer
};

struct NavigatorOptions {
  int threads = 1;             // workers for k-means (the answers do not depend on it)
  double delta_factor = 0.3;   // models tab: drop neighbours within delta_factor * eps of the
                               // current model (the paper's delta = 0.3 eps)
  bool ward_isotropic = true;  // lobe tab of Ward: also "alpha+" / "alpha-"
};

class Navigator {
 public:
  // Database::open(dir) (throws DatabaseError naming the file), then prepares the gallery.
  static Navigator open(const std::filesystem::path& dir, const NavigatorOptions& options = {});
  explicit Navigator(Database database, const NavigatorOptions& options = {});

  const Database& database() const { return database_; }
  const NavigatorOptions& options() const { return options_; }

  // The neighbours of `current` in one tab at embedded distance `radius`. `clusters` is the k of
  // the models and gallery tabs (at most that many neighbours). With `exact`, the lobe, colour
  // and models tabs' offers move along their paths to the exact distance `radius` and report it
  // (an offer flagged beyond_radius stays the fit). Throws NavigatorError, and MaterialError for
  // an invalid material.
  std::vector<Neighbor> neighbors(const Material& current, double radius, Tab tab,
                                  int clusters = kDefaultClusters,
                                  const ExactSteps* exact = nullptr) const;
  // `count` maximally different materials over every model (k-means over every grid node, each
  // with a grey rho_d and the rho_s that puts it at one common distance from matte grey). Each
  // neighbour's distance is from that matte grey material.
  std::vector<Neighbor> gallery(int count = 8) const;

  // Where an artist starts: the database's first model with each parameter at the middle of
  // its database axis (in the parameter's scale), grey rho_d = 0.2 and rho_s = 0.3, a visible
  // highlight. Its variations have room in every direction of every tab (a default material's
  // dim rho_s = 0.04 sent most lobe walks to the grid's ends).
  Material start_material() const;

  // The embedding of a material (its model must be in the database) and the distance through it.
  Eigen::VectorXf embed(const Material& m) const;
  double distance(const Material& a, const Material& b) const;
  // `m` converted to model `to`: the fit's parameters interpolated over m's grid (in each
  // parameter's scale), rho_d kept, rho_s scaled by the fit (capped at kRhoSMax).
  Material convert(const Material& m, ModelId to) const;
  // The best fit of `m` in every other model of the database, in model order.
  std::vector<Equivalent> equivalents(const Material& m) const;

  // Returns the pages of every model's mapped embedding to the system
  // (ModelEmbedding::release_pages): they are read back from the page cache by the next query
  // that needs them. For a long-running host between bursts of queries, which otherwise keeps
  // every page any query has touched.
  void release_pages() const;

 private:
  const ModelEmbedding& embedding_of(ModelId id) const;
  // A tab's offers in the order they were found, without their words.
  std::vector<Neighbor> tab_offers(const Material& current, double radius, Tab tab, int clusters,
                                   const ExactSteps* exact) const;
  std::vector<Neighbor> lobe_tab(const Material& current, double radius,
                                 const ExactSteps* exact) const;
  std::vector<Neighbor> models_tab(const Material& current, double radius, int clusters,
                                   const ExactSteps* exact) const;
  std::vector<Neighbor> gallery_tab(const Eigen::VectorXf& from, int count) const;
  void build_gallery();

  Database database_;
  NavigatorOptions options_;
  Material matte_;  // the gallery's reference: grey rho_d, rho_s = 0
  std::vector<Material> gallery_materials_;
  Eigen::MatrixXf gallery_embeddings_;  // one column per gallery material
};

}  // namespace brdfnav
