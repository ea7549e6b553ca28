#include "integrator/distance_hider.h"

#include "integrator/depth_bands.h"
#include "integrator/footprint_secondary_rays.h"

#include "core/footprint/footprint_frame.h"
#include "core/footprint/polygon_coverage.h"
#include "core/footprint/swept_polygon_coverage.h"
#include "core/footprint/sphere_coverage.h"
#include "core/math/curve_basis.h"
#include "core/scene/interaction.h"
#include "core/geometry/points/point_set_coverage.h"
#include "core/scene/ray_differentials.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace darc {

namespace {


// Footprints never shrink below this fraction of the scene's size (r -> 0 at a pinhole's apex,
// curve-ray-tracing.md §6 case 11).
constexpr float kMinFootprintSceneFraction = 1e-7f;

template <typename T>
T bezier(const T* c, float u) {
  float s = 1 - u;
  return c[0] * (s * s * s) + c[1] * (3 * s * s * u) + c[2] * (3 * s * u * u) + c[3] * (u * u * u);
}

// A fragment of `primitive` at depth t (strand, u and distance for curves and points).
Fragment fragment(float t, float coverage, uint32_t primitive, CoverageMask mask, uint32_t strand = kNoStrand,
                  float u = 0, float distance = 0) {
  Fragment f;
  f.t = t;
  f.coverage = coverage;
  f.primitive = primitive;
  f.mask = mask;
  f.strand = strand;
  f.u = u;
  f.distance = distance;
  return f;
}

// The depth of the plane through x0 with normal n along the footprint's sub-rays
// (footprint_sub_ray_at), to first order about the footprint's centre: with
// t(u, v) = n . (x0 - o(u, v)) / n . d(u, v), dt/du = -(n . dox + t n . ddx) / n . d at the centre.
DepthPlane depth_plane(const Ray& ray, const RayFootprint& footprint, const Vec3f& n, const Vec3f& x0) {
  DepthPlane p;
  const float nd = dot(n, ray.d);
  if (!(std::abs(nd) > 1e-6f * length(n) * length(ray.d))) return p;  // edge-on
  p.t0 = dot(n, x0 - ray.o) / nd;
  p.du = -(dot(n, footprint.dox) + p.t0 * dot(n, footprint.ddx)) / nd;
  p.dv = -(dot(n, footprint.doy) + p.t0 * dot(n, footprint.ddy)) / nd;
  p.valid = std::isfinite(p.t0) && std::isfinite(p.du) && std::isfinite(p.dv);
  return p;
}

// Widens a camera ray's footprint by its lens (DepthOfField): one ray per pixel stratum then
// stands for the whole lens. The sub-rays over the lens are a pencil through the focal point
// (origin offsets along the lens axes, directions converging at focus_t); the footprint is the
// pixel's parallelogram plus that disc. Both are kept linear in t, so every kernel that takes a
// footprint works unchanged: the lens's axes, turned a quarter turn from the pixel's and
// scaled to the disc's area (sqrt(pi) times its radius), are added to the pixel's. Their sum
// spans, at every depth, a parallelogram of the pixel's area plus the circle of confusion's
// (the cross terms vanish where the pixel's axes follow the lens's), its size never below the
// pixel's, equal to it on the focal plane. Coverage within it is taken as uniform: a strand
// defocused far beyond the pixel peaks at sqrt(pi)/2 = 0.886 of the thin lens's 4w/(pi c)
// (docs/architecture.md, depth of field). The form is general: surfaces are met by sub-rays.
void add_lens(const Camera::LensAxes& lens, RayFootprint& f) {
  constexpr float kDiscToSquare = 1.7724538509055159f;  // sqrt(pi): a square of the disc's area
  // Turned so that the lens's square has the pixel's orientation: the areas then add (turned
  // the other way they would cancel).
  const Vec3f pixel_normal = f.form == FootprintForm::Parallel ? cross(f.dox, f.doy) : cross(f.ddx, f.ddy);
  const Vec3f ax = lens.y_axis * kDiscToSquare;
  Vec3f ay = lens.x_axis * kDiscToSquare;
  if (dot(cross(ax, ay), pixel_normal) < 0) ay = -ay;
  f.dox += ax;
  f.doy += ay;
  f.ddx -= ax / lens.focus_t;
  f.ddy -= ay / lens.focus_t;
  f.form = FootprintForm::General;
  f.waist_t = lens.focus_t;
  f.through_lens = true;
}

RayFootprint camera_footprint(const Camera& cam, double x, double y, double spacing, const Ray& ray,
                              float min_radius) {
  Ray rx = cam.generate_ray(x + spacing, y), ry = cam.generate_ray(x, y + spacing);
  RayFootprint f;
  f.dox = rx.o - ray.o;
  f.doy = ry.o - ray.o;
  f.ddx = rx.d - ray.d;
  f.ddy = ry.d - ray.d;
  f.min_radius = min_radius;
  // A perspective camera's rays share their origin (a pencil with its apex there); an
  // orthographic camera's share their direction.
  if (f.dox == Vec3f{} && f.doy == Vec3f{}) {
    f.form = FootprintForm::Pencil;
    f.apex_t = 0;
  } else if (f.ddx == Vec3f{} && f.ddy == Vec3f{}) {
    f.form = FootprintForm::Parallel;
  }
  if (cam.has_lens()) add_lens(cam.lens_axes(x, y), f);
  return f;
}

// Walks the footprint of `ray_in`, adds every fragment to scratch.abuffer and composites
// them front to back with `shade`, stopping once the footprint is opaque. Hits `filter` skips
// are left out (what a secondary ray starts on; for shadow rays, Transparent primitives).
// Returns the nearest fragment's depth.
template <class Shade>
float collect_fragments(const DistanceContext& ctx, const Ray& ray_in, const RayFootprint& footprint,
                        RayCounters& counters, RayScratch& scratch, Shade&& shade, const HitFilter& filter,
                        float min_transmittance) {
  const Scene& scene = ctx.base.scene;
  const CurveSet& cs = scene.curves;
  Ray ray = ray_in;
  ABuffer& abuffer = scratch.abuffer;
  abuffer.clear();
  float nearest = std::numeric_limits<float>::infinity();
  DistanceRay distance_ray = make_distance_ray(ray, footprint);
  // Made when the first planar convex surface is met (camera and shadow rays: pencils and
  // prisms; reflected and refracted rays have none and keep the sub-ray tests).
  FootprintFrame frame;
  enum class FrameState { NotMade, Made, None } frame_state = FrameState::NotMade;
  // Pieces that lie behind the plane the sub-rays start from, or touch it, are in no sub-ray's
  // way: for a shadow ray, the pieces of the mesh around its start point.
  StartHalfSpace start;
  const bool has_start = footprint.start_half_space(ray.o, ray.d, start);
  auto behind_start = [&](std::span<const Vec3f> corners) {
    float highest = -std::numeric_limits<float>::infinity();
    for (const Vec3f& c : corners) highest = std::max(highest, start.at(c));
    return start.excludes(highest);
  };
  // A piece of the mesh a shadow ray starts on is skipped when it is met nearer than
  // origin_layer_min_t (HitFilter::skips_layer_piece). A piece whose every corner lies nearer
  // than that on every sub-ray is skipped before its coverage is computed: the concave floor a
  // shadow ray leaves puts a dozen of its own pieces within the footprint's reach, and their
  // coverage tests were two thirds of the Aqsis vase's shadow-ray work. A corner X lies on
  // sub-ray (u, v) at t = (d.(X - o) - A) / (d.d + B), A = d.(u dox + v doy), B = d.(u ddx + v ddy).
  const bool has_origin_layer = filter.origin_layer != kNoLayer && filter.origin_layer_min_t > 0;
  const float origin_a = 0.5f * (std::abs(dot(footprint.dox, ray.d)) + std::abs(dot(footprint.doy, ray.d)));
  const float origin_den =
      dot(ray.d, ray.d) - 0.5f * (std::abs(dot(footprint.ddx, ray.d)) + std::abs(dot(footprint.ddy, ray.d)));
  auto wholly_at_start = [&](uint32_t layer, std::span<const Vec3f> corners) {
    if (!has_origin_layer || layer != filter.origin_layer || !(origin_den > 0)) return false;
    float farthest = -std::numeric_limits<float>::infinity();
    for (const Vec3f& c : corners) farthest = std::max(farthest, dot(c - ray.o, ray.d));
    // A margin of 1e-3 of the limit keeps rounding on the side of testing the piece.
    return (farthest + origin_a) / origin_den < filter.origin_layer_min_t * (1.0f - 1e-3f);
  };
  auto analytic_frame = [&]() -> const FootprintFrame* {
    if (frame_state == FrameState::NotMade)
      frame_state = FootprintFrame::make(ray, footprint, frame) ? FrameState::Made : FrameState::None;
    return frame_state == FrameState::Made ? &frame : nullptr;
  };
  // Adds the fragment of the whole sphere `local` (primitive p) whose analytic coverage is h,
  // shaded where the sub-ray (h.u, h.v) meets it (or passes it closest, for a sliver between
  // the sub-rays). False, adding nothing, when its near side is hidden (Sides 1 seen from
  // inside out): the sub-ray tests then find what is visible.
  auto add_ball_fragment = [&](const SphereFootprintHit& h, uint32_t p, uint32_t local, const Material& m,
                               const Vec3f& opacity) {
    const Ray sub = footprint_sub_ray_at(ray, footprint, h.u, h.v);
    SurfaceHit sh;
    float t;
    if (scene.surfaces.intersect(local, sub, sh)) {
      t = sh.t;
    } else {
      Vec3d centre;
      double radius;
      scene.surfaces.whole_ball(local, centre, radius);
      const Vec3d d(sub.d);
      t = float(dot(centre - Vec3d(sub.o), d) / dot(d, d));
    }
    const Vec3f normal = scene.surfaces.geometric_normal(local, sub.at(t), ray.time);
    if (m.hides_back_of(normal, sub.d)) return false;
    ++counters.surface_pieces;
    counters.shadow_surface_pieces += filter.shadow;
    Fragment f = fragment(t, h.coverage, p, ctx.settings.coverage_masks ? h.mask : kFullMask);
    f.at_sub_ray = true;
    f.sub_u = h.u;
    f.sub_v = h.v;
    f.t_near = h.t_near;
    f.t_far = h.t_far;
    f.normal = normal;
    f.covers_centre = h.covers_centre;
    const Fragment* held = abuffer.add(f, shade);
    nearest = std::min(nearest, t);
    // Nothing behind an opaque ball that covers the whole footprint can be seen.
    if (held && held->coverage >= 1.0f && held->mask == kFullMask && opacity == Vec3f{1, 1, 1}) {
      ray.tmax = std::min(ray.tmax, held->t_far);
      distance_ray.t_max = ray.tmax;
    }
    return true;
  };
  auto visit = [&](uint32_t p) {
      uint32_t local;
      const Scene::PrimKind kind = scene.prim_kind(p, local);
      switch (kind) {
        case Scene::PrimKind::CurveSegment: {
          if (cs.strand_id[local] == filter.skip_strand) return;
          if (filter.shadow && scene.materials[cs.attribute_id[local]].transmission == Transmission::Transparent)
            return;
          ++counters.segment_tests;
          counters.shadow_segment_tests += filter.shadow;
          CurveFragmentHit h;
          // Segments are cut at their strand's ends and at joints the strand runs straight
          // through: the A-buffer adds the pieces of a strand up (SegmentEnds::cut_joints).
          SegmentEnds ends = segment_ends(cs, local);
          ends.cut_joints = true;
          if (!intersect_segment_distance(cs, local, distance_ray, ctx.settings.coverage, ends, h,
                                          ctx.settings.coverage_masks))
            return;
          const Material& m = scene.materials[cs.attribute_id[local]];
          if (cs.oriented(local) && m.hides_back_of(lerp(h.u, cs.end_normal(local, 0), cs.end_normal(local, 1)), ray.d))
            return;
          Fragment f = fragment(h.t, h.coverage, p, h.mask, cs.strand_id[local], h.u, h.distance);
          f.time = h.time;
          abuffer.add(f, shade);
          nearest = std::min(nearest, h.t);
          break;
        }
        case Scene::PrimKind::Surface: {
          const Material& m = scene.materials[scene.surfaces.material(local)];
          if (filter.shadow && m.transmission == Transmission::Transparent) return;
          const float tmin = p == filter.origin_primitive ? filter.origin_min_t : 0.0f;
          if (tmin == std::numeric_limits<float>::infinity()) return;
          const Vec3f opacity = filter.shadow ? shadow_opacity(m, m.opacity) : m.opacity;
          // Planar convex surfaces (triangles, mesh faces, convex polygons): what their edges cover
          // of the footprint, analytically.
          ConvexOutline outline;
          if (tmin == 0.0f && scene.surfaces.convex_outline(local, outline, ray.time)) {
            if (has_start && behind_start(outline.span())) return;
            if (wholly_at_start(outline.layer, outline.span())) return;
            if (const FootprintFrame* fr = analytic_frame()) {
              ++counters.surface_pieces;
              counters.shadow_surface_pieces += filter.shadow;
              frame.t_max = ray.tmax;
              PolygonFootprintHit h;
              // A moving piece: its coverage over the ray's stretch of the shutter, and its plane
              // where it is at the time its depth is taken.
              float piece_time = ray.time;
              const bool swept = ray.sweeps_shutter && scene.surfaces.moving(local);
              if (swept) {
                auto corners_at = [&](float time, std::array<Vec3f, kMaxPolygonCorners>& corners) {
                  ConvexOutline at;
                  if (!scene.surfaces.convex_outline(local, at, time)) return 0;
                  std::copy(at.corners.begin(), at.corners.begin() + at.count, corners.begin());
                  return at.count;
                };
                if (!swept_polygon_coverage(*fr, ray.sweep_from, ray.sweep_to, corners_at, h, piece_time)) return;
                scene.surfaces.convex_outline(local, outline, piece_time);
              } else if (!polygon_coverage(*fr, outline.span(), h)) {
                return;
              }
              if (filter.skips_layer_piece(outline.layer, h.t_near)) return;
              const Vec3f normal = scene.surfaces.geometric_normal(local, outline.corners[0], piece_time);
              if (m.hides_back_of(normal, h.travel)) return;
              Fragment f = fragment(h.t, h.coverage, p, h.mask);
              if (!ctx.settings.coverage_masks) f.mask = kFullMask;
              f.at_sub_ray = true;
              f.sub_u = h.u;
              f.sub_v = h.v;
              f.layer = outline.layer;
              f.t_near = h.t_near;
              f.t_far = h.t_far;
              f.normal = normal;
              f.covers_centre = h.covers_centre;
              f.plane = depth_plane(ray, footprint, normal, outline.corners[0]);
              f.planar = true;
              if (swept) f.time = piece_time;
              const Fragment* held = abuffer.add(f, shade);
              nearest = std::min(nearest, h.t);
              // Nothing behind an opaque layer that covers the whole footprint can be seen.
              if (held && held->coverage >= 1.0f - 1e-4f && held->mask == kFullMask && opacity == Vec3f{1, 1, 1}) {
                ray.tmax = std::min(ray.tmax, held->t_far);
                distance_ray.t_max = ray.tmax;
              }
              return;
            }
          }
          // Whole spheres: what their silhouette covers of the footprint, analytically (a sphere
          // smaller than the footprint, between its sub-rays, is not missed).
          Vec3d ball_centre;
          double ball_radius;
          if (tmin == 0.0f && scene.surfaces.whole_ball(local, ball_centre, ball_radius)) {
            if (const FootprintFrame* fr = analytic_frame()) {
              frame.t_max = ray.tmax;
              SphereFootprintHit h;
              const SphereCoverage result = sphere_coverage(*fr, ball_centre, ball_radius, h);
              if (result == SphereCoverage::Miss) {
                ++counters.surface_pieces;
                counters.shadow_surface_pieces += filter.shadow;
                return;
              }
              if (result == SphereCoverage::Covered && add_ball_fragment(h, p, local, m, opacity)) return;
            }
          }
          // A visible hit of this surface by `r` (Sides 1 surfaces seen from behind are not).
          auto hit_surface = [&](const Ray& r_in, SurfaceHit& h) {
            ++counters.surface_tests;
            Ray r = r_in;
            r.tmin = std::max(r.tmin, tmin);
            return scene.surfaces.intersect(local, r, h) && !m.hides_back_of(h.ng, r.d);
          };
          SurfaceFragment sf;
          const BBox piece_box = scene.surfaces.is_piece(local) ? scene.surfaces.bounds(local) : BBox{};
          if (!surface_coverage(ray, footprint, hit_surface, sf, scene.surfaces.is_piece(local) ? &piece_box : nullptr))
            return;
          // A surface over the whole footprint whose depth changes much across it (a ground seen
          // through a lens) goes in as bands of equal depth, each shaded where its sub-ray hits.
          // Camera rays through a lens only: a band's secondary rays would leave from its own
          // point of the surface, so a glass of eta 1 would no longer vanish.
          const DepthBands bands =
              sf.whole && footprint.through_lens && ctx.settings.coverage_masks ? depth_bands(sf) : DepthBands{};
          for (int k = 0; k < bands.count; ++k) {
            const DepthBand& band = bands.band[size_t(k)];
            SurfaceHit bh;
            const float t = hit_surface(footprint_sub_ray(ray, footprint, band.point), bh) ? bh.t : band.t;
            Fragment f = fragment(t, band.coverage, p, band.mask);
            f.surface_point = band.point;
            abuffer.add(f, shade);
          }
          if (bands.count == 0) {
            Fragment f = fragment(sf.t, sf.coverage, p, sf.mask);
            f.surface_point = sf.point;
            if (!ctx.settings.coverage_masks) f.mask = kFullMask;
            abuffer.add(f, shade);
          }
          nearest = std::min(nearest, bands.count > 0 ? bands.nearest : sf.t);
          // Nothing behind an opaque surface that covers the whole footprint can be seen: past
          // its farthest depth over the footprint (what stands on it in front of that is seen
          // where it is farther).
          if (sf.coverage == 1.0f && opacity == Vec3f{1, 1, 1}) {
            ray.tmax = std::min(ray.tmax, sf.whole ? farthest_depth(sf) : sf.t);
            distance_ray.t_max = ray.tmax;
          }
          break;
        }
        case Scene::PrimKind::Point: {
          // Sub-pixel like a strand: its coverage and mask go into the A-buffer (a disc facing the
          // ray has no back, so Sides does not apply).
          const Material& m = scene.materials[scene.points.material[local]];
          if (filter.shadow && m.transmission == Transmission::Transparent) return;
          ++counters.point_tests;
          PointFragmentHit h;
          if (!intersect_point_distance(scene.points, local, distance_ray, ctx.settings.coverage, h,
                                        ctx.settings.coverage_masks) ||
              filter.skips_primitive(p, h.t))
            return;
          abuffer.add(fragment(h.t, h.coverage, p, h.mask, kNoStrand, 0, h.distance), shade);
          nearest = std::min(nearest, h.t);
          break;
        }
      }
  };

  int steps_to_sort = ctx.settings.sort_interval;  // a countdown: no division per step
  bool terminated = false;
  // Shadow rays want transmittance alone: what is pending is composited at every step, in any
  // order (ABuffer::composite_for_transmittance), so they stop as soon as they are blocked.
  const bool transmittance_only = filter.shadow;
  auto progress = [&](float t_final) {
    if (--steps_to_sort > 0 && t_final < ray.tmax) return true;
    if (steps_to_sort <= 0) steps_to_sort = ctx.settings.sort_interval;
    if (transmittance_only) {
      if (abuffer.composite_for_transmittance(t_final, shade) > 0 &&
          max_component(abuffer.transmittance()) < min_transmittance) {
        terminated = true;
        return false;
      }
      return t_final < ray.tmax;
    }
    // Nothing pending is final yet: compositing would do nothing.
    if (t_final < abuffer.nearest_pending() && t_final < ray.tmax) return true;
    if (abuffer.composite_until(t_final, shade) > 0 &&
        max_component(abuffer.transmittance()) < min_transmittance) {
      terminated = true;
      return false;
    }
    return t_final < ray.tmax;
  };
  counters.cells_visited += scene.accel.footprint_walk(ray, footprint, scratch.traversal, visit, progress);
  if (terminated) {
    ++counters.rays_terminated_early;
  } else {
    abuffer.composite_until(std::numeric_limits<float>::infinity(), shade);
  }
  counters.fragments += abuffer.fragments_added();
  counters.fragment_merges += abuffer.fragments_merged();
  counters.peak_fragments = std::max<uint64_t>(counters.peak_fragments, abuffer.peak_length());
  return nearest;
}

}  // namespace

