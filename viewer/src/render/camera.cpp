#include "kerf/render/camera.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>

namespace kerf::render {

using geometry::Vec3;

std::optional<View> parseView(std::string_view name) {
  if (name == "iso") return View::Iso;
  if (name == "top") return View::Top;
  if (name == "front") return View::Front;
  if (name == "side") return View::Side;
  return std::nullopt;
}

const char* viewName(View v) {
  switch (v) {
    case View::Iso: return "iso";
    case View::Top: return "top";
    case View::Front: return "front";
    case View::Side: return "side";
  }
  return "iso";
}

Vec3 Camera::eyeDirection() const {
  return {std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch)};
}
Vec3 Camera::right() const { return {-std::sin(yaw), std::cos(yaw), 0.0}; }
Vec3 Camera::up() const { return eyeDirection().cross(right()); }

Eigen::Matrix4f Camera::viewMatrix() const {
  const Vec3 r = right(), u = up(), e = eyeDirection();
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = r.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = e.transpose();
  m(0, 3) = -r.dot(target);
  m(1, 3) = -u.dot(target);
  m(2, 3) = -e.dot(target);
  return m.cast<float>();
}

Eigen::Matrix4f Camera::projectionMatrix(double aspect) const {
  // Orthographic, eye space z in [-depth, +depth] around the target maps to depth [1, -1]...[0,1].
  const double h = halfHeight, w = halfHeight * aspect;
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = 1.0 / w;
  m(1, 1) = 1.0 / h;
  m(2, 2) = -1.0 / depth;
  m(3, 3) = 1.0;
  return m.cast<float>();
}

Eigen::Vector2d Camera::project(const Vec3& p, int width, int height) const {
  const Vec3 d = p - target;
  const double aspect = static_cast<double>(width) / height;
  const double x = d.dot(right()) / (halfHeight * aspect), y = d.dot(up()) / halfHeight;
  return {(x + 1.0) * 0.5 * width, (1.0 - y) * 0.5 * height};
}

Camera fitCamera(const Vec3& boxMin, const Vec3& boxMax, View view, int width, int height, double margin,
                 int reservedTop) {
  Camera c;
  switch (view) {
    case View::Iso:
      c.yaw = -0.25 * geometry::kPi;
      c.pitch = std::atan(1.0 / std::sqrt(2.0));  // the classic isometric 35.26 deg
      break;
    case View::Top:
      c.yaw = -0.5 * geometry::kPi;
      c.pitch = 0.5 * geometry::kPi;
      break;
    case View::Front:
      c.yaw = -0.5 * geometry::kPi;
      c.pitch = 0.0;
      break;
    case View::Side:
      c.yaw = 0.0;
      c.pitch = 0.0;
      break;
  }
  c.target = 0.5 * (boxMin + boxMax);
  const Vec3 r = c.right(), u = c.up();
  double hx = 0.0, hy = 0.0;
  for (int i = 0; i < 8; ++i) {
    const Vec3 corner{(i & 1) ? boxMax.x() : boxMin.x(), (i & 2) ? boxMax.y() : boxMin.y(),
                      (i & 4) ? boxMax.z() : boxMin.z()};
    hx = std::max(hx, std::abs((corner - c.target).dot(r)));
    hy = std::max(hy, std::abs((corner - c.target).dot(u)));
  }
  const int below = std::max(1, height - std::clamp(reservedTop, 0, height / 2));
  const double aspect = static_cast<double>(width) / below;
  const double half = std::max({hy, hx / aspect, 1e-3}) * (1.0 + 2.0 * margin);
  // Fitted into the band below the title, then seen in the whole image at the same scale.
  c.halfHeight = half * static_cast<double>(height) / below;
  c.target += c.up() * (0.5 * (height - below) * c.mmPerPixel(height));
  c.depth = std::max((boxMax - boxMin).norm(), 1e-3) * 2.0;
  return c;
}

}  // namespace kerf::render
