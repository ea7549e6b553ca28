// A ray's footprint from its ray differentials (Igehy 1999): the sub-ray (u, v), u and v in
// [-1/2, 1/2], starts at o + u*dox + v*doy and runs along d + u*ddx + v*ddy, so at parameter t
// the footprint is spanned by axis_x(t) = dox + t*ddx and axis_y(t) = doy + t*ddy.
//
// Three forms (docs/architecture.md, footprint section):
// - a pencil: every sub-ray passes through one apex A = o + apex_t*d (dox = -apex_t*ddx and
//   doy = -apex_t*ddy). Perspective camera rays have their apex at the origin (apex_t = 0); a
//   shadow ray toward a point or spot light has it at the light (its sub-rays start on the
//   receiving surface and meet at the light, so the footprint shrinks to nothing there);
// - parallel: ddx = ddy = 0 (orthographic camera rays, shadow rays toward a distant light: a
//   prism of the receiving patch);
// - general: anything else (reflected and refracted rays), used to first order.
// The origin differentials need not be perpendicular to d: a shadow ray's lie in the receiver's
// tangent plane, so that its sub-rays start on the surface.
#pragma once

#include "core/math/vec.h"

#include <algorithm>
#include <cmath>

namespace darc {

enum class FootprintForm { General, Pencil, Parallel };

// An upper bound on the footprint's reach (the farthest a sub-ray is from the ray at parameter
// t: half the sum of the axes' lengths), as a + b*|t - apex_t|. The true reach
// 1/2 (|dox + t ddx| + |doy + t ddy|) is convex in t, so it never lies above this V over an
// interval where the V does not; the bound is exact for a pencil (a = 0 up to rounding) and for
// the parallel form (b = 0).
struct ReachBound {
  float a = 0, b = 0, apex_t = 0;

  float at(float t) const { return a + b * std::abs(t - apex_t); }
  // The largest reach over [t0, t1] (t0 <= t1): at one of the ends, the V being convex.
  float max_over(float t0, float t1) const { return std::max(at(t0), at(t1)); }
  // Whether the reach only grows for t >= 0 (apex at or before the origin: every camera ray),
  // so that the largest over [t0, t1] is at(t1) and the smallest at(t0): hot culls then need
  // only one end of a depth range.
  bool grows() const { return apex_t <= 0.0f; }
};

// The half-space n . x > offset + margin, which the sub-rays of a footprint stay in for t > 0
// (RayFootprint::start_half_space). `margin` (rounding: the plane is known to about 1e-5 of the
// coordinates' size) puts what merely touches the plane, as the pieces of a mesh around a point
// on it do, outside: a sub-ray meets it only at its own start.
struct StartHalfSpace {
  Vec3f n;
  float offset = 0, margin = 0;
  float at(const Vec3f& x) const { return dot(n, x) - offset; }
  // Whether points whose largest value of at() is `highest` can be met by no sub-ray.
  bool excludes(float highest) const { return !(highest > margin); }
};

struct RayFootprint {
  Vec3f dox, doy, ddx, ddy;
  // Floor on the footprint size, so that r -> 0 (a pinhole at its apex, a ray without
  // differentials) never divides by zero: below it coverage becomes a plain hit test.
  float min_radius = 0;
  FootprintForm form = FootprintForm::General;
  float apex_t = 0;  // a pencil's apex, as a parameter along the ray
  // General form: where along the ray the footprint is about smallest (a lens's focal plane),
  // the apex of its reach bound; 0 (the origin) when nothing better is known.
  float waist_t = 0;
  // A camera ray's footprint widened by its lens (DepthOfField): it holds the circle of
  // confusion, and a surface's depth may change across it by far more than across a pixel.
  bool through_lens = false;

  Vec3f axis_x(float t) const { return dox + ddx * t; }
  Vec3f axis_y(float t) const { return doy + ddy * t; }
  bool has_differentials() const {
    return length_squared(dox) + length_squared(doy) + length_squared(ddx) + length_squared(ddy) > 0;
  }

