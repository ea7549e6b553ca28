#include "core/geometry/surfaces/surface_set.h"

#include <algorithm>
#include <cmath>

namespace darc {

BBox SurfaceSet::bounds(uint32_t surface) const {
  uint32_t i;
  switch (locate(surface, i)) {
    case Kind::Sphere: return spheres[i].bounds();
    case Kind::Polygon: return polygons[i].bounds();
    case Kind::Triangle: return triangles.bounds(i);
    case Kind::Quadric: return quadrics[i].bounds();
  }
  return {};
}

uint32_t SurfaceSet::material(uint32_t surface) const {
  uint32_t i;
  switch (locate(surface, i)) {
    case Kind::Sphere: return sphere_material[i];
    case Kind::Polygon: return polygon_material[i];
    case Kind::Triangle: return triangle_material[i];
    case Kind::Quadric: return quadric_material[i];
  }
  return 0;
}

bool SurfaceSet::intersect(uint32_t surface, const Ray& ray, SurfaceHit& hit) const {
  uint32_t i;
  switch (locate(surface, i)) {
    case Kind::Sphere: return spheres[i].intersect(ray, hit);
    case Kind::Polygon: return polygons[i].intersect(ray, hit);
    case Kind::Triangle: return triangles.intersect(i, ray, hit);
    case Kind::Quadric: return quadrics[i].intersect(ray, hit);
  }
  return false;
}

Vec3f SurfaceSet::geometric_normal(uint32_t surface, const Vec3f& p, float time) const {
  uint32_t i;
  switch (locate(surface, i)) {
    case Kind::Sphere: return spheres[i].normal_at(p);
    case Kind::Polygon: return polygons[i].normal;
    case Kind::Triangle: return triangles.face_normal(i, time);
    case Kind::Quadric: return quadrics[i].normal_at(p);
  }
  return {};
}

bool SurfaceSet::convex_outline(uint32_t surface, ConvexOutline& out, float time) const {
  uint32_t i;
  switch (locate(surface, i)) {
    case Kind::Triangle:
      for (int k = 0; k < 3; ++k) out.corners[size_t(k)] = triangles.corner(i, k, time);
      out.count = 3;
      out.layer = layer(surface);
      return true;
    case Kind::Polygon: {
      const PolygonShape& shape = polygons[i];
      const size_t n = shape.convex_corners.size();
      if (n < 3 || n > out.corners.size()) return false;
      std::copy(shape.convex_corners.begin(), shape.convex_corners.end(), out.corners.begin());
      out.count = int(n);
      out.layer = layer(surface);
      return true;
    }
    case Kind::Sphere:
    case Kind::Quadric: return false;
  }
  return false;
}

uint32_t SurfaceSet::layer(uint32_t surface) const {
  uint32_t i;
  switch (locate(surface, i)) {
    case Kind::Triangle: return triangles.layer(i);
    case Kind::Polygon: return polygons[i].piece ? polygons[i].layer : kNoLayer;
    case Kind::Sphere:
    case Kind::Quadric: return kNoLayer;
  }
  return kNoLayer;
}

Vec3f SurfaceSet::shading_normal(uint32_t surface, const Vec3f& p, float time) const {
  uint32_t i;
  if (locate(surface, i) == Kind::Triangle) return triangles.shading_normal(i, p, time);
  return geometric_normal(surface, p, time);
}

namespace {

// A difference of a periodic parameter across a footprint: the short way round the seam.
float across_seam(float d, bool periodic) {
  if (periodic) d -= std::round(d);
  return d;
}

}  // namespace

TextureCoordinates SurfaceSet::texture_coordinates(uint32_t surface, const Vec3f& p, const Vec3f& dx, const Vec3f& dy,
                                                   const std::array<float, 8>& uv_to_st, float time) const {
  TextureCoordinates out;
  uint32_t i;
  Vec2f uv, dudx, dudy;  // (u, v) and its changes along dx and dy
  switch (locate(surface, i)) {
    case Kind::Polygon: {
      const PolygonShape& poly = polygons[i];
      if (!poly.has_st) return out;
      out.s = dot(poly.s_gradient, p) + poly.s_offset;
      out.t = dot(poly.t_gradient, p) + poly.t_offset;
      out.dsdx = dot(poly.s_gradient, dx);
      out.dtdx = dot(poly.t_gradient, dx);
      out.dsdy = dot(poly.s_gradient, dy);
      out.dtdy = dot(poly.t_gradient, dy);
      return out;
    }
    case Kind::Triangle:
      if (!triangles.parameters(i, p, dx, dy, uv, dudx, dudy, time)) return out;
      break;
    case Kind::Sphere:
    case Kind::Quadric: {
      // Differences of the parameters at the footprint's ends: exact to first order, and
      // bounded where the footprint is larger than the surface's curvature.
      const bool sphere = locate(surface, i) == Kind::Sphere;
      auto at = [&](const Vec3f& q) { return sphere ? spheres[i].parameters_at(q) : quadrics[i].parameters_at(q); };
      const double sweep = sphere ? spheres[i].thetamax : quadrics[i].thetamax;
      const bool periodic = std::abs(sweep) >= 2 * 3.14159265358979;
      uv = at(p);
      const Vec2f ux = at(p + dx), uy = at(p + dy);
      dudx = {across_seam(ux.x - uv.x, periodic), ux.y - uv.y};
      dudy = {across_seam(uy.x - uv.x, periodic), uy.y - uv.y};
      if (!(length_squared(dx) > 0)) dudx = {};
      if (!(length_squared(dy) > 0)) dudy = {};
      uv.x -= std::floor(uv.x);  // one turn of a full sweep
      if (!periodic) uv.x = std::clamp(uv.x, 0.0f, 1.0f);
      uv.y = std::clamp(uv.y, 0.0f, 1.0f);
      break;
    }
  }
  // s(u, v) = bilinear in the corners' s; its partial derivatives give the chain rule.
  const auto& m = uv_to_st;
  auto bilerp = [&](int k) {
    return (1 - uv.y) * ((1 - uv.x) * m[k] + uv.x * m[2 + k]) + uv.y * ((1 - uv.x) * m[4 + k] + uv.x * m[6 + k]);
  };
  auto d_du = [&](int k) { return (1 - uv.y) * (m[2 + k] - m[k]) + uv.y * (m[6 + k] - m[4 + k]); };
  auto d_dv = [&](int k) { return (1 - uv.x) * (m[4 + k] - m[k]) + uv.x * (m[6 + k] - m[2 + k]); };
  out.s = bilerp(0);
  out.t = bilerp(1);
  out.dsdx = d_du(0) * dudx.x + d_dv(0) * dudx.y;
  out.dtdx = d_du(1) * dudx.x + d_dv(1) * dudx.y;
  out.dsdy = d_du(0) * dudy.x + d_dv(0) * dudy.y;
  out.dtdy = d_du(1) * dudy.x + d_dv(1) * dudy.y;
  return out;
}

}  // namespace darc
