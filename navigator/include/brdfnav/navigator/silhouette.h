// What a person sees of the sphere's edge. The renderer shades one ray per pixel centre, so its
// images' alpha is 0 or 1: the metric's mask, which the database keeps. Drawn that way the
// silhouette is a staircase; a thumbnail's alpha is instead the fraction of each pixel the
// sphere covers.
#pragma once

#include <brdfnav/core/image.h>

namespace brdfnav {

// The sphere scene as the renderer frames it (the unit disk spans the square image): alpha
// becomes the fraction of each pixel inside the disk (8 x 8 samples in the pixels the edge
// crosses; 1 inside, 0 outside as rendered), and the pixels the disk reaches without covering
// their centre, which the renderer left black, take the mean colour of their covered
// neighbours. Colours stay unassociated with alpha (a covered pixel keeps its own). Throws
// ImageError for an image that is not square.
void antialias_sphere_silhouette(Image& image);

}  // namespace brdfnav
