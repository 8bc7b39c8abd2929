// Minimal column-major 4x4 matrix maths for the cameras (float, as GL wants it).
#pragma once
#include <array>

namespace sph::render {

struct Vec3f {
  float x = 0.f, y = 0.f, z = 0.f;
};

struct Vec4f {
  float x = 0.f, y = 0.f, z = 0.f, w = 0.f;
};

/// m[col * 4 + row], the layout glUniformMatrix4fv expects with transpose = GL_FALSE.
struct Mat4 {
  std::array<float, 16> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  float& at(int row, int col) { return m[col * 4 + row]; }
  float at(int row, int col) const { return m[col * 4 + row]; }
};

Mat4 operator*(const Mat4& a, const Mat4& b);
Vec4f operator*(const Mat4& a, const Vec4f& v);

/// glOrtho: maps [l,r]x[b,t]x[-n,-f] (eye space) to the clip cube.
Mat4 ortho(float l, float r, float b, float t, float n, float f);
/// gluPerspective: vertical field of view fovy [radians], aspect = width/height.
Mat4 perspective(float fovy, float aspect, float n, float f);
/// gluLookAt: eye looking at target with the given up direction.
Mat4 look_at(Vec3f eye, Vec3f target, Vec3f up);

}  // namespace sph::render
