#include "core/scene/interaction.h"

#include "core/math/curve_basis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace darc {

namespace {

template <typename T>
T bezier(const T* c, float u) {
  float s = 1 - u;
  return c[0] * (s * s * s) + c[1] * (3 * s * s * u) + c[2] * (3 * s * u * u) + c[3] * (u * u * u);
}

// The footprint's stretch on a surface seen at a grazing angle is limited to this factor (the
// surface seen at under 7 degrees): at the silhouette the exact stretch has no bound, and
// reflected and refracted footprints would inherit it.
constexpr float kMaxGrazingStretch = 8.0f;
// A strand's patch (the band its shadow rays leave) is at most this many times as long as it is
// wide. A shadow ray meets every strand that crosses its band, and a band as long as a thumbnail's
// footprint and as thin as a strand 1/20 of it meets hundreds (hair on a head at 32x24: 408
// segment tests per shadow ray); the shadow averaged over 8 widths of the strand around where it
// is seen is as good an estimate of the strand's shadow in the pixel (the pixel averages many
// strands). Measured one run, 1 thread, distance 1x1 against stochastic 16x16, the 320x240 scenes
// rendered smaller (--res): hair on a head at 32x24 segment tests -45 %, RMSE 0.0205 -> 0.0208;
// hair-shadow at 32x24 -41 %, RMSE 0.0123 -> 0.0089; at 320x240 -2 to -4 % and RMSE within 0.2 %.
// An aspect of 4 saved more (-65 % at 32x24) but cost 7 % RMSE on hair-shadow at 80x60.
constexpr float kMaxStrandPatchAspect = 8.0f;

// The stretch a texture lookup's footprint may have: beyond it the surface is seen within a
// tenth of a degree of edge-on.
constexpr float kMaxTextureStretch = 1000.0f;

// RI's default TextureCoordinates: s = u, t = v (the request is not supported: README).
constexpr std::array<float, 8> kDefaultTextureCoordinates{0, 0, 1, 0, 0, 1, 1, 1};

// A strand's s, t at u (its "st" or "s", "t" primvars, 0 without them) and their change over the
// footprint's length along it (it.dPdx, the band rays leave; zero for exact rays): coordinates
// follow the strand, not its width, so nothing changes across it (uniform st, a scalp map, is one
// texel lookup per strand, and the footprint's coverage of many strands filters across the scalp).
TextureCoordinates strand_texture_coordinates(const CurveSet& cs, uint32_t local, const Ray& ray, float u,
                                              const Interaction& it) {
  const SegmentShading& sh = cs.segment_shading(local);
  TextureCoordinates st;
  st.s = bezier(sh.s.data(), u);
  st.t = bezier(sh.t.data(), u);
  Vec3f at_time[4];
  const float speed = length(bezier_derivative(cs.control_points_at(local, ray.time, at_time), u));
  if (speed > 0.0f) {
    const float du = std::abs(dot(it.dPdx, it.dPdv)) / speed;  // u across the footprint along the strand
    st.dsdx = bezier_derivative(sh.s.data(), u) * du;
    st.dtdx = bezier_derivative(sh.t.data(), u) * du;
  }
  return st;
}

// The offset of a neighbouring ray's hit on the plane through P with normal n (Igehy's transfer):
// the neighbour at parameter t is at P + axis, then slides along d onto the plane.
Vec3f transfer(const Vec3f& axis, const Vec3f& d, const Vec3f& n, float max_stretch = kMaxGrazingStretch) {
  const float dn = dot(d, n);
  const Vec3f perpendicular = axis - d * (dot(axis, d) / dot(d, d));
  if (std::abs(dn) < 1e-4f * length(d)) return perpendicular;
  // The exact offset is the perpendicular one plus a slide along the ray; the slide is what grows
  // without bound at grazing angles, so it is the part shortened to the stretch limit.
  const Vec3f slide = axis - d * (dot(axis, n) / dn) - perpendicular;
  const float limit2 = max_stretch * max_stretch * length_squared(perpendicular);
  const float slide2 = length_squared(slide), room2 = limit2 - length_squared(perpendicular);
  if (slide2 > room2 && slide2 > 0) return perpendicular + slide * std::sqrt(std::max(0.0f, room2) / slide2);
  return perpendicular + slide;
}

// A point: a disc facing the ray, so N faces the ray as a non-oriented curve's does. Seen
// through a footprint larger than the disc, P and the footprint are moved onto the part of the
// footprint that is the disc (a square of its area around its centre), as a strand's band is:
// rays leaving it start on it, and its shadow footprint is its own size, not the pixel's.
Interaction point_interaction(const PointSet& points, uint32_t local, const Ray& ray, Interaction it,
                              const RayFootprint* footprint) {
  it.material = points.material[local];
  it.N = -normalize(ray.d);
  it.Cs = points.color(local);
  it.Os = points.opacity(local);
  // One texel per point: its st, looked up with no footprint (the disc faces the ray, it has no
  // parameters to spread a footprint over).
  it.st.s = points.texture_coordinates(local).x;
  it.st.t = points.texture_coordinates(local).y;
  if (!footprint) return it;
  const Vec3f ax = transfer(footprint->axis_x(it.t), ray.d, it.N);
  const Vec3f ay = transfer(footprint->axis_y(it.t), ray.d, it.N);
  const float side = std::sqrt(length(cross(ax, ay)));
  const float radius = points.radius_at(local, ray.time);
  const float disc_side = std::sqrt(std::numbers::pi_v<float>) * radius;
  const float scale = side > disc_side && side > 0.0f ? disc_side / side : 1.0f;
  it.dPdx = ax * scale;
  it.dPdy = ay * scale;
  // The centre of that square: where the ray crosses the disc when the disc is the larger, kept
  // inside the disc by half the square.
  const Vec3f centre = points.center_at(local, ray.time);
  const Vec3f offset = it.P - centre;
  const float room = std::max(0.0f, radius - 0.5f * std::min(side, disc_side));
  const float reach = length(offset);
  if (reach > room) it.P = centre + (reach > 0.0f ? offset * (room / reach) : Vec3f{});
  return it;
}

}  // namespace

