// Moving transforms: keys are met exactly, a turn stays rigid half-way, and the time outside the
// keys holds the nearest key.
#include "core/math/transform_interpolation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace darc {
namespace {

double max_difference(const Matrix4& a, const Matrix4& b) {
  double d = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) d = std::max(d, std::abs(a.m[i][j] - b.m[i][j]));
  return d;
}

TEST(TransformInterpolation, ATurnHalfWayIsTheHalfTurnAndStaysRigid) {
  const Matrix4 a = Matrix4::rotate(0, {0, 0, 1}) * Matrix4::translate({1, 2, 3});
  const Matrix4 b = Matrix4::rotate(90, {0, 0, 1}) * Matrix4::translate({3, 2, 1});
  const Matrix4 half = interpolate_transform(a, b, 0.5);
  const Matrix4 expected = Matrix4::rotate(45, {0, 0, 1}) * Matrix4::translate({2, 2, 2});
  EXPECT_LT(max_difference(half, expected), 1e-12);
  // A point 10 units from the axis keeps its distance (a lerp of matrices gives 7.07).
  const Vec3d p = half.transform_point({10, 0, 0}) - Vec3d{2, 2, 2};
  EXPECT_NEAR(length(Vec3d{p.x, p.y, 0}), 10.0, 1e-9);
}

TEST(TransformInterpolation, ScaleAndTranslationGoLinearly) {
  const Matrix4 a = Matrix4::scale({1, 1, 1}), b = Matrix4::scale({3, 1, 2}) * Matrix4::translate({4, 0, 0});
  const Matrix4 q = interpolate_transform(a, b, 0.25);
  EXPECT_LT(max_difference(q, Matrix4::scale({1.5, 1, 1.25}) * Matrix4::translate({1, 0, 0})), 1e-12);
}

TEST(TransformInterpolation, KeysAreMetAndTimesOutsideHoldTheNearestKey) {
  const std::vector<TransformKey> keys{{0.0, Matrix4::translate({0, 0, 0})},
                                       {0.25, Matrix4::translate({1, 0, 0})},
                                       {1.0, Matrix4::translate({1, 3, 0})}};
  EXPECT_EQ(transform_at(keys, 0.25), keys[1].m);
  EXPECT_EQ(transform_at(keys, -1.0), keys[0].m);
  EXPECT_EQ(transform_at(keys, 2.0), keys[2].m);
  EXPECT_LT(max_difference(transform_at(keys, 0.625), Matrix4::translate({1, 1.5, 0})), 1e-12);
}

TEST(TransformInterpolation, AReflectionInBothKeysIsKept) {
  const Matrix4 a = Matrix4::scale({-1, 1, 1}), b = Matrix4::scale({-1, 1, 1}) * Matrix4::rotate(60, {0, 1, 0});
  const Matrix4 q = interpolate_transform(a, b, 0.5);
  EXPECT_LT(max_difference(q, Matrix4::scale({-1, 1, 1}) * Matrix4::rotate(30, {0, 1, 0})), 1e-9);
}

TEST(TransformInterpolation, MergedTimesAreSortedAndUnique) {
  const std::vector<double> a{0, 0.5, 1}, b{0.25, 0.5};
  EXPECT_EQ(merge_times(a, b), (std::vector<double>{0, 0.25, 0.5, 1}));
}

}  // namespace
}  // namespace darc
