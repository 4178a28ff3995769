// An orthographic camera: a direction to look from (yaw, pitch), a target and a half height.
// Engineering views are parallel projections, so top/front/side show true lengths.
#pragma once

#include "kerf/geometry/vec.h"

#include <Eigen/Core>

#include <optional>
#include <string_view>

namespace kerf::render {

enum class View { Iso, Top, Front, Side };
std::optional<View> parseView(std::string_view name);
const char* viewName(View v);

struct Camera {
  double yaw = -0.25 * geometry::kPi;  ///< radians about +z; -90 deg looks from -y (front)
  double pitch = 0.6155;               ///< radians above the xy plane; +90 deg looks down (top)
  geometry::Vec3 target{0, 0, 0};
  double halfHeight = 1.0;  ///< half the visible height, mm
  double depth = 1.0;       ///< half the depth range, mm (near/far around the target)

  bool operator==(const Camera&) const = default;

  [[nodiscard]] geometry::Vec3 eyeDirection() const;  ///< unit, from the target towards the eye
  [[nodiscard]] geometry::Vec3 right() const;
  [[nodiscard]] geometry::Vec3 up() const;
  [[nodiscard]] Eigen::Matrix4f viewMatrix() const;
  [[nodiscard]] Eigen::Matrix4f projectionMatrix(double aspect) const;
  /// Pixel position (x right, y down, origin top left) of a point in a width x height image.
  [[nodiscard]] Eigen::Vector2d project(const geometry::Vec3& p, int width, int height) const;
  /// mm per pixel in an image `height` pixels high.
  [[nodiscard]] double mmPerPixel(int height) const { return 2.0 * halfHeight / height; }
};

/// A camera looking from `view` with the box fitted into a width x height image with a margin
/// (a fraction of the size on each side), below a band `reservedTop` pixels high (the title).
Camera fitCamera(const geometry::Vec3& boxMin, const geometry::Vec3& boxMax, View view, int width, int height,
                 double margin = 0.08, int reservedTop = 0);

}  // namespace kerf::render