Ray footprint_sub_ray(const Ray& ray, const RayFootprint& footprint, int point) {
  const float step = 1.0f / kMaskSide;
  float u = (float(point % kMaskSide) + 0.5f) * step - 0.5f, v = (float(point / kMaskSide) + 0.5f) * step - 0.5f;
  return footprint_sub_ray_at(ray, footprint, u, v);
}

Ray footprint_sub_ray_at(const Ray& ray, const RayFootprint& footprint, float u, float v) {
  Ray r = ray;
  r.o = ray.o + footprint.dox * u + footprint.doy * v;
  r.d = ray.d + footprint.ddx * u + footprint.ddy * v;
  return r;
}

FootprintCells footprint_cells(const Ray& ray, const RayFootprint& footprint, const BBox& bounds) {
  const FootprintCells whole;
  const float dd = dot(ray.d, ray.d);
  if (!(dd > 0)) return whole;
  float u0 = std::numeric_limits<float>::infinity(), u1 = -u0, v0 = u0, v1 = -u0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3f x{(corner & 1) ? bounds.hi.x : bounds.lo.x, (corner & 2) ? bounds.hi.y : bounds.lo.y,
                  (corner & 4) ? bounds.hi.z : bounds.lo.z};
    // A corner behind the ray's origin (the neighbours of the piece a shadow ray leaves) is
    // placed where the footprint starts: sub-rays only reach the box's part in front.
    const float t = std::max(0.0f, dot(x - ray.o, ray.d) / dd);
    if (!std::isfinite(t)) return whole;
    const Vec3f ax = footprint.axis_x(t), ay = footprint.axis_y(t), w = x - ray.at(t);
    // w ~ ax u + ay v, least squares.
    const float a11 = dot(ax, ax), a12 = dot(ax, ay), a22 = dot(ay, ay), b1 = dot(w, ax), b2 = dot(w, ay);
    const float det = a11 * a22 - a12 * a12;
    if (!(det > 1e-12f * a11 * a22) || !std::isfinite(det)) return whole;
    const float u = (a22 * b1 - a12 * b2) / det, v = (a11 * b2 - a12 * b1) / det;
    u0 = std::min(u0, u), u1 = std::max(u1, u), v0 = std::min(v0, v), v1 = std::max(v1, v);
  }
  // Sub-ray (col, row) sits at u = (col + 0.5) / kMaskSide - 0.5 (footprint_sub_ray).
  auto cell = [](float u) { return (u + 0.5f) * float(kMaskSide) - 0.5f; };
  FootprintCells c;
  c.col0 = int(std::max(0.0f, std::floor(cell(u0) - kPieceCellMargin)));
  c.col1 = int(std::min(float(kMaskSide - 1), std::ceil(cell(u1) + kPieceCellMargin)));
  c.row0 = int(std::max(0.0f, std::floor(cell(v0) - kPieceCellMargin)));
  c.row1 = int(std::min(float(kMaskSide - 1), std::ceil(cell(v1) + kPieceCellMargin)));
  if (!(cell(u1) + kPieceCellMargin >= 0) || !(cell(v1) + kPieceCellMargin >= 0) ||
      !(cell(u0) - kPieceCellMargin <= float(kMaskSide - 1)) || !(cell(v0) - kPieceCellMargin <= float(kMaskSide - 1)))
    return FootprintCells{1, 0, 1, 0};  // entirely outside
  return c;
}

