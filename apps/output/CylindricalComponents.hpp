#pragma once
// Vector and symmetric-tensor components in the cylindrical frame of an axis, at a point:
// e_r from the axis to the point, e_t = a x e_r, e_z = a. Tensors in Voigt order xx yy zz xy
// yz xz (the materials') come out as rr tt zz rt tz rz (the same slots with x -> r, y -> t).
// On the axis e_r is undefined: the components along r and t are NaN.
#include <array>
#include <cmath>
#include <limits>

namespace contactlab {

using Vec3 = std::array<double, 3>;

// {e_r, e_t, e_z} at `point` (NaN on the axis).
inline std::array<Vec3, 3> cylindricalFrame(const Vec3& point, const Vec3& centre,
                                            const Vec3& axis) {
  const auto dot = [](const Vec3& a, const Vec3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  };
  const double length = std::sqrt(dot(axis, axis));
  const Vec3 ez{axis[0] / length, axis[1] / length, axis[2] / length};
  Vec3 er{point[0] - centre[0], point[1] - centre[1], point[2] - centre[2]};
  const double along = dot(er, ez);
  for (int i = 0; i < 3; ++i)
    er[i] -= along * ez[i];
  const double r = std::sqrt(dot(er, er));
  for (double& c : er)
    c = r > 0 ? c / r : std::numeric_limits<double>::quiet_NaN();
  const Vec3 et{ez[1] * er[2] - ez[2] * er[1], ez[2] * er[0] - ez[0] * er[2],
                ez[0] * er[1] - ez[1] * er[0]};
  return {er, et, ez};
}

inline Vec3 cylindricalComponents(const Vec3& v, const Vec3& point, const Vec3& centre,
                                  const Vec3& axis) {
  const auto e = cylindricalFrame(point, centre, axis);
  Vec3 out{};
  for (int a = 0; a < 3; ++a)
    out[a] = e[a][0] * v[0] + e[a][1] * v[1] + e[a][2] * v[2];
  return out;
}

inline std::array<double, 6> cylindricalComponents(const std::array<double, 6>& voigt,
                                                   const Vec3& point, const Vec3& centre,
                                                   const Vec3& axis) {
  const auto e = cylindricalFrame(point, centre, axis);
  const double S[3][3] = {{voigt[0], voigt[3], voigt[5]},
                          {voigt[3], voigt[1], voigt[4]},
                          {voigt[5], voigt[4], voigt[2]}};
  const auto form = [&](int a, int b) {
    double sum = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        sum += e[a][i] * S[i][j] * e[b][j];
    return sum;
  };
  return {form(0, 0), form(1, 1), form(2, 2), form(0, 1), form(1, 2), form(0, 2)};
}

}  // namespace contactlab
