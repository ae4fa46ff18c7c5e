/* A lookdev host of libbrdfnav_navigator.so found with find_package(brdfnav COMPONENTS
 * navigator): opens the database given as its argument, takes the gallery's first material,
 * asks for its lobe variations and makes a closure of libbrdfnav.so from one of them. Fails
 * unless each step works and a missing database is BRDFNAV_ERROR_DATABASE with a message. */
#include <brdfnav/brdfnav_navigator.h>

#include <stdio.h>
#include <string.h>

static int check(brdfnav_status status, const char* what) {
  if (status == BRDFNAV_OK) return 1;
  fprintf(stderr, "%s failed (%d): %s\n", what, (int)status, brdfnav_navigator_geterror());
  return 0;
}

int main(int argc, char** argv) {
  brdfnav_navigator *navigator = NULL, *missing = NULL;
  brdfnav_neighbors *gallery = NULL, *variations = NULL;
  brdfnav_neighbor start, variation;
  brdfnav_closure* closure = NULL;
  size_t count = 0;
  int ok = 0;

  if (argc != 2) {
    fprintf(stderr, "usage: %s DATABASE\n", argv[0]);
    return 2;
  }
  if (brdfnav_navigator_abi_version() != BRDFNAV_NAVIGATOR_ABI_VERSION) {
    fprintf(stderr, "navigator ABI version %d, expected %d\n", brdfnav_navigator_abi_version(),
            BRDFNAV_NAVIGATOR_ABI_VERSION);
    return 1;
  }
  if (brdfnav_navigator_open("/nonexistent/database", &missing) != BRDFNAV_ERROR_DATABASE ||
      missing != NULL || strstr(brdfnav_navigator_geterror(), "/nonexistent/database") == NULL) {
    fprintf(stderr, "a missing database was not reported: '%s'\n", brdfnav_navigator_geterror());
    return 1;
  }
  if (check(brdfnav_navigator_open(argv[1], &navigator), "open") &&
      check(brdfnav_navigator_gallery(navigator, 3, &gallery), "gallery") &&
      check(brdfnav_neighbors_get(gallery, 0, &start), "gallery entry") &&
      check(brdfnav_navigator_neighbors(navigator, &start.material, 0.03, BRDFNAV_TAB_LOBE, 8,
                                        &variations),
            "neighbors") &&
      check(brdfnav_neighbors_count(variations, &count), "count") && count > 0 &&
      check(brdfnav_neighbors_get(variations, 0, &variation), "variation")) {
    ok = brdfnav_closure_create(&variation.material, &closure) == BRDFNAV_OK;
    if (!ok) fprintf(stderr, "closure: %s\n", brdfnav_geterror());
    printf("%s: %zu variations of a %s material, the first '%s' at %.4f\n", argv[1], count,
           start.material.model, variation.label, variation.distance);
  }
  brdfnav_closure_destroy(closure);
  brdfnav_neighbors_free(variations);
  brdfnav_neighbors_free(gallery);
  brdfnav_navigator_close(navigator);
  return ok ? 0 : 1;
}
