#include "core/geometry/surfaces/surface_set.h"

#include <algorithm>

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

Vec3f SurfaceSet::geometric_normal(uint32_t surface, const Vec3f& p) const {
  uint32_t i;
  switch (locate(surface, i)) {
    case Kind::Sphere: return spheres[i].normal_at(p);
    case Kind::Polygon: return polygons[i].normal;
    case Kind::Triangle: return triangles.face_normal(i);
    case Kind::Quadric: return quadrics[i].normal_at(p);
  }
  return {};
}

bool SurfaceSet::convex_outline(uint32_t surface, ConvexOutline& out) const {
  uint32_t i;
  switch (locate(surface, i)) {
    case Kind::Triangle:
      for (int k = 0; k < 3; ++k) out.corners[size_t(k)] = triangles.corner(i, k);
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

Vec3f SurfaceSet::shading_normal(uint32_t surface, const Vec3f& p) const {
  uint32_t i;
  if (locate(surface, i) == Kind::Triangle) return triangles.shading_normal(i, p);
  return geometric_normal(surface, p);
}

}  // namespace darc
