// cambrian: the small vector and rotation types shared by genomes, body plans and physics.
#pragma once

#include <cmath>

namespace cambrian {

/// A 3-vector in metres, radians or unitless, by context.
struct Vec3 {
  double x = 0, y = 0, z = 0;

  double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  friend Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
  friend Vec3 operator*(Vec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
  friend Vec3 operator*(double s, Vec3 a) { return a * s; }
  friend bool operator==(Vec3 a, Vec3 b) = default;
};

inline double dot(Vec3 a, Vec3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(Vec3 a) {
  return std::sqrt(dot(a, a));
}
inline Vec3 hadamard(Vec3 a, Vec3 b) {
  return {a.x * b.x, a.y * b.y, a.z * b.z};
}

/// A unit quaternion (w, x, y, z) rotating vectors from a local frame into its parent frame.
struct Quat {
  double w = 1, x = 0, y = 0, z = 0;
  friend bool operator==(Quat a, Quat b) = default;
};

inline Quat operator*(Quat a, Quat b) {
  return {
      a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
      a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
inline Quat conjugate(Quat q) {
  return {q.w, -q.x, -q.y, -q.z};
}

/// Rotates v by q.
inline Vec3 rotate(Quat q, Vec3 v) {
  Vec3 u{q.x, q.y, q.z};
  Vec3 t = 2.0 * cross(u, v);
  return v + q.w * t + cross(u, t);
}

/// Rotation from intrinsic Z-Y-X Euler angles (yaw about z, then pitch about y, then roll about x).
inline Quat quatFromEuler(Vec3 rpy) {
  double cr = std::cos(rpy.x * 0.5), sr = std::sin(rpy.x * 0.5);
  double cp = std::cos(rpy.y * 0.5), sp = std::sin(rpy.y * 0.5);
  double cy = std::cos(rpy.z * 0.5), sy = std::sin(rpy.z * 0.5);
  return {cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
          cr * cp * sy - sr * sp * cy};
}

/// A rigid transform: p_parent = rotation * p_local + position.
struct Transform {
  Vec3 position;
  Quat rotation;
};

inline Vec3 apply(const Transform& t, Vec3 p) {
  return rotate(t.rotation, p) + t.position;
}
inline Transform compose(const Transform& a, const Transform& b) {
  return {apply(a, b.position), a.rotation * b.rotation};
}

constexpr double kPi = 3.14159265358979323846;

}  // namespace cambrian
