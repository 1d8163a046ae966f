#include "mjray/core/transform.h"

#include <cmath>
#include <numbers>

namespace mjray {

Matrix4 Matrix4::identity() {
  Matrix4 r;
  for (int i = 0; i < 4; ++i) r.m[i][i] = 1;
  return r;
}

Matrix4 Matrix4::operator*(const Matrix4& b) const {
  Matrix4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      r.m[i][j] = m[i][0] * b.m[0][j] + m[i][1] * b.m[1][j] + m[i][2] * b.m[2][j] + m[i][3] * b.m[3][j];
  return r;
}

Matrix4 Matrix4::transposed() const {
  Matrix4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = m[j][i];
  return r;
}

Transform Transform::translate(const Vector3& d) {
  Matrix4 m = Matrix4::identity(), inv = Matrix4::identity();
  for (int i = 0; i < 3; ++i) {
    m.m[i][3] = d[i];
    inv.m[i][3] = -double(d[i]);
  }
  return {m, inv};
}

Transform Transform::scale(float sx, float sy, float sz) {
  Matrix4 m = Matrix4::identity(), inv = Matrix4::identity();
  const double s[3] = {sx, sy, sz};
  for (int i = 0; i < 3; ++i) {
    m.m[i][i] = s[i];
    inv.m[i][i] = 1.0 / s[i];
  }
  return {m, inv};
}

Transform Transform::rotate(int axis, float degrees) {
  const double radians = double(degrees) * std::numbers::pi / 180.0;
  const double c = std::cos(radians), s = std::sin(radians);
  // Compute the plane (a, b) rotated counter-clockwise when looking down the axis.
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  Matrix4 m = Matrix4::identity();
  m.m[a][a] = c;
  m.m[a][b] = -s;
  m.m[b][a] = s;
  m.m[b][b] = c;
  return {m, m.transposed()};
}

Point3 Transform::operator()(const Point3& p) const {
  const auto& a = m_.m;
  const double x = p.x, y = p.y, z = p.z;
  return {float(a[0][0] * x + a[0][1] * y + a[0][2] * z + a[0][3]),
          float(a[1][0] * x + a[1][1] * y + a[1][2] * z + a[1][3]),
          float(a[2][0] * x + a[2][1] * y + a[2][2] * z + a[2][3])};
}

Vector3 Transform::operator()(const Vector3& v) const {
  const auto& a = m_.m;
  const double x = v.x, y = v.y, z = v.z;
  return {float(a[0][0] * x + a[0][1] * y + a[0][2] * z),
          float(a[1][0] * x + a[1][1] * y + a[1][2] * z),
          float(a[2][0] * x + a[2][1] * y + a[2][2] * z)};
}

Normal3 Transform::operator()(const Normal3& n) const {
  const auto& a = inverse_.m;  // transpose of the inverse: index [j][i]
  const double x = n.x, y = n.y, z = n.z;
  return {float(a[0][0] * x + a[1][0] * y + a[2][0] * z),
          float(a[0][1] * x + a[1][1] * y + a[2][1] * z),
          float(a[0][2] * x + a[1][2] * y + a[2][2] * z)};
}

Bounds3 Transform::operator()(const Bounds3& b) const {
  Bounds3 r;
  if (b.empty()) return r;
  for (int i = 0; i < 8; ++i) r.expand((*this)(b.corner(i)));
  return r;
}

}  // namespace mjray
