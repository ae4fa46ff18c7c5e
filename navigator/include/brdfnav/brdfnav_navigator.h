/* brdfnav navigator C ABI: opens a database made by `brdfnav precompute` and offers a
 * material's variations at equal visual distance (docs/NAVIGATION.md), and any material's
 * preview thumbnail as an OpenColorIO display shows it, for lookdev tools. It is
 * libbrdfnav_navigator.so, apart from the closures of libbrdfnav.so (brdfnav.h) that a renderer
 * loads: it reads the database's images with OpenEXR and manages colour with OpenColorIO, which
 * a renderer need not take into its process.
 *
 * Conventions are brdfnav.h's, with these of its own:
 * - Hosts that load the library at run time call brdfnav_navigator_abi_version() first and use
 *   nothing else unless it equals the BRDFNAV_NAVIGATOR_ABI_VERSION they were compiled with.
 * - The message of a failed call is brdfnav_navigator_geterror()'s (not brdfnav_geterror()'s:
 *   each library keeps its own per-thread message).
 * - The materials are brdfnav.h's brdfnav_material; a neighbour's material can be passed to
 *   brdfnav_closure_create() of libbrdfnav.so. This library does not need libbrdfnav.so.
 */
#ifndef BRDFNAV_BRDFNAV_NAVIGATOR_H
#define BRDFNAV_BRDFNAV_NAVIGATOR_H

#include <brdfnav/brdfnav.h>

#include <stddef.h>

/* 1: the navigator, moved out of libbrdfnav.so (brdfnav.h's ABI 3) into a library of its own,
 *    with its own version and error message.
 * 2: brdfnav_neighbor gained words, change and opposite (a change of its layout that version 1
 *    did not mark); display thumbnails through OpenColorIO (brdfnav_navigator_displays(),
 *    _display(), _views(), _view(), _thumbnail_size(), _thumbnail()).
 * 3: a thumbnail's bytes are those `brdfnav serve` shows: straight alpha, the sphere's edge
 *    antialiased, nothing composited over grey (the same size and layout as in version 2). */
#define BRDFNAV_NAVIGATOR_ABI_VERSION 3