DistanceContext make_distance_context(const HiderContext& base, const DistanceHiderSettings& settings) {
  DistanceContext ctx{base, settings, 0};
  Vec3f extent = base.scene.bounds.empty() ? Vec3f{1, 1, 1} : base.scene.bounds.extent();
  ctx.min_radius = kMinFootprintSceneFraction * std::max(max_component(extent), 1e-6f);
  return ctx;
}

SampleValue trace_distance_ray(const DistanceContext& ctx, const Ray& ray, const RayFootprint& footprint,
                               RayCounters& counters, RayScratchStack& scratch, const PathState& path,
                               const HitFilter& filter) {
  const Scene& scene = ctx.base.scene;
  RayScratch& level = scratch.at(size_t(path.depth));
  FootprintSecondaryRays secondary(ctx, counters, scratch);
  auto shade = [&](const Fragment& f) -> ShadedFragment {
    // Surfaces are shaded where the sub-ray that found them hit, strands where the footprint sees
    // them (ABuffer::at_visible_part); the footprint stays the ray's.
    Ray shading_ray = f.at_sub_ray        ? footprint_sub_ray_at(ray, footprint, f.sub_u, f.sub_v)
                      : f.surface_point < 0 ? ray
                                            : footprint_sub_ray(ray, footprint, f.surface_point);
    if (f.time >= 0) shading_ray.time = f.time;
    // A surface moved to where it is seen (ABuffer::at_visible_part): its depth there on its
    // plane, and the patch it is seen on as the footprint of what leaves it.
    float t = f.t;
    RayFootprint seen_footprint = footprint;
    if (f.moved) {
      const Ray measured = footprint_sub_ray_at(ray, footprint, f.depth_u, f.depth_v);
      const float across = dot(shading_ray.d, f.normal);
      const float moved_t = dot(measured.at(f.t) - shading_ray.o, f.normal) / across;
      if (std::isfinite(moved_t) && moved_t > 0) t = moved_t;
      seen_footprint = footprint.part(f.patch_u, f.patch_v);
    }
    const Interaction at = make_interaction(
        scene, f.primitive, shading_ray, t, f.u, &seen_footprint,
        f.at_sub_ray && f.strand != kNoStrand ? StrandShadingPoint::WhereTheRayCrosses : StrandShadingPoint::BandCentre,
        f.seen_share);
    auto visible = [&] { return path.weight * level.abuffer.visibility_weight(f); };
    const LazyWeight weight(visible);
    // A surface seen on part of the footprint: its shadow rays average over the points it is
    // seen at (FootprintSecondaryRays::seen_surface_transmittance).
    FootprintSecondaryRays::SeenSurface seen;
    const bool seen_part = f.moved && f.patch_u > 0 && f.patch_v > 0 && level.abuffer.seen_points(f, seen.weights);
    if (seen_part) {
      seen.dPdx = at.dPdx / f.patch_u;
      seen.dPdy = at.dPdy / f.patch_v;
      seen.centre = at.P - seen.dPdx * f.sub_u - seen.dPdy * f.sub_v;
    }
    secondary.shading(seen_part ? &seen : nullptr);
    ShadedPoint r = shade_with_secondary_rays(ctx.base.shading, ctx.base.secondary, at, normalize(shading_ray.d),
                                              &seen_footprint, path.depth, weight, secondary, counters);
    secondary.shading(nullptr);
    return {r.Ci, r.Oi};
  };

  SampleValue out;
  out.depth = collect_fragments(ctx, ray, footprint, counters, level, shade, filter,
                                stopping_transmittance(ctx.base.secondary, path.weight, kDistanceMinTransmittance));
  out.color = level.abuffer.color();
  Vec3f tr = level.abuffer.transmittance();
  out.alpha = 1.0f - (tr.x + tr.y + tr.z) / 3.0f;
  return out;
}

