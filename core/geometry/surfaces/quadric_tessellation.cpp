#include "core/geometry/surfaces/quadric_tessellation.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

namespace darc {

namespace {

constexpr double kSagittaPixels = 0.02;
constexpr int kMinPerTurn = 32, kMaxPerTurn = 1024, kPerTurnWithoutView = 64;

// Intervals per full turn of a circle of `radius` (object units) whose pixel is `pixel` units
// wide: the sagitta r (1 - cos(a/2)) ~ r a^2 / 8 at most kSagittaPixels pixels.
int per_turn(double radius, double pixel) {
  if (!(pixel > 0) || !(std::abs(radius) > 0)) return kPerTurnWithoutView;
  const double angle = std::sqrt(8 * kSagittaPixels * pixel / std::abs(radius));
  // Clamped as a double: a huge radius over a tiny pixel would overflow an int.
  const double count = std::ceil(2 * std::numbers::pi / angle);
  return int(std::clamp(std::isfinite(count) ? count : double(kMaxPerTurn), double(kMinPerTurn), double(kMaxPerTurn)));
}

int intervals(int turn, double sweep) {
  return std::max(1, int(std::ceil(turn * std::abs(sweep) / (2 * std::numbers::pi))));
}

double pixel_at(const DicingView* view, const Vec3d& p) { return view ? view->pixel_size(p) : 0.0; }

using Surface = std::function<Vec3d(double u, double v)>;

// The grid of P(u, v), its parametric normals (central differences, one-sided at the borders;
// where dP/du vanishes, at a pole or an apex, the normal a little way inside) and (u, v).
TriangleMeshData grid_mesh(const Surface& P, QuadricGrid grid, bool reverse = false) {
  TriangleMeshData mesh;
  const int nu = std::max(1, grid.nu), nv = std::max(1, grid.nv);
  constexpr double h = 1e-4;
  auto normal = [&](double u, double v) {
    for (double nudge : {0.0, 1e-3, -1e-3}) {
      const double vv = std::clamp(v + nudge, 0.0, 1.0);
      const double u0 = std::max(0.0, u - h), u1 = std::min(1.0, u + h);
      const double v0 = std::max(0.0, vv - h), v1 = std::min(1.0, vv + h);
      const Vec3d n = cross((P(u1, vv) - P(u0, vv)) / (u1 - u0), (P(u, v1) - P(u, v0)) / (v1 - v0));
      const double len = length(n);
      if (len > 1e-12) return Vec3f(n / len) * (reverse ? -1.0f : 1.0f);
    }
    return Vec3f{};
  };
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const double u = double(i) / nu, v = double(j) / nv;
      mesh.P.push_back(Vec3f(P(u, v)));
      mesh.N.push_back(normal(u, v));
      mesh.uv.push_back({float(u), float(v)});
    }
  auto at = [&](int i, int j) { return uint32_t(j * (nu + 1) + i); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      if (reverse) {
        mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i + 1, j + 1), at(i + 1, j), at(i, j), at(i, j + 1),
                                                 at(i + 1, j + 1)});
      } else {
        mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1),
                                                 at(i, j + 1)});
      }
    }
  return mesh;
}

Vec3d around_z(double radius, double theta, double z) {
  return {radius * std::cos(theta), radius * std::sin(theta), z};
}

}  // namespace

QuadricGrid sphere_grid(const Sphere& s, const DicingView* view) {
  const int turn = per_turn(s.radius, pixel_at(view, {0, 0, 0.5 * (s.zmin + s.zmax)}));
  return {intervals(turn, s.thetamax), intervals(turn, s.v_phi_span)};
}

QuadricGrid quadric_grid(const Quadric& q, const DicingView* view) {
  const Vec3d centre{0, 0, 0.5 * (q.z_lo + q.z_hi)};
  switch (q.kind) {
    case QuadricKind::Cone:
    case QuadricKind::Disk:
    case QuadricKind::Cylinder:
      return {intervals(per_turn(q.radius, pixel_at(view, centre)), q.thetamax), 1};
    case QuadricKind::Hyperboloid: {
      const double r = std::max(std::hypot(q.point1.x, q.point1.y), std::hypot(q.point2.x, q.point2.y));
      // The ruled surface bulges between its ends when the segment twists round the axis.
      return {intervals(per_turn(r, pixel_at(view, centre)), q.thetamax), 8};
    }
    case QuadricKind::Paraboloid: {
      const int turn = per_turn(q.radius, pixel_at(view, centre));
      return {intervals(turn, q.thetamax), std::max(4, turn / 8)};
    }
    case QuadricKind::Torus: {
      const double pixel = pixel_at(view, centre);
      return {intervals(per_turn(q.major_radius + std::abs(q.radius), pixel), q.thetamax),
              intervals(per_turn(q.radius, pixel), q.phimax - q.phimin)};
    }
  }
  return {};
}

TriangleMeshData tessellate_sphere(const Sphere& s, QuadricGrid grid) {
  // A negative RIB radius flips the analytic sphere's normal without moving its points; the
  // parametrization with |radius| already follows the signs of the z range and the sweep.
  const bool reverse = s.flip_normal != ((s.v_phi_span < 0) != (s.thetamax < 0));
  return grid_mesh(
      [&](double u, double v) {
        const double phi = s.v_phi0 + v * s.v_phi_span, theta = u * s.thetamax;
        return around_z(s.radius * std::cos(phi), theta, s.radius * std::sin(phi));
      },
      grid, reverse);
}

TriangleMeshData tessellate_quadric(const Quadric& q, QuadricGrid grid) {
  Surface P;
  switch (q.kind) {
    case QuadricKind::Cone:
      P = [&](double u, double v) { return around_z(q.radius * (1 - v), u * q.thetamax, v * q.height); };
      break;
    case QuadricKind::Cylinder:
      P = [&](double u, double v) { return around_z(q.radius, u * q.thetamax, q.zmin + v * (q.zmax - q.zmin)); };
      break;
    case QuadricKind::Disk:
      P = [&](double u, double v) { return around_z(q.radius * (1 - v), u * q.thetamax, q.height); };
      break;
    case QuadricKind::Paraboloid:
      P = [&](double u, double v) {
        const double z = q.zmin + v * (q.zmax - q.zmin);
        const double r = q.zmax != 0 ? q.radius * std::sqrt(std::max(0.0, z / q.zmax)) : 0.0;
        return around_z(r, u * q.thetamax, z);
      };
      break;
    case QuadricKind::Hyperboloid:
      P = [&](double u, double v) {
        const Vec3d p = q.point1 * (1 - v) + q.point2 * v;
        const double c = std::cos(u * q.thetamax), s = std::sin(u * q.thetamax);
        return Vec3d{p.x * c - p.y * s, p.x * s + p.y * c, p.z};
      };
      break;
    case QuadricKind::Torus:
      P = [&](double u, double v) {
        const double phi = q.phimin + v * (q.phimax - q.phimin);
        return around_z(q.major_radius + q.radius * std::cos(phi), u * q.thetamax, q.radius * std::sin(phi));
      };
      break;
  }
  return grid_mesh(P, grid);
}

}  // namespace darc
