#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "membrane_chain.h"

namespace membrane {

namespace {

// Twice the signed shoelace area of `up` (in order) followed by `down` (in
// reverse order): the closing edges are the platen pieces between the sides.
template <class A, class B> double twice_area_up_down(const A &up, const B &down)
{
  const std::size_t nu = up.size(), nd = down.size(), n = nu + nd;
  auto vertex = [&](std::size_t i) -> const Eigen::Vector2d & {
    return i < nu ? up[i] : down[nd - 1 - (i - nu)];
  };
  double s = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d &a = vertex(i);
    const Eigen::Vector2d &b = vertex((i + 1) % n);
    s += a.x() * b.y() - b.x() * a.y();
  }
  return s;
}

} // namespace

double sample_area(const Polyline &left, const Polyline &right)
{
  if (left.empty() || right.empty()) return 0.0;
  // Up the left and down the right is clockwise, hence the sign flip.
  return -0.5 * twice_area_up_down(left, right);
}

double side_area(const Polyline &polyline, Side side, double x_wall)
{
  if (polyline.empty()) return 0.0;
  const std::array<Eigen::Vector2d, 2> wall = {Eigen::Vector2d(x_wall, polyline.front().y()),
                                               Eigen::Vector2d(x_wall, polyline.back().y())};
  return side == Side::Right ? -0.5 * twice_area_up_down(wall, polyline)
                             : -0.5 * twice_area_up_down(polyline, wall);
}

double outermost_x_at(double y, const Polyline &polyline, Side side)
{
  double best = std::numeric_limits<double>::quiet_NaN();
  auto take = [&](double x) {
    if (std::isnan(best) || (side == Side::Right ? x > best : x < best)) best = x;
  };
  for (std::size_t k = 0; k + 1 < polyline.size(); ++k) {
    const Eigen::Vector2d &a = polyline[k];
    const Eigen::Vector2d &b = polyline[k + 1];
    if (y < std::min(a.y(), b.y()) || y > std::max(a.y(), b.y())) continue;
    if (a.y() == b.y()) {
      take(a.x());
      take(b.x());
    } else {
      take(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
    }
  }
  return best;
}

double width_at(double y, const Polyline &left, const Polyline &right)
{
  return outermost_x_at(y, right, Side::Right) - outermost_x_at(y, left, Side::Left);
}

} // namespace membrane
