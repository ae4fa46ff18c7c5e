/* brdfnav C ABI: the analytic BRDF models of brdfnav (Blinn-Phong, Ward, Cook-Torrance,
 * Lafortune, He et al., GGX) as closures that a renderer or tool loads from libbrdfnav.so, which
 * needs nothing but the C and C++ runtimes and yaml-cpp. The navigator, which offers a
 * material's variations at equal visual distance, is a library of its own
 * (brdfnav/brdfnav_navigator.h, libbrdfnav_navigator.so).
 *
 * Conventions
 * - Hosts that load the library at run time call brdfnav_abi_version() first and use nothing
 *   else unless it equals the BRDFNAV_ABI_VERSION they were compiled with.
 * - Directions are in the local shading frame: normal +z, tangent +x, bitangent +y, all
 *   pointing away from the surface. Any finite non-zero vector is accepted and normalised.
 * - f is the BRDF without the cosine factor (1/sr), RGB in the material's colour space.
 * - Functions that can fail return a brdfnav_status. On failure they leave their outputs
 *   untouched (except the functions that create an object, which set *out to NULL) and
 *   brdfnav_geterror() returns a message for the calling thread. No C++ exception escapes.
 * - Closures are immutable: eval, sample and pdf may run concurrently on one closure.
 * - Strings returned by the library (names, descriptions) live as long as the library is
 *   loaded. Model and parameter indices are stable for one BRDFNAV_ABI_VERSION.
 */
#ifndef BRDFNAV_BRDFNAV_H
#define BRDFNAV_BRDFNAV_H

#include <stddef.h>

/* 2: added the navigator (brdfnav_navigator_*, brdfnav_neighbors_*, BRDFNAV_ERROR_DATABASE).
 * 3: the navigator moved to libbrdfnav_navigator.so (brdfnav_navigator.h); closures unchanged. */
#define BRDFNAV_ABI_VERSION 3

#if defined(__GNUC__)
#define BRDFNAV_API __attribute__((visibility("default")))
#else
#define BRDFNAV_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

typedef enum brdfnav_status {
  BRDFNAV_OK = 0,
  /* A null pointer, an index out of range, a zero or non-finite direction, a random number
   * outside [0, 1), or a material struct that names an unknown model or parameter or holds
   * an out-of-range value. */
  BRDFNAV_ERROR_INVALID_ARGUMENT = 1,
  /* An inline spec or a YAML material file that is malformed or out of range; the message
   * names the file, the line and the key. */
  BRDFNAV_ERROR_PARSE = 2,
  /* A material file that cannot be read (missing, a directory, no permission). */
  BRDFNAV_ERROR_IO = 3,
  BRDFNAV_ERROR_OUT_OF_MEMORY = 4,
  /* An unexpected failure inside the library (a bug: please report the message). */
  BRDFNAV_ERROR_INTERNAL = 5,
  /* A navigation database that is missing, unreadable, corrupt or inconsistent; the message
   * names the file (libbrdfnav_navigator.so only). */
  BRDFNAV_ERROR_DATABASE = 6
} brdfnav_status;

typedef enum brdfnav_scale {
  BRDFNAV_SCALE_LINEAR = 0,
  BRDFNAV_SCALE_LOG = 1 /* grid nodes evenly spaced in log(value) */
} brdfnav_scale;

typedef struct brdfnav_model_desc {
  const char* name;  /* canonical name: "ward", ... (YAML, inline specs) */
  const char* title; /* for people */
  int param_count;   /* non-linear parameters, see brdfnav_get_param() */
  int has_mirror;    /* 1 when the model has a delta (mirror) term: sample() may return it */
} brdfnav_model_desc;

/* One row of a model's parameter table. */
typedef struct brdfnav_param_desc {
  const char* name;        /* canonical name: "alpha_x", ... */
  const char* unit;        /* "1" for dimensionless, "um" for micrometres */
  const char* description; /* one line */
  double valid_min;        /* inclusive range accepted by brdfnav_closure_create() */
  double valid_max;
  double default_value;
  double grid_min; /* the precompute grid (ignored when node_count > 0) */
  double grid_max;
  int grid_count;
  brdfnav_scale scale;
  const double* nodes; /* explicit increasing grid nodes, or NULL */
  size_t node_count;
} brdfnav_param_desc;

