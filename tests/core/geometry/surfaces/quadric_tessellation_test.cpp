// The quadrics as triangle meshes (for motion blur): every kind's mesh is where its analytic
// surface is (rays meet both at the same depth, within the tessellation's tenth of a pixel),
// wound so that its face normal is the analytic geometric normal (dP/du x dP/dv: Orientation and
// Sides act alike), with shading normals along it.
#include "core/geometry/surfaces/quadric_tessellation.h"
#include "core/geometry/surfaces/triangle_store.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace darc {
namespace {

struct Case {
  std::string name;
  std::function<bool(const Ray&, SurfaceHit&)> analytic;
  TriangleMeshData mesh;
};

std::vector<Case> cases() {
  const Matrix4 identity;
  std::vector<Case> out;
  auto add_sphere = [&](std::string name, const Sphere& s) {
    out.push_back({name, [s](const Ray& r, SurfaceHit& h) { return s.intersect(r, h); },
                   tessellate_sphere(s, sphere_grid(s, nullptr))});
  };
  auto add_quadric = [&](std::string name, const Quadric& q) {
    out.push_back({name, [q](const Ray& r, SurfaceHit& h) { return q.intersect(r, h); },
                   tessellate_quadric(q, quadric_grid(q, nullptr))});
  };
  add_sphere("sphere", Sphere::make(1, -1, 1, 360, identity));
  add_sphere("clipped sphere", Sphere::make(1, -0.5, 0.8, 270, identity));
  add_sphere("inverted sphere", Sphere::make(-1, -1, 1, 360, identity));
  add_quadric("cone", Quadric::cone(1.5, 1, 360, identity));
  add_quadric("cylinder", Quadric::cylinder(1, -1, 1, 300, identity));
  add_quadric("disk", Quadric::disk(0.2, 1, 360, identity));
  add_quadric("paraboloid", Quadric::paraboloid(1, 0.1, 1, 360, identity));
  add_quadric("hyperboloid", Quadric::hyperboloid({1, -0.5, -1}, {1, 0.5, 1}, 360, identity));
  add_quadric("torus", Quadric::torus(1, 0.3, 0, 360, 360, identity));
  return out;
}

TEST(QuadricTessellation, EveryKindsMeshIsWhereItsSurfaceIsAndFacesItsWay) {
  for (const Case& c : cases()) {
    TriangleStore store;
    ASSERT_GT(store.add(c.mesh), 0u) << c.name;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> uniform(-1, 1);
    int both = 0, disagree = 0;
    for (int i = 0; i < 2000; ++i) {
      Ray ray;
      ray.o = Vec3f{uniform(rng), uniform(rng), uniform(rng)} * 4.0f;
      const Vec3f target{uniform(rng) * 0.8f, uniform(rng) * 0.8f, uniform(rng) * 0.8f};
      ray.d = normalize(target - ray.o);
      SurfaceHit a;
      const bool hit_a = c.analytic(ray, a);
      SurfaceHit m;
      bool hit_m = false;
      for (uint32_t t = 0; t < store.size(); ++t) {
        SurfaceHit h;
        Ray r = ray;
        if (hit_m) r.tmax = m.t;
        if (store.intersect(t, r, h)) {
          m = h;
          hit_m = true;
        }
      }
      if (hit_a != hit_m) {
        ++disagree;  // a ray grazing the outline, between the chord and the arc
        continue;
      }
      if (!hit_a) continue;
      ++both;
      if (std::abs(a.t - m.t) > 0.02f) {
        ++disagree;
        continue;
      }
      EXPECT_GT(dot(normalize(a.ng), m.ng), 0.8f) << c.name << " faces the analytic normal's way";
    }
    EXPECT_GT(both, 100) << c.name;
    EXPECT_LT(disagree, 2000 / 100) << c.name << ": at most 1 % of the rays near an outline";
    // Shading normals along the face normals.
    for (size_t t = 0; t + 2 < c.mesh.indices.size(); t += 3) {
      const Vec3f& pa = c.mesh.P[c.mesh.indices[t]];
      const Vec3f n = cross(c.mesh.P[c.mesh.indices[t + 1]] - pa, c.mesh.P[c.mesh.indices[t + 2]] - pa);
      if (length(n) < 1e-6f) continue;  // at a pole or an apex
      EXPECT_GT(dot(normalize(n), c.mesh.N[c.mesh.indices[t]]), 0.5f) << c.name << " triangle " << t / 3;
    }
  }
}

TEST(QuadricTessellation, TheGridFollowsThePixelSize) {
  const Sphere s = Sphere::make(1, -1, 1, 360, Matrix4{});
  const QuadricGrid coarse = sphere_grid(s, nullptr);
  EXPECT_EQ(coarse.nu, 64);
  DicingView near;
  near.object_to_camera = Matrix4::translate({0, 0, 3});
  near.perspective = true;
  near.pixel_span = 1e-3;  // a thousand pixels across at distance 1: the sphere is 700 pixels wide
  const QuadricGrid fine = sphere_grid(s, &near);
  EXPECT_GT(fine.nu, 64);
  // The chord's sagitta at that size: r (1 - cos(pi / nu)) in pixels, at most a fiftieth.
  EXPECT_LE((1 - std::cos(3.14159265 / fine.nu)) / near.pixel_size({0, 0, 0}), 0.02 + 1e-9);
}

}  // namespace
}  // namespace darc
