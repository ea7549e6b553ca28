// How large a pixel is where a surface lies: what lets a tessellation follow the screen, as
// RenderMan's dicing does, instead of the surface alone. A surface tessellated for one frame's
// camera gets triangles no finer than that frame can show (the curvature a silhouette needs, a
// couple of pixels a triangle elsewhere), so a ray's footprint meets a few pieces, not dozens.
// The camera of a frame is fixed before WorldBegin (RI), so the same RIB frame always gets the
// same triangles: images stay deterministic.
#pragma once

#include "core/math/matrix.h"
#include "core/math/vec.h"

namespace darc {

struct DicingView {
  Matrix4 object_to_camera;  // the surface's object space to camera space (row vectors)
  bool perspective = true;
  // Camera-space units one pixel spans: at distance 1 from the eye (perspective), or anywhere
  // (orthographic). The smaller of a pixel's width and height.
  double pixel_span = 0;
  // An upper bound of how much object_to_camera stretches a length (its linear part's
  // Frobenius norm), so that a pixel is never counted larger in object units than it is.
  double stretch = 1;

  // The size of a pixel at object-space point P, in object-space units. Perspective: at the
  // point's depth in front of the eye, at its distance elsewhere (behind the eye or beside it:
  // seen only in shadows and reflections, where a pixel is about as large).
  double pixel_size(const Vec3d& P) const;
};

// The view of object space through a frame's camera: object_to_world (the current transform)
// followed by world_to_camera; pixel spans from the screen window and resolution.
DicingView make_dicing_view(const Matrix4& object_to_world, const Matrix4& world_to_camera, bool perspective,
                            double fov_degrees, double screen_width, double screen_height, int xres, int yres);

}  // namespace darc