typedef struct brdfnav_param_value {
  const char* name;
  double value;
} brdfnav_param_value;

/* A material: f = rho_d / pi + rho_s * lobe(model, params). */
typedef struct brdfnav_material {
  const char* model;                 /* canonical model name */
  const brdfnav_param_value* params; /* by name, any order; omitted ones take their defaults */
  size_t param_count;
  double rho_d[3];        /* diffuse albedo, each in [0, 1] */
  double rho_s[3];        /* specular multiplier, each in [0, 10] */
  const char* colorspace; /* scene-linear colour space of rho_d and rho_s; NULL: lin_rec709 */
} brdfnav_material;

typedef struct brdfnav_sample {
  int sampled;  /* 0 when the chosen strategy produced no direction (then the rest is 0) */
  int is_delta; /* 1 for the mirror term: pdf is a discrete probability, not a density */
  double wi[3]; /* sampled incident direction, local frame */
  double f[3];  /* BRDF value without the cosine; for a delta: reflectance / cos(wi) */
  double pdf;   /* solid-angle density (or the discrete probability for a delta) */
} brdfnav_sample;

typedef struct brdfnav_closure brdfnav_closure; /* opaque */

BRDFNAV_API int brdfnav_abi_version(void);

/* The last failure's message on the calling thread ("" if none). Valid until the next failing
 * call on this thread. Successful calls do not clear it. */
BRDFNAV_API const char* brdfnav_geterror(void);

/* Models are indexed 0 .. brdfnav_model_count() - 1. */
BRDFNAV_API int brdfnav_model_count(void);
BRDFNAV_API brdfnav_status brdfnav_get_model(int model, brdfnav_model_desc* out);
BRDFNAV_API brdfnav_status brdfnav_find_model(const char* name, int* model);
/* Parameters are indexed 0 .. param_count - 1 in the model's table order. */
BRDFNAV_API brdfnav_status brdfnav_get_param(int model, int param, brdfnav_param_desc* out);

/* A closure from a material struct; errors are BRDFNAV_ERROR_INVALID_ARGUMENT. */
BRDFNAV_API brdfnav_status brdfnav_closure_create(const brdfnav_material* material,
                                                  brdfnav_closure** out);
/* A closure from a YAML material file (an existing file, or any *.yaml / *.yml path) or an
 * inline spec "model:key=value,..." such as "ward:alpha_x=0.1,alpha_y=0.05,rho_d=0.2". */
BRDFNAV_API brdfnav_status brdfnav_closure_load(const char* path_or_spec, brdfnav_closure** out);
/* Accepts NULL. */
BRDFNAV_API void brdfnav_closure_destroy(brdfnav_closure* closure);

/* The material's model index and colour space name. */
BRDFNAV_API brdfnav_status brdfnav_closure_model(const brdfnav_closure* closure, int* model);
BRDFNAV_API brdfnav_status brdfnav_closure_colorspace(const brdfnav_closure* closure,
                                                      const char** colorspace);

/* f(wi, wo) without the cosine and without the delta term; zero below the horizon. */
BRDFNAV_API brdfnav_status brdfnav_closure_eval(const brdfnav_closure* closure, const double wi[3],
                                                const double wo[3], double f[3]);
/* Importance-samples wi for wo. uc picks the component (diffuse, lobe, mirror), u1 and u2 the
 * direction; each in [0, 1). */
BRDFNAV_API brdfnav_status brdfnav_closure_sample(const brdfnav_closure* closure,
                                                  const double wo[3], double uc, double u1,
                                                  double u2, brdfnav_sample* out);
/* Solid-angle density of brdfnav_closure_sample() over its non-delta components. */
BRDFNAV_API brdfnav_status brdfnav_closure_pdf(const brdfnav_closure* closure, const double wi[3],
                                               const double wo[3], double* pdf);

#ifdef __cplusplus
}
#endif

#endif /* BRDFNAV_BRDFNAV_H */
