// PLACEHOLDER until the He implementation lands (same session).
#include <brdfnav/core/he.h>
namespace brdfnav {
Rgb He::eval(const Vec3&, const Vec3&) const { return Rgb::Zero(); }
std::optional<Vec3> He::sample(const Vec3&, const Vec2&) const { return std::nullopt; }
double He::pdf(const Vec3&, const Vec3&) const { return 0; }
double He::albedo_hint(const Vec3&) const { return 0; }
Rgb He::mirror_weight(const Vec3&) const { return Rgb::Zero(); }
}  // namespace brdfnav
