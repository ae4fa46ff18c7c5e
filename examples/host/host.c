/* A renderer's integrator in miniature, on brdfnav's C ABI alone (brdfnav/brdfnav.h,
 * libbrdfnav.so): the file a TD copies to wire brdfnav into a renderer.
 *
 *   brdfnav_example_host MATERIAL [SAMPLES]
 *
 * MATERIAL is a material file or an export (`brdfnav export`; YAML), or an inline spec such as
 * "ward:alpha_x=0.1,alpha_y=0.05,rho_d=0.2". For a few outgoing directions it
 *   1. shades: evaluates f(wi, wo) at the mirror direction and off it;
 *   2. integrates: estimates the directional albedo  a(wo) = integral f(wi, wo) cos(wi) dwi  by
 *      importance sampling (sum of f cos / pdf over SAMPLES draws, the delta lobe included);
 *   3. checks what an integrator relies on: each non-delta sample's f and pdf equal eval() and
 *      pdf() at the sampled direction, pdf > 0 wherever a sample lands, and the estimate is
 *      finite and not negative.
 * Exit status 0 when every check passes, 1 otherwise, 2 for bad usage. */
#include <brdfnav/brdfnav.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

/* A small deterministic generator (splitmix64): numbers in [0, 1), as brdfnav_closure_sample()
 * requires. A renderer passes its own sampler's numbers. */
static double next_uniform(uint64_t* state) {
  uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return (double)(z >> 11) * (1.0 / 9007199254740992.0); /* 53 bits: always < 1 */
}

static int failed(brdfnav_status status, const char* what) {
  if (status == BRDFNAV_OK) return 0;
  fprintf(stderr, "brdfnav_example_host: %s failed (status %d): %s\n", what, (int)status,
          brdfnav_geterror());
  return 1;
}

static int close_to(double a, double b) {
  return fabs(a - b) <= 1e-9 * fmax(1.0, fmax(fabs(a), fabs(b)));
}

/* Albedo at wo by importance sampling, with the consistency checks of step 3. Returns the
 * number of failed checks; *mean and *error get the estimate and its standard error (green). */
static int integrate(const brdfnav_closure* closure, const double wo[3], int samples, uint64_t* rng,
                     double* mean, double* error) {
  double sum = 0, sum2 = 0;
  int bad = 0;
  for (int i = 0; i < samples; ++i) {
    const double uc = next_uniform(rng), u1 = next_uniform(rng), u2 = next_uniform(rng);
    brdfnav_sample s;
    if (failed(brdfnav_closure_sample(closure, wo, uc, u1, u2, &s), "sample")) return bad + 1;
    double weight = 0;
    if (s.sampled && s.pdf > 0) weight = s.f[1] * s.wi[2] / s.pdf;
    if (s.sampled && !s.is_delta) {
      double f[3], pdf = 0;
      if (failed(brdfnav_closure_eval(closure, s.wi, wo, f), "eval") ||
          failed(brdfnav_closure_pdf(closure, s.wi, wo, &pdf), "pdf"))
        return bad + 1;
      if (!close_to(f[0], s.f[0]) || !close_to(f[1], s.f[1]) || !close_to(f[2], s.f[2]) ||
          !close_to(pdf, s.pdf) || !(pdf > 0)) {
        if (bad++ < 3)
          fprintf(stderr, "sample %d: sample() says f %.9g pdf %.9g, eval/pdf say %.9g %.9g\n", i,
                  s.f[1], s.pdf, f[1], pdf);
      }
    }
    sum += weight;
    sum2 += weight * weight;
  }
  *mean = sum / samples;
  *error = sqrt(fmax(0.0, sum2 / samples - *mean * *mean) / samples);
  return bad;
}

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    fprintf(stderr, "usage: %s MATERIAL [SAMPLES]\n", argv[0]);
    return 2;
  }
  const int samples = argc == 3 ? atoi(argv[2]) : 20000;
  if (samples < 100) {
    fprintf(stderr, "%s: SAMPLES must be at least 100\n", argv[0]);
    return 2;
  }
  /* A host that loads the library at run time checks its version before anything else. */
  if (brdfnav_abi_version() != BRDFNAV_ABI_VERSION) {
    fprintf(stderr, "libbrdfnav ABI %d, this host was built for %d\n", brdfnav_abi_version(),
            BRDFNAV_ABI_VERSION);
    return 1;
  }
  brdfnav_closure* closure = NULL;
  if (failed(brdfnav_closure_load(argv[1], &closure), "loading the material")) return 1;
  int model = 0;
  brdfnav_model_desc desc;
  const char* colorspace = "";
  if (failed(brdfnav_closure_model(closure, &model), "model") ||
      failed(brdfnav_get_model(model, &desc), "model description") ||
      failed(brdfnav_closure_colorspace(closure, &colorspace), "colour space")) {
    brdfnav_closure_destroy(closure);
    return 1;
  }
  printf("material: %s (%s), colour space %s%s\n", desc.name, desc.title, colorspace,
         desc.has_mirror ? ", with a mirror (delta) lobe" : "");

  /* Directions are in the local shading frame: +z the normal, both pointing away. */
  const double elevations[] = {0.0, 30.0, 60.0, 80.0};
  uint64_t rng = 1;
  int bad = 0;
  printf("theta_o  f(mirror) green  f(30 deg off) green  albedo green (+- std. error)\n");
  for (int e = 0; e < 4; ++e) {
    const double t = elevations[e] * 3.14159265358979323846 / 180.0;
    const double wo[3] = {sin(t), 0.0, cos(t)}, mirror[3] = {-sin(t), 0.0, cos(t)};
    const double t_off = elevations[e] >= 30.0 ? t - 0.5235987755982988 : t + 0.5235987755982988;
    const double off[3] = {-sin(t_off), 0.0, cos(t_off)};
    double f_mirror[3], f_off[3], albedo = 0, error = 0;
    if (failed(brdfnav_closure_eval(closure, mirror, wo, f_mirror), "eval") ||
        failed(brdfnav_closure_eval(closure, off, wo, f_off), "eval")) {
      ++bad;
      break;
    }
    bad += integrate(closure, wo, samples, &rng, &albedo, &error);
    printf("%5.0f    %-16.6g %-19.6g %.4f +- %.4f\n", elevations[e], f_mirror[1], f_off[1], albedo,
           error);
    if (!isfinite(albedo) || albedo < 0) {
      fprintf(stderr, "albedo %g at theta_o = %.0f\n", albedo, elevations[e]);
      ++bad;
    }
  }
  brdfnav_closure_destroy(closure);
  if (bad) fprintf(stderr, "%d check(s) failed\n", bad);
  return bad ? 1 : 0;
}
