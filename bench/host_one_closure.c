/* The smallest renderer host: creates one closure from an inline spec, evaluates it once. What
 * brdfnav_bench_host measures as a whole process (libraries loaded, wall time, peak memory). */
#include <brdfnav/brdfnav.h>

#include <stdio.h>

int main(void) {
  const double wi[3] = {0.3, 0.0, 1.0}, wo[3] = {-0.3, 0.0, 1.0};
  double f[3];
  brdfnav_closure* closure = NULL;
  if (brdfnav_closure_load("ward:alpha_x=0.1,alpha_y=0.05,rho_d=0.2", &closure) != BRDFNAV_OK ||
      brdfnav_closure_eval(closure, wi, wo, f) != BRDFNAV_OK) {
    fprintf(stderr, "%s\n", brdfnav_geterror());
    return 1;
  }
  printf("%.9g %.9g %.9g\n", f[0], f[1], f[2]);
  brdfnav_closure_destroy(closure);
  return 0;
}
