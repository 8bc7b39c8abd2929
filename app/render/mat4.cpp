#include "mat4.h"

#include <cmath>

namespace sph::render {

namespace {
Vec3f sub(Vec3f a, Vec3f b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
float dot(Vec3f a, Vec3f b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3f cross(Vec3f a, Vec3f b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec3f normalize(Vec3f a) {
  const float n = std::sqrt(dot(a, a));
  return n > 0.f ? Vec3f{a.x / n, a.y / n, a.z / n} : a;
}
}  // namespace

Mat4 operator*(const Mat4& a, const Mat4& b) {
  Mat4 c;
  for (int r = 0; r < 4; ++r)
    for (int k = 0; k < 4; ++k) {
      float s = 0.f;
      for (int j = 0; j < 4; ++j) s += a.at(r, j) * b.at(j, k);
      c.at(r, k) = s;
    }
  return c;
}

Vec4f operator*(const Mat4& a, const Vec4f& v) {
  auto row = [&](int r) { return a.at(r, 0) * v.x + a.at(r, 1) * v.y + a.at(r, 2) * v.z + a.at(r, 3) * v.w; };
  return {row(0), row(1), row(2), row(3)};
}

Mat4 ortho(float l, float r, float b, float t, float n, float f) {
  Mat4 m;
  m.at(0, 0) = 2.f / (r - l);
  m.at(1, 1) = 2.f / (t - b);
  m.at(2, 2) = -2.f / (f - n);
  m.at(0, 3) = -(r + l) / (r - l);
  m.at(1, 3) = -(t + b) / (t - b);
  m.at(2, 3) = -(f + n) / (f - n);
  return m;
}

Mat4 perspective(float fovy, float aspect, float n, float f) {
  const float c = 1.f / std::tan(0.5f * fovy);
  Mat4 m;
  m.at(0, 0) = c / aspect;
  m.at(1, 1) = c;
  m.at(2, 2) = (f + n) / (n - f);
  m.at(2, 3) = 2.f * f * n / (n - f);
  m.at(3, 2) = -1.f;
  m.at(3, 3) = 0.f;
  return m;
}

Mat4 look_at(Vec3f eye, Vec3f target, Vec3f up) {
  const Vec3f f = normalize(sub(target, eye));
  const Vec3f s = normalize(cross(f, up));
  const Vec3f u = cross(s, f);
  Mat4 m;
  m.at(0, 0) = s.x; m.at(0, 1) = s.y; m.at(0, 2) = s.z;
  m.at(1, 0) = u.x; m.at(1, 1) = u.y; m.at(1, 2) = u.z;
  m.at(2, 0) = -f.x; m.at(2, 1) = -f.y; m.at(2, 2) = -f.z;
  m.at(0, 3) = -dot(s, eye);
  m.at(1, 3) = -dot(u, eye);
  m.at(2, 3) = dot(f, eye);
  return m;
}

}  // namespace sph::render