  // The V around the apex: a pencil's; for the general form its waist (the origin unless set:
  // a + b t for t >= 0, which never shrinks, so a reflected footprint that converges is bounded
  // loosely but safely); for the parallel form any point (b = 0). The reach changes by at most
  // b per unit of t, so the V around any point bounds it. A least-squares apex for the general
  // form was tried: for a ray whose directions barely change (glass of eta 1) it lies wherever
  // rounding puts it, and the refinement depth it feeds changed the image by 3.5e-4 against the
  // same strands seen directly; a lens's waist is set where it is known (its focal plane).
  ReachBound reach_bound() const {
    const float spread = 0.5f * (length(ddx) + length(ddy));
    const float t_apex = form == FootprintForm::Pencil ? apex_t : form == FootprintForm::General ? waist_t : 0.0f;
    const float a = 0.5f * (length(dox + ddx * t_apex) + length(doy + ddy * t_apex));
    return {a, spread, t_apex};
  }
  // The reach an acceleration walk needs: the footprint's corners, 0.5 max(|X + Y|, |X - Y|) for
  // its axes X and Y (reach_bound's 0.5 (|X| + |Y|) is up to 1.41 times that: a box grown by it
  // let in a quarter more pieces of a mesh), and min_radius, the smallest radius the curve and
  // point kernels give a footprint's coverage; never more than reach_bound, so that a walk
  // never visits what reach_bound would have left out.
  ReachBound walk_reach_bound() const {
    const ReachBound loose = reach_bound();
    const Vec3f x0 = dox + ddx * loose.apex_t, y0 = doy + ddy * loose.apex_t;
    const float a = 0.5f * std::max(length(x0 + y0), length(x0 - y0));
    const float b = 0.5f * std::max(length(ddx + ddy), length(ddx - ddy));
    return {std::min(loose.a, std::max(a, min_radius)), std::min(loose.b, b), loose.apex_t};
  }
  // The half-space every sub-ray of the ray (origin o, direction d) stays in for t >= 0, when
  // there is one: the sub-rays start on the plane through o spanned by dox and doy, and when
  // every sub-ray direction d + u ddx + v ddy (|u|, |v| <= 1/2) leaves that plane to the same
  // side, nothing strictly behind it is within the footprint. A shadow ray's sub-rays start on
  // the receiver's tangent plane and run to a light in front of it: the surface around the
  // receiving point, which curves away behind that plane, is never in their way (nor found by a
  // walk that asks). False when the origins span no plane (camera pencils) or the directions
  // do not all leave it to one side (a light behind or in the plane, most reflected rays).
  bool start_half_space(const Vec3f& o, const Vec3f& d, StartHalfSpace& out) const {
    const Vec3f n = cross(dox, doy);
    const float leave = dot(n, d), spread = 0.5f * (std::abs(dot(n, ddx)) + std::abs(dot(n, ddy)));
    if (!(std::abs(leave) > spread) || !std::isfinite(leave)) return false;
    out.n = leave > 0 ? n : -n;
    out.offset = dot(out.n, o);
    const float size = std::max({std::abs(o.x), std::abs(o.y), std::abs(o.z), 1.0f});
    out.margin = 1e-5f * size * (std::abs(n.x) + std::abs(n.y) + std::abs(n.z));
    return true;
  }
  // The footprint of the sub-rays (u, v) in [-su/2, su/2] x [-sv/2, sv/2]: a part of this one
  // around its ray, of the same form.
  RayFootprint part(float su, float sv) const {
    RayFootprint f = *this;
    f.dox = dox * su;
    f.ddx = ddx * su;
    f.doy = doy * sv;
    f.ddy = ddy * sv;
    return f;
  }
  // Upper bound on how far from the ray a strand can be and still cover part of the footprint
  // at parameter t (reaches the footprint's corners).
  float reach(float t) const { return reach_bound().at(t); }
};

// The footprint of a sub-ray family that meets at `apex_t` along the ray.
inline RayFootprint pencil_footprint(const Vec3f& dox, const Vec3f& doy, const Vec3f& ddx, const Vec3f& ddy,
                                     float apex_t, float min_radius) {
  RayFootprint f{dox, doy, ddx, ddy, min_radius, FootprintForm::Pencil, apex_t, 0};
  return f;
}

}  // namespace darc