Vec3f trace_footprint_transmittance(const DistanceContext& ctx, const Ray& ray, const RayFootprint& footprint,
                                    RayCounters& counters, RayScratch& scratch, const HitFilter& filter,
                                    float min_transmittance, const FootprintPointWeights* point_weights) {
  const Scene& scene = ctx.base.scene;
  const CurveSet& cs = scene.curves;
  HitFilter shadow = filter;
  shadow.shadow = true;
  // Only opacity matters here: Os from the primitive (curve and point primvars, else the material), as
  // its Transmission attribute says.
  auto opacity = [&](const Fragment& f) -> ShadedFragment {
    uint32_t local;
    Scene::PrimKind kind = scene.prim_kind(f.primitive, local);
    if (kind == Scene::PrimKind::CurveSegment)
      return {Vec3f{}, shadow_opacity(scene.materials[cs.attribute_id[local]], bezier(cs.opacities(local), f.u))};
    if (kind == Scene::PrimKind::Point)
      return {Vec3f{}, shadow_opacity(scene.materials[scene.points.material[local]], scene.points.opacity(local))};
    const uint32_t material = scene.surfaces.material(local);
    return {Vec3f{}, shadow_opacity(scene.materials[material], scene.materials[material].opacity)};
  };
  collect_fragments(ctx, ray, footprint, counters, scratch, opacity, shadow, min_transmittance);
  return point_weights ? scratch.abuffer.transmittance(*point_weights) : scratch.abuffer.transmittance();
}