#ifdef __cplusplus
extern "C" {
#endif

BRDFNAV_API int brdfnav_navigator_abi_version(void);

/* The last failure's message of this library's functions on the calling thread ("" if none).
 * Valid until the next failing call on this thread. Successful calls do not clear it. */
BRDFNAV_API const char* brdfnav_navigator_geterror(void);

/* A navigator opens a database made by `brdfnav precompute`
 * once; each query returns a list of neighbours of a material at embedded distance `radius`
 * (the cube-root RMS metric) in one tab of the interface. A navigator may be queried from any
 * number of threads at once; a list is immutable. Strings and arrays a list hands out live
 * until brdfnav_neighbors_free(). */
typedef enum brdfnav_tab {
  BRDFNAV_TAB_LOBE = 0,     /* each non-linear parameter up and down: labels "alpha_x+", ... */
  BRDFNAV_TAB_DIFFUSE = 1,  /* rho_d along CIELAB: "L+", "L-", "ab+0", "ab+45", ... "ab+315" */
  BRDFNAV_TAB_SPECULAR = 2, /* rho_s, the same directions */
  BRDFNAV_TAB_MODELS = 3,   /* other models' neighbours, one per cluster: label = model name */
  BRDFNAV_TAB_GALLERY = 4   /* the most different materials of the database */
} brdfnav_tab;

/* brdfnav_neighbor.flags */
#define BRDFNAV_NEIGHBOR_AT_BOUNDARY 1u /* a parameter reached its range's end before radius */
#define BRDFNAV_NEIGHBOR_CLAMPED 2u     /* the colour reached its valid range's end before radius */
#define BRDFNAV_NEIGHBOR_BEYOND_RADIUS \
  4u /* models tab: the closest the model comes is farther than radius */

/* A list holds a tab's offers in ring order: each pair of opposite directions as i and i + n/2
 * when every offer has its opposite, so that offer i drawn at angle 2 pi i / n faces its
 * opposite across the current material. */
typedef struct brdfnav_neighbor {
  brdfnav_tab tab;
  const char* label;
  double distance;           /* embedded distance from the current material */
  unsigned flags;            /* BRDFNAV_NEIGHBOR_* bits */
  brdfnav_material material; /* every parameter given; pointers into the list */
  const char* words;         /* for an artist: "sharper", "lighter", "towards red", ... */
  const char* change;        /* the parameter change: "alpha_x 0.1 -> 0.0707" */
  int opposite;              /* index of the opposite offer in the list, -1 for none */
} brdfnav_neighbor;

typedef struct brdfnav_navigator brdfnav_navigator; /* opaque */
typedef struct brdfnav_neighbors brdfnav_neighbors; /* opaque: a list of neighbours */

/* Opens and verifies a database directory (BRDFNAV_ERROR_DATABASE naming the file when it is
 * missing or damaged). Sets *out to NULL on failure. */
BRDFNAV_API brdfnav_status brdfnav_navigator_open(const char* database_dir,
                                                  brdfnav_navigator** out);
/* Accepts NULL. Every list it returned stays valid. */
BRDFNAV_API void brdfnav_navigator_close(brdfnav_navigator* navigator);

/* The neighbours of `current` in `tab` at distance `radius` (finite, >= 1e-4: kMinRadius).
 * `clusters` (>= 1) is the most neighbours the models and gallery tabs return (8 in the paper). A
 * model the database does not hold, a material in a colour space other than lin_rec709 (the
 * database's) and a bad radius or cluster count are BRDFNAV_ERROR_INVALID_ARGUMENT. Sets *out to
 * NULL on failure. */
BRDFNAV_API brdfnav_status brdfnav_navigator_neighbors(const brdfnav_navigator* navigator,
                                                       const brdfnav_material* current,
                                                       double radius, brdfnav_tab tab, int clusters,
                                                       brdfnav_neighbors** out);
/* The same with the material as a YAML file or inline spec (as brdfnav_closure_load()). */
BRDFNAV_API brdfnav_status brdfnav_navigator_neighbors_load(const brdfnav_navigator* navigator,
                                                            const char* path_or_spec, double radius,
                                                            brdfnav_tab tab, int clusters,
                                                            brdfnav_neighbors** out);
/* The start gallery: `count` (>= 1) maximally different materials; distances are from the
 * gallery's matte grey reference. Sets *out to NULL on failure. */
BRDFNAV_API brdfnav_status brdfnav_navigator_gallery(const brdfnav_navigator* navigator, int count,
                                                     brdfnav_neighbors** out);

BRDFNAV_API brdfnav_status brdfnav_neighbors_count(const brdfnav_neighbors* list, size_t* count);
/* Neighbour `index` (0 .. count - 1); out->material can be passed to brdfnav_closure_create(). */
BRDFNAV_API brdfnav_status brdfnav_neighbors_get(const brdfnav_neighbors* list, size_t index,
                                                 brdfnav_neighbor* out);
/* Accepts NULL. */
BRDFNAV_API void brdfnav_neighbors_free(brdfnav_neighbors* list);

/* Display thumbnails: the navigator's thumbnail of a material (the database's images around it,
 * blended as the embedding interpolates: navigator/thumbnails.h) is linear lin_rec709 RGBA; these
 * functions turn it into what an OpenColorIO (display, view) shows. The OCIO config is $OCIO's
 * when set, otherwise the one built into the library (docs/COLOR.md: displays "sRGB" and
 * "Rec.1886", each with views "Standard" and "ACES 1.0 SDR-video"). It is loaded by the first of
 * these calls on a navigator and kept until brdfnav_navigator_close(), each (display, view)
 * processor built once and reused; a config that cannot be loaded is BRDFNAV_ERROR_IO naming
 * its file (each call tries again), and a config that does no colour management (OCIO's raw
 * config) is reported once as a warning on stderr. */

/* The config's displays, in its order (the first is its default display). Names live until
 * brdfnav_navigator_close(). */
BRDFNAV_API brdfnav_status brdfnav_navigator_displays(const brdfnav_navigator* navigator,
                                                      size_t* count);
BRDFNAV_API brdfnav_status brdfnav_navigator_display(const brdfnav_navigator* navigator,
                                                     size_t index, const char** name);
/* A display's views, in the config's order (the first is the display's default view). An
 * unknown display is BRDFNAV_ERROR_INVALID_ARGUMENT naming it and listing the displays. */
BRDFNAV_API brdfnav_status brdfnav_navigator_views(const brdfnav_navigator* navigator,
                                                   const char* display, size_t* count);
BRDFNAV_API brdfnav_status brdfnav_navigator_view(const brdfnav_navigator* navigator,
                                                  const char* display, size_t index,
                                                  const char** name);

/* The size of every thumbnail of this navigator: the database's resolution (square). */
BRDFNAV_API brdfnav_status brdfnav_navigator_thumbnail_size(const brdfnav_navigator* navigator,
                                                            int* width, int* height);
/* The thumbnail of `material` (a lin_rec709 material of a model the database holds, as
 * brdfnav_navigator_neighbors() takes) on `display` through `view`: *width x *height pixels of 4
 * bytes, R G B A, row-major, row 0 at the top, written to `rgba`: what `brdfnav serve` shows.
 * RGB is the display encoding of the surface's own colour, composited over nothing; A is the
 * fraction of the pixel the surface covers, straight (not associated with RGB): composite with
 * "over" as rgb * a + background * (1 - a). The sphere's edge is antialiased (A between 0 and
 * 255 there); a mesh scene's A is 0 or 255. A pixel nothing covers is 0 0 0 0. `capacity` is
 * the size of `rgba` in bytes, at least width * height * 4 (brdfnav_navigator_thumbnail_size()).
 * An unknown display or view, a smaller capacity, and a material the navigator does not take are
 * BRDFNAV_ERROR_INVALID_ARGUMENT (the message names the display or view and lists the valid
 * ones), with nothing written. */
BRDFNAV_API brdfnav_status brdfnav_navigator_thumbnail(const brdfnav_navigator* navigator,
                                                       const brdfnav_material* material,
                                                       const char* display, const char* view,
                                                       int* width, int* height, unsigned char* rgba,
                                                       size_t capacity);

#ifdef __cplusplus
}
#endif

#endif /* BRDFNAV_BRDFNAV_NAVIGATOR_H */
