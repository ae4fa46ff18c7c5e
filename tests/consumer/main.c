/* A host of libbrdfnav.so found with find_package(brdfnav): creates a closure from a material
 * struct and from an inline spec, evaluates both at a mirror configuration, and fails unless the
 * two agree and show a specular highlight above the diffuse level. */
#include <brdfnav/brdfnav.h>

#include <math.h>
#include <stdio.h>

static int check(brdfnav_status status, const char* what) {
  if (status == BRDFNAV_OK) return 1;
  fprintf(stderr, "%s failed (%d): %s\n", what, (int)status, brdfnav_geterror());
  return 0;
}

int main(void) {
  const brdfnav_param_value params[] = {{"alpha_x", 0.1}, {"alpha_y", 0.05}};
  const brdfnav_material material = {"ward",      params, 2, {0.2, 0.2, 0.2}, {0.04, 0.04, 0.04},
                                     "lin_rec709"};
  const double wi[3] = {0.3, 0.0, 1.0}, wo[3] = {-0.3, 0.0, 1.0};
  brdfnav_closure *from_struct = NULL, *from_spec = NULL;
  double f_struct[3], f_spec[3];
  int ok = 0;

  if (brdfnav_abi_version() != BRDFNAV_ABI_VERSION) {
    fprintf(stderr, "ABI version %d, expected %d\n", brdfnav_abi_version(), BRDFNAV_ABI_VERSION);
    return 1;
  }
  if (check(brdfnav_closure_create(&material, &from_struct), "create") &&
      check(brdfnav_closure_load("ward:alpha_x=0.1,alpha_y=0.05,rho_d=0.2,rho_s=0.04", &from_spec),
            "load") &&
      check(brdfnav_closure_eval(from_struct, wi, wo, f_struct), "eval") &&
      check(brdfnav_closure_eval(from_spec, wi, wo, f_spec), "eval")) {
    printf("f = %.9g %.9g %.9g\n", f_struct[0], f_struct[1], f_struct[2]);
    ok = f_struct[0] == f_spec[0] && f_struct[1] == f_spec[1] && f_struct[2] == f_spec[2] &&
         f_struct[0] > 0.2 / 3.14159265358979 && isfinite(f_struct[0]);
  }
  brdfnav_closure_destroy(from_struct);
  brdfnav_closure_destroy(from_spec);
  return ok ? 0 : 1;
}