Vec3f trace_footprint_transmittance(const DistanceContext& ctx, const Ray& ray, const RayFootprint& footprint,
                                    RayCounters& counters, RayScratch& scratch, uint32_t skip_strand) {
  HitFilter filter;
  filter.skip_strand = skip_strand;
  return trace_footprint_transmittance(ctx, ray, footprint, counters, scratch, filter);
}

void render_tile_distance(const DistanceContext& ctx, const PixelRect& rect, TileAccumulator& acc,
                          RayCounters& counters) {
  const int nx = ctx.base.samples_x, ny = ctx.base.samples_y;
  const Camera& cam = ctx.base.scene.camera;
  RayScratchStack scratch(ctx.base.scene.accel);
  double spacing = 1.0 / std::max(nx, ny);
  // Motion blur: each ray is traced once per stretch of the shutter (time_strata of them), each
  // sweep averaging moving strands' coverage over its stretch and seeing the scene at the
  // stretch's middle for depth and shading. Every ray covers the whole shutter: handing the
  // stretches out among a pixel's rays instead (each ray's area seeing only its own quarter of the
  // shutter at 2x2) made 2x2 worse than 1x1 on the swinging tuft (RMSE 0.0051 against 0.0022).
  const bool moves = ctx.base.scene.has_motion();
  const ShutterOpening& shutter = ctx.base.scene.output.shutter_opening;
  const int per_sample = moves ? std::max(1, ctx.settings.time_strata) : 1;
  const float strata = float(per_sample);
  for (int py = rect.y0; py < rect.y1; ++py)
    for (int px = rect.x0; px < rect.x1; ++px) {
      for (int sy = 0; sy < ny; ++sy)
        for (int sx = 0; sx < nx; ++sx) {
          // Stratum centres: the footprint, not jitter, does the antialiasing.
          double x = px + (sx + 0.5) / nx, y = py + (sy + 0.5) / ny;
          const Ray centre = cam.generate_ray(x, y);
          RayFootprint fp = camera_footprint(cam, x, y, spacing, centre, ctx.min_radius);
          Vec3f color{};
          float alpha = 0, depth = std::numeric_limits<float>::infinity();
          for (int k = 0; k < per_sample; ++k) {
            Ray ray = centre;
            if (moves) {
              // Stretches of equal weight under the shutter's opening (ShutterOpening::time_at):
              // for the default box shutter, equal stretches of time.
              ray.sweeps_shutter = true;
              ray.sweep_from = shutter.time_at(float(k) / strata);
              ray.sweep_to = shutter.time_at(float(k + 1) / strata);
              ray.time = shutter.is_box() ? 0.5f * (ray.sweep_from + ray.sweep_to)
                                          : shutter.time_at((float(k) + 0.5f) / strata);
            }
            ++counters.primary_rays;
            const SampleValue v = trace_distance_ray(ctx, ray, fp, counters, scratch);
            color += v.color;
            alpha += v.alpha;
            depth = std::min(depth, v.depth);
          }
          if (per_sample > 1) {
            color = color / float(per_sample);
            alpha /= float(per_sample);
          }
          acc.add_sample(float(x), float(y), {color.x, color.y, color.z, alpha}, depth);
        }
    }
}

}  // namespace darc
