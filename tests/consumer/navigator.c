/* A lookdev host of libbrdfnav_navigator.so found with find_package(brdfnav COMPONENTS
 * navigator): opens the database given as its argument, takes the gallery's first material,
 * asks for its lobe variations, makes a closure of libbrdfnav.so from one of them and fetches the
 * variation's display thumbnail on the config's default display and view. Fails unless each step
 * works, the thumbnail covers its centre and not its corner, and a missing database is
 * BRDFNAV_ERROR_DATABASE with a message. */
#include <brdfnav/brdfnav_navigator.h>

#include <stdio.h>
#include <stdlib.h>
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
  size_t count = 0, displays = 0;
  const char *display = NULL, *view = NULL;
  int ok = 0, width = 0, height = 0;
  unsigned char* rgba = NULL;

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
  /* The variation's thumbnail as the config's default display and view show it. */
  if (ok) {
    ok = check(brdfnav_navigator_displays(navigator, &displays), "displays") && displays > 0 &&
         check(brdfnav_navigator_display(navigator, 0, &display), "display") &&
         check(brdfnav_navigator_view(navigator, display, 0, &view), "view") &&
         check(brdfnav_navigator_thumbnail_size(navigator, &width, &height), "thumbnail size") &&
         width > 0 && height > 0;
    if (ok) rgba = malloc((size_t)width * (size_t)height * 4);
    ok = ok && rgba != NULL &&
         check(brdfnav_navigator_thumbnail(navigator, &variation.material, display, view, &width,
                                           &height, rgba, (size_t)width * (size_t)height * 4),
               "thumbnail");
    if (ok) {
      const unsigned char* centre = rgba + ((size_t)(height / 2) * (size_t)width + width / 2) * 4;
      /* Straight alpha over nothing (ABI 3): the corner is 0 0 0 0, not mid grey. */
      ok = centre[3] == 255 && rgba[0] == 0 && rgba[1] == 0 && rgba[2] == 0 && rgba[3] == 0;
      printf("thumbnail %dx%d on %s / %s: centre %d %d %d, corner alpha %d\n", width, height,
             display, view, centre[0], centre[1], centre[2], rgba[3]);
    }
  }
  free(rgba);
  brdfnav_closure_destroy(closure);
  brdfnav_neighbors_free(variations);
  brdfnav_neighbors_free(gallery);
  brdfnav_navigator_close(navigator);
  return ok ? 0 : 1;
}