Interaction make_interaction(const Scene& scene, uint32_t primitive, const Ray& ray, float t, float u,
                             const RayFootprint* footprint, StrandShadingPoint strand_point, float seen_share) {
  Interaction it;
  it.primitive = primitive;
  it.t = t;
  it.time = ray.time;
  it.sweeps_shutter = ray.sweeps_shutter;
  it.sweep_from = ray.sweep_from;
  it.sweep_to = ray.sweep_to;
  it.u = u;
  it.P = ray.at(t);
  uint32_t local;
  const Scene::PrimKind kind = scene.prim_kind(primitive, local);
  Vec3f plane_normal;  // the plane the footprint is transferred to
  if (kind == Scene::PrimKind::CurveSegment) {
    const CurveSet& cs = scene.curves;
    it.is_curve = true;
    it.strand = cs.strand_id[local];
    it.material = cs.attribute_id[local];
    it.N = -ray.d;
    if (cs.oriented(local)) {
      it.N = normalize(lerp(u, cs.end_normal(local, 0), cs.end_normal(local, 1)));
      if (scene.materials[it.material].flip_normals) it.N = -it.N;
    }
    it.Cs = bezier(cs.colors(local), u);
    it.Os = bezier(cs.opacities(local), u);
    Vec3f at_time[4];
    const Vec3f* cp = cs.control_points_at(local, ray.time, at_time);
    it.dPdv = normalize(bezier_derivative(cp, u));
    if (length_squared(it.dPdv) == 0.0f) it.dPdv = normalize(cp[3] - cp[0]);
    plane_normal = -ray.d;
  } else if (kind == Scene::PrimKind::Point) {
    return point_interaction(scene.points, local, ray, it, footprint);
  } else {
    const SurfaceSet& surfaces = scene.surfaces;
    it.material = surfaces.material(local);
    const Material& m = scene.materials[it.material];
    const Vec3f sign = m.flip_normals ? Vec3f{-1, -1, -1} : Vec3f{1, 1, 1};
    const Vec3f ng = surfaces.geometric_normal(local, it.P, ray.time);
    const Vec3f ns = surfaces.shading_normal(local, it.P, ray.time);
    it.N = mul(sign, ns);
    it.Cs = m.color;
    it.Os = m.opacity;
    plane_normal = ng;
    if (footprint) {
      it.dPdx = transfer(footprint->axis_x(t), ray.d, plane_normal);
      it.dPdy = transfer(footprint->axis_y(t), ray.d, plane_normal);
      // The normal's change across the footprint, as the difference of the normals at its
      // edges (exact for a sphere's first-order change, bounded for large footprints; zero on
      // flat faces).
      it.dNdx = mul(sign, surfaces.shading_normal(local, it.P + it.dPdx, ray.time) - ns);
      it.dNdy = mul(sign, surfaces.shading_normal(local, it.P + it.dPdy, ray.time) - ns);
    }
    if (m.reads_textures) {
      // A texture is filtered over the footprint's true extent on the surface, however long
      // grazing angles make it (the lookup's anisotropic filter bounds its own cost): the limit
      // above is for the rays that leave the surface.
      const Vec3f tx = footprint ? transfer(footprint->axis_x(t), ray.d, plane_normal, kMaxTextureStretch) : Vec3f{};
      const Vec3f ty = footprint ? transfer(footprint->axis_y(t), ray.d, plane_normal, kMaxTextureStretch) : Vec3f{};
      it.st = surfaces.texture_coordinates(local, it.P, tx, ty, kDefaultTextureCoordinates, ray.time);
    }
    return it;
  }
  if (footprint) {
    // A strand thinner than the footprint fills only a band of it: the part of the footprint that
    // is this strand is the band along the tangent, as long as the footprint and as wide as the
    // strand, centred on its axis. Rays leaving the strand (shadow rays above all) start there, so
    // that neighbours beside it in the same footprint do not shade it as if they were in front.
    // The band is at most kMaxStrandPatchAspect times as long as it is wide (around where the
    // strand is seen).
    const Vec3f ax = transfer(footprint->axis_x(t), ray.d, plane_normal);
    const Vec3f ay = transfer(footprint->axis_y(t), ray.d, plane_normal);
    const float side = std::sqrt(length(cross(ax, ay)));
    const Vec3f across = normalize(cross(it.dPdv, ray.d));
    const float width = std::abs(bezier(scene.curves.widths(local), u));
    const float band = std::min(side, width * std::clamp(seen_share, 0.0f, 1.0f));
    // The band's centre: on the axis when the strand is thinner than the footprint; where the ray
    // crosses the ribbon when it is wider (kept inside the ribbon by half the band). Shaded where
    // it is seen, anywhere across its width: keeping the band inside the strand there too pulled
    // an edge a clump leaves uncovered back under the neighbours' shadows (hair-shadow 160x120,
    // 1x1 against stochastic 16x16: RMSE 0.0059 against 0.0069; hair on a head 0.0096 against 0.0124).
    Vec3f at_time[4];
    const Vec3f axis_point = bezier(scene.curves.control_points_at(local, ray.time, at_time), u);
    const float room = strand_point == StrandShadingPoint::WhereTheRayCrosses ? 0.5f * width
                                                                              : std::max(0.0f, 0.5f * (width - band));
    const float offset = std::clamp(dot(it.P - axis_point, across), -room, room);
    it.P = axis_point + across * offset;
    it.dPdx = it.dPdv * std::min(side, kMaxStrandPatchAspect * band);
    it.dPdy = across * band;
    if (length_squared(across) == 0.0f) {  // seen along its tangent: the footprint as it is
      it.dPdx = ax;
      it.dPdy = ay;
    }
  }
  if (scene.materials[it.material].reads_textures) it.st = strand_texture_coordinates(scene.curves, local, ray, u, it);
  return it;
}

}  // namespace darc
