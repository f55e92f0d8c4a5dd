// The lateral membrane of hand-made packings (fix_membrane3d/lateral_surface.h):
// which spheres are on it, inside and outside, its loads and the volume, against
// values worked by hand.
#include "lateral_surface.h"
#include "packings.h"
#include "shapes.h"
#include "membrane3d_vtk.h"
#include "surface_closure.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>

using namespace packings;
using membrane3d::LateralSurface;
using membrane3d::Side;
using shapes::expect_vector_near;

namespace {

constexpr double p = 2.0; // pressure
constexpr double round_off = 1e-12;

int count(const LateralSurface &m, Side side)
{
  int n = 0;
  for (Side s : m.side) n += s == side;
  return n;
}

// The sum of the loads on the spheres that `pick` selects.
Vector3d load_on(const std::vector<Sphere> &s, const LateralSurface &m,
                 const std::function<bool(const Vector3d &)> &pick)
{
  const auto load = membrane3d::membrane_loads(m, s.size(), p);
  Vector3d sum = Vector3d::Zero();
  for (std::size_t i = 0; i < s.size(); ++i)
    if (pick(s[i].x)) sum += load[i];
  return sum;
}

// `layers` rings of n spheres of circumradius R at spacing 1 in z, each around a
// central sphere (n + 1 per layer, the central one last)
std::vector<Sphere> rings(int n, int layers, double R)
{
  std::vector<Sphere> s;
  for (int k = 0; k < layers; ++k) {
    for (int i = 0; i < n; ++i)
      s.push_back(
          {Vector3d(R * std::cos(2 * M_PI * i / n), R * std::sin(2 * M_PI * i / n), k), radius});
    s.push_back({Vector3d(0, 0, k), radius});
  }
  return s;
}

} // namespace

// 4 x 3 x 5 simple-cubic block, T = r: face diagonals (gap sqrt 2 - 1) are links,
// body diagonals (sqrt 3 - 1) are not. The membrane runs through the centres of the
// four lateral faces, from the lower platen (z = -1/2) to the upper (9/2).
TEST(LateralSurface, SimpleCubicBlock)
{
  const auto s = simple_cubic(4, 3, 5);
  const auto m = membrane3d::lateral_surface(s, touching_platens(s), radius);
  EXPECT_EQ(count(m, Side::surface), 60 - 2 * 1 * 5);
  EXPECT_EQ(count(m, Side::inside), 10);
  EXPECT_EQ(count(m, Side::outside), 0);
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Vector3d &x = s[i].x;
    const bool on_face = x.x() == 0 || x.x() == 3 || x.y() == 0 || x.y() == 2;
    EXPECT_EQ(m.side[i], on_face ? Side::surface : Side::inside) << "sphere " << i;
  }
  EXPECT_TRUE(m.reaches_lo && m.reaches_hi);
  EXPECT_NEAR(membrane3d::lateral_volume(m.surface), 3 * 2 * 5, round_off);
  expect_vector_near(membrane3d::vector_area(m.surface), Vector3d::Zero(), round_off);
  // each face: p x its area (width x height 5), inwards
  expect_vector_near(load_on(s, m, [](const Vector3d &x) { return x.x() == 3; }),
                     Vector3d(-p * 2 * 5, 0, 0), round_off);
  expect_vector_near(load_on(s, m, [](const Vector3d &x) { return x.x() == 0; }),
                     Vector3d(p * 2 * 5, 0, 0), round_off);
  expect_vector_near(load_on(s, m, [](const Vector3d &x) { return x.y() == 2; }),
                     Vector3d(0, -p * 3 * 5, 0), round_off);
  expect_vector_near(load_on(s, m, [](const Vector3d &x) { return x.y() == 0; }),
                     Vector3d(0, p * 3 * 5, 0), round_off);
}

namespace {

// The 4 x 3 x 5 block with one more sphere out of its x = 3 face, over the window
// y in [0, 1], z in [2, 3], at gap g from the window's four spheres.
std::vector<Sphere> block_with_bump(double g)
{
  auto s = simple_cubic(4, 3, 5);
  s.push_back({Vector3d(3 + std::sqrt((1 + g) * (1 + g) - 0.5), 0.5, 2.5), radius});
  return s;
}

bool beyond_face(const Vector3d &x)
{
  return x.x() >= 3;
}

} // namespace

// The bump's four links make a square pyramid on the window: the bump is on the
// membrane, the window's spheres stay on it, and the volume grows by the pyramid's
// (base 1, height h) / 3; the face's load is still p x its projected area.
TEST(LateralSurface, BumpAtGapJustBelowTheTolerance)
{
  for (double g : {0.0, radius - 1e-9}) {
    const auto s = block_with_bump(g);
    const auto m = membrane3d::lateral_surface(s, touching_platens(s), radius);
    const double h = s.back().x.x() - 3;
    EXPECT_EQ(m.side.back(), Side::surface) << "gap " << g;
    EXPECT_EQ(count(m, Side::surface), 51);
    EXPECT_NEAR(membrane3d::lateral_volume(m.surface), 30 + h / 3, round_off);
    expect_vector_near(load_on(s, m, beyond_face), Vector3d(-p * 2 * 5, 0, 0), round_off);
    expect_vector_near(load_on(s, m, [](const Vector3d &) { return true; }), Vector3d::Zero(),
                       round_off);
  }
}

// Just beyond the tolerance the bump has no link: it has escaped, the block is as
// without it.
TEST(LateralSurface, BumpAtGapJustAboveTheToleranceHasEscaped)
{
  const auto s = block_with_bump(radius + 1e-9);
  const auto m = membrane3d::lateral_surface(s, touching_platens(s), radius);
  EXPECT_EQ(m.side.back(), Side::outside);
  EXPECT_EQ(count(m, Side::surface), 50);
  EXPECT_NEAR(membrane3d::lateral_volume(m.surface), 30, round_off);
  EXPECT_EQ(membrane3d::membrane_loads(m, s.size(), p).back(), Vector3d::Zero());
}

// A sphere far out; a tip on the bump of the last test, linked to the bump only (a
// dead end: no facet of links holds it); a linked 2 x 2 x 2 cluster away from the
// block: all outside, the block and its bump as without them.
TEST(LateralSurface, EscapedSpheresDeadEndAndClusterAreOutside)
{
  auto s = block_with_bump(0);
  const double h = s.back().x.x() - 3;
  s.push_back({s.back().x + Vector3d(1, 0, 0), radius}); // the tip
  s.push_back({Vector3d(9, 1, 2.5), radius});            // far out
  for (int k = 0; k < 8; ++k)
    s.push_back({Vector3d(6 + (k & 1), -3 + ((k >> 1) & 1), 1 + ((k >> 2) & 1)), radius});
  const auto m = membrane3d::lateral_surface(s, touching_platens(simple_cubic(4, 3, 5)), radius);
  EXPECT_EQ(m.side[60], Side::surface); // the bump
  for (std::size_t i = 61; i < s.size(); ++i) EXPECT_EQ(m.side[i], Side::outside) << i;
  EXPECT_EQ(count(m, Side::surface), 51);
  EXPECT_NEAR(membrane3d::lateral_volume(m.surface), 30 + h / 3, round_off);
}

// A 4 x 3 x 6 block with a shelf x in {4, 5, 6} on its two upper layers (z = 4, 5):
// the membrane runs under the shelf (its normal -z), so the loads have an axial part
// p x the underside's area (3 x 2), and the volume is 3 x 2 x 6 + 3 x 2 x 1.5.
TEST(LateralSurface, OverhangingShelf)
{
  auto s = simple_cubic(4, 3, 6);
  for (int k = 4; k < 6; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 4; i < 7; ++i) s.push_back({Vector3d(i, j, k), radius});
  const auto m = membrane3d::lateral_surface(s, touching_platens(s), radius);
  // inside: the block's core x in {1, 2}, y = 1 (12) and the shelf's upper core
  // x in {3, 4, 5}, y = 1, z = 5
  EXPECT_EQ(count(m, Side::inside), 15);
  EXPECT_EQ(count(m, Side::surface), 90 - 15);
  EXPECT_EQ(m.side[2 * 12 + 1 * 4 + 3], Side::surface); // (3, 1, 2): the face below the shelf
  EXPECT_NEAR(membrane3d::lateral_volume(m.surface), 36 + 9, round_off);
  const auto all = [](const Vector3d &) { return true; };
  expect_vector_near(load_on(s, m, all), Vector3d(0, 0, p * 3 * 2), round_off);
  EXPECT_NEAR(load_on(s, m, [](const Vector3d &x) { return x.z() == 4 && x.x() >= 3; }).z(),
              p * 3 * 2, round_off);
  EXPECT_NEAR(load_on(s, m, [](const Vector3d &x) { return x.x() == 6; }).x(), -p * 2 * 1.5,
              round_off);
  EXPECT_NEAR(load_on(s, m, [](const Vector3d &x) { return x.x() == 0; }).x(), p * 2 * 6,
              round_off);
  EXPECT_NEAR(load_on(s, m, [](const Vector3d &x) { return x.y() == 0; }).y(),
              p * (3 * 6 + 3 * 1.5), round_off);
}

// FCC block m = 2, l = 3 (88 spheres), T = 0.75: the (100) faces' square windows and
// the windows between the lowest layer and its image in the platen are closed. The
// membrane is the four faces, the volume (4 h)^2 x H with h = sqrt 2 / 2.
TEST(LateralSurface, FaceCentredCubicBlock)
{
  const auto s = face_centred_cubic(2, 3);
  ASSERT_EQ(s.size(), 88u);
  const Platens platens = touching_platens(s);
  const auto m = membrane3d::lateral_surface(s, platens, 0.75);
  const double side = 4 * std::sqrt(2.0) / 2;
  EXPECT_EQ(count(m, Side::inside), 32);
  EXPECT_EQ(count(m, Side::surface), 56);
  EXPECT_NEAR(membrane3d::lateral_volume(m.surface), side * side * (platens.hi - platens.lo),
              1e-11);
  expect_vector_near(load_on(s, m, [side](const Vector3d &x) { return x.x() > side - 1e-9; }),
                     Vector3d(-p * side * (platens.hi - platens.lo), 0, 0), 1e-11);
}

// Rings of 12 touching spheres (circumradius R = 1 / (2 sin 15 deg)) stacked in 6
// layers at spacing 1 around a central column out of their reach: the membrane is the
// 12-gon prism through the ring centres, volume 6 R^2 sin 30 deg x H; the column is
// inside.
TEST(LateralSurface, CylinderOfRingsHasThePrismVolume)
{
  const int n = 12, layers = 6;
  const double R = 1 / (2 * std::sin(M_PI / n));
  const std::vector<Sphere> s = rings(n, layers, R);
  const Platens platens = touching_platens(s);
  const auto m = membrane3d::lateral_surface(s, platens, radius);
  EXPECT_EQ(count(m, Side::surface), n * layers);
  for (int k = 0; k < layers; ++k) EXPECT_EQ(m.side[k * (n + 1) + n], Side::inside);
  EXPECT_NEAR(membrane3d::lateral_volume(m.surface),
              n / 2.0 * R * R * std::sin(2 * M_PI / n) * (platens.hi - platens.lo), 1e-12);
  expect_vector_near(load_on(s, m, [](const Vector3d &) { return true; }), Vector3d::Zero(), 1e-12);
}

// A block lifted off the lower platen by 0.3 (within T = 0.5): the membrane is still
// sealed to the platen, hanging from the lowest layer down to it, V = 3 x 2 x 5.3 and
// nothing axial; lifted by 0.6 (beyond T) the flood runs under it: no rim there, and
// the membrane pushes it up by p x its base.
TEST(LateralSurface, BlockOffThePlatenKeepsItsRimWithinTheTolerance)
{
  const auto s = simple_cubic(4, 3, 5);
  Platens platens = touching_platens(s);
  platens.lo -= 0.3;
  const auto near = membrane3d::lateral_surface(s, platens, radius);
  EXPECT_TRUE(near.reaches_lo && near.reaches_hi);
  EXPECT_NEAR(membrane3d::lateral_volume(near.surface), 3 * 2 * 5.3, round_off);
  expect_vector_near(load_on(s, near, [](const Vector3d &) { return true; }), Vector3d::Zero(),
                     round_off);
  platens.lo -= 0.3;
  const auto far = membrane3d::lateral_surface(s, platens, radius);
  EXPECT_FALSE(far.reaches_lo);
  EXPECT_TRUE(far.reaches_hi);
  expect_vector_near(load_on(s, far, [](const Vector3d &) { return true; }),
                     Vector3d(0, 0, p * 3 * 2), round_off);
}

// The input order changes nothing: the same sides, loads (to round-off) and volume.
TEST(LateralSurface, InputOrderDoesNotMatter)
{
  const auto s = block_with_bump(0.2);
  std::vector<int> order(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) order[i] = static_cast<int>((i * 37) % s.size());
  std::vector<Sphere> shuffled;
  for (int i : order) shuffled.push_back(s[i]);
  const Platens platens = touching_platens(s);
  const auto a = membrane3d::lateral_surface(s, platens, radius);
  const auto b = membrane3d::lateral_surface(shuffled, platens, radius);
  const auto load_a = membrane3d::membrane_loads(a, s.size(), p);
  const auto load_b = membrane3d::membrane_loads(b, s.size(), p);
  for (std::size_t k = 0; k < s.size(); ++k) {
    EXPECT_EQ(a.side[order[k]], b.side[k]) << k;
    expect_vector_near(load_a[order[k]], load_b[k], round_off);
  }
  EXPECT_NEAR(membrane3d::lateral_volume(a.surface), membrane3d::lateral_volume(b.surface),
              round_off);
}

TEST(LateralSurface, SpheresOutOfReachAreNoPacking)
{
  std::vector<Sphere> s;
  for (int k = 0; k < 27; ++k)
    s.push_back({Vector3d(3 * (k % 3), 3 * (k / 3 % 3), 3 * (k / 9)), radius});
  EXPECT_THROW(membrane3d::lateral_surface(s, {-1, 7}, radius), std::runtime_error);
}

// Spheres that span no volume with their platen images (a one-sphere-thick wall
// between touching platens, a column, a layer far from its platens) have no cells to
// flood: FlatSample, saying which, where the flood once read cells that were not
// tetrahedra (a segmentation fault).
TEST(LateralSurface, AFlatSampleIsRefused)
{
  const auto message = [](const std::vector<Sphere> &s, const Platens &platens) {
    try {
      membrane3d::lateral_surface(s, platens, radius);
    } catch (const membrane3d::FlatSample &e) {
      return std::string(e.what());
    }
    return std::string("no FlatSample");
  };
  const auto wall = simple_cubic(1, 4, 1); // x = 0, y = 0..3, z = 0
  EXPECT_EQ(message(wall, touching_platens(wall)),
            "the 4 spheres and their 8 images in the platens lie in one plane: they enclose "
            "no volume for a membrane to wrap");
  const auto column = simple_cubic(1, 1, 5);
  EXPECT_EQ(message(column, touching_platens(column)),
            "the 5 spheres and their 8 images in the platens lie on one line: they enclose "
            "no volume for a membrane to wrap");
  const auto layer = simple_cubic(2, 2, 1);
  EXPECT_EQ(message(layer, {-20, 20}),
            "the 4 spheres lie in one plane: they enclose no volume for a membrane to wrap");
}

TEST(LateralSurface, BadInputIsRefused)
{
  const auto s = simple_cubic(2, 2, 2);
  const Platens platens = touching_platens(s);
  EXPECT_THROW(membrane3d::lateral_surface(s, {1.5, -0.5}, radius), std::invalid_argument);
  EXPECT_THROW(membrane3d::lateral_surface(s, {0.5, 1.5}, radius), std::invalid_argument);
  EXPECT_THROW(membrane3d::lateral_surface({s[0], s[1], s[2]}, platens, radius),
               std::invalid_argument);
  EXPECT_THROW(membrane3d::lateral_surface(s, platens, -0.1), std::invalid_argument);
  EXPECT_THROW(membrane3d::lateral_surface(s, platens, std::nan("")), std::invalid_argument);
  auto bad = s;
  bad[3].r = 0;
  EXPECT_THROW(membrane3d::lateral_surface(bad, platens, radius), std::invalid_argument);
  bad = s;
  bad[2].x.x() = std::nan("");
  EXPECT_THROW(membrane3d::lateral_surface(bad, platens, radius), std::invalid_argument);
}

// A topology holds while the spheres move: placed on the block stretched by 10 % in x
// it gives the stretched block's volume; over its members only (the 50 face spheres
// of the bump-free block and the escaped bump) it gives the same loads.
TEST(LateralSurface, TopologyPlacedOnMovedSpheresAndOnItsMembers)
{
  const auto s = block_with_bump(radius + 0.1); // the bump has escaped
  const Platens platens = touching_platens(s);
  const auto topology = membrane3d::detect_membrane(s, platens, radius);
  auto stretched = s;
  for (Sphere &x : stretched) x.x.x() *= 1.1;
  const auto moved = membrane3d::place_membrane(topology, stretched, platens);
  EXPECT_NEAR(membrane3d::lateral_volume(moved.surface), 3.3 * 2 * 5, 1e-12);

  std::vector<int> members;
  const auto mine = membrane3d::members_only(topology, members);
  ASSERT_EQ(members.size(), 51u);
  EXPECT_EQ(members.back(), 60);
  EXPECT_EQ(mine.side.back(), Side::outside);
  std::vector<Sphere> member_spheres;
  for (int i : members) member_spheres.push_back(s[i]);
  const auto all = membrane3d::place_membrane(topology, s, platens);
  const auto few = membrane3d::place_membrane(mine, member_spheres, platens);
  const auto load_all = membrane3d::membrane_loads(all, s.size(), p);
  const auto load_few = membrane3d::membrane_loads(few, members.size(), p);
  for (std::size_t k = 0; k < members.size(); ++k) {
    EXPECT_EQ(load_few[k], load_all[members[k]]) << k;
    EXPECT_EQ(few.side[k], all.side[members[k]]) << k;
  }
  EXPECT_THROW(membrane3d::place_membrane(topology, member_spheres, platens),
               std::invalid_argument);
}

// The axis of the 4 x 3 block is (1.5, 1); the escaped bump at y = 0.5 is pushed with
// p pi r^2 along (1.5 - x, 1 - 0.5), normalised.
TEST(LateralSurface, EscapedSphereIsPushedTowardsTheAxis)
{
  const auto s = block_with_bump(radius + 0.1);
  const auto m = membrane3d::lateral_surface(s, touching_platens(s), radius);
  const Eigen::Vector2d axis = membrane3d::membrane_axis(m);
  EXPECT_NEAR(axis.x(), 1.5, 1e-12);
  EXPECT_NEAR(axis.y(), 1.0, 1e-12);
  std::vector<Vector3d> load(s.size(), Vector3d::Zero());
  membrane3d::add_escape_loads(m, s, p, load);
  const Vector3d towards(1.5 - s.back().x.x(), 0.5, 0);
  expect_vector_near(load.back(), p * M_PI * radius * radius * towards.normalized(), 1e-12);
  for (std::size_t i = 0; i + 1 < s.size(); ++i) EXPECT_EQ(load[i], Vector3d::Zero());
}

// Independent checks (surface_closure.h): the membrane closed by caps at its rims
// encloses the volume lateral_volume gives, and its winding number is 1 about every
// sphere the flood put inside and 0 about every escaped one.
TEST(LateralSurface, CapsAndWindingNumberAgreeWithTheFlood)
{
  auto shelf = simple_cubic(4, 3, 6);
  for (int k = 4; k < 6; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 4; i < 7; ++i) shelf.push_back({Vector3d(i, j, k), radius});
  auto bumps = block_with_bump(0.3);
  bumps.push_back({Vector3d(1.5, -0.9, 2.5), radius}); // touching nothing: escaped
  for (const auto &s : {shelf, bumps, face_centred_cubic(2, 3)}) {
    const double tolerance = s.size() == 88 ? 0.75 : radius;
    const auto m = membrane3d::lateral_surface(s, touching_platens(s), tolerance);
    const auto closed = membrane3d::close_with_caps(m.surface);
    EXPECT_NEAR(membrane3d::enclosed_volume(closed), membrane3d::lateral_volume(m.surface), 1e-12);
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (m.side[i] == Side::surface) continue;
      EXPECT_NEAR(membrane3d::winding_number(closed, s[i].x), m.side[i] == Side::inside ? 1 : 0,
                  1e-9)
          << "sphere " << i << " of " << s.size();
    }
  }
}

// On the outer faces: the 4 x 3 x 5 block's faces move out by r = 1/2, its vertical
// edges by r along both normals, so the membrane is the block's outer box 4 x 3 x 5
// (V = 60) and each face's spheres carry p x its outer area, as a rigid wall's would:
// p x 3 x 5 on the face x = 0, p x 4 x 5 on the face y = 0 (through the centres:
// p x 2 x 5 and p x 3 x 5).
TEST(LateralSurface, OuterFacesOfABlockAreItsBox)
{
  const auto s = simple_cubic(4, 3, 5);
  const auto m = membrane3d::lateral_surface(s, touching_platens(s), radius,
                                             membrane3d::Vertices::outer_faces);
  EXPECT_EQ(count(m, Side::surface), 50);
  EXPECT_NEAR(membrane3d::lateral_volume(m.surface), 4 * 3 * 5, 1e-12);
  EXPECT_NEAR(load_on(s, m, [](const Vector3d &x) { return x.x() == 0; }).x(), p * 3 * 5, 1e-12);
  EXPECT_NEAR(load_on(s, m, [](const Vector3d &x) { return x.y() == 0; }).y(), p * 4 * 5, 1e-12);
  expect_vector_near(load_on(s, m, [](const Vector3d &) { return true; }), Vector3d::Zero(), 1e-12);
  const auto o = membrane3d::outer_face_offsets(
      membrane3d::detect_membrane(s, touching_platens(s), radius), s, touching_platens(s));
  expect_vector_near(o[0], Vector3d(-radius, -radius, 0), 1e-12); // a corner column
  expect_vector_near(o[1], Vector3d(0, -radius, 0), 1e-12);       // the face y = 0
  expect_vector_near(o[1 * 4 + 1], Vector3d::Zero(), 0);          // inside: none
}

// On the outer faces the 12-gon prism of rings moves out to the polygon whose sides
// are r from the centres' sides: circumradius R + r / cos 15 deg.
TEST(LateralSurface, OuterFacesOfRingsAreTheOffsetPrism)
{
  const int n = 12, layers = 4;
  const double R = 1 / (2 * std::sin(M_PI / n));
  const std::vector<Sphere> s = rings(n, layers, R);
  const Platens platens = touching_platens(s);
  const auto m = membrane3d::lateral_surface(s, platens, radius, membrane3d::Vertices::outer_faces);
  const double outer = R + radius / std::cos(M_PI / n);
  EXPECT_NEAR(membrane3d::lateral_volume(m.surface),
              n / 2.0 * outer * outer * std::sin(2 * M_PI / n) * (platens.hi - platens.lo), 1e-12);
}

// The offset is at most 2 r: a sphere alone on a spike of facets does not fly off.
TEST(LateralSurface, OuterFaceOffsetIsBounded)
{
  const auto s = block_with_bump(0.3);
  const auto topology = membrane3d::detect_membrane(s, touching_platens(s), radius);
  const auto o = membrane3d::outer_face_offsets(topology, s, touching_platens(s));
  for (std::size_t i = 0; i < s.size(); ++i) EXPECT_LE(o[i].norm(), 2 * s[i].r + 1e-15);
}

// A sheared sample's spheres near its platens (data/cuboid_near_platen.txt, from a
// run of examples/triaxial). Were a vertex moved past a platen plane, its image would
// come inside and the facets of images only (left out of the membrane) would leave it
// open; kept between the planes, the membrane is closed by its caps: no lateral load,
// the caps' volume its own. Two of its facets (at spheres 16, 5, 10 by the lower
// platen and 179, 185, 188 by the upper) are folds facing against their spheres' net
// outward area (cosines -0.74 to -1): counted, they pulled those vertices up past the
// upper platen; left out, no vertex leaves the planes by itself.
TEST(LateralSurface, OuterFacesStayBetweenThePlatens)
{
  const std::vector<Sphere> s = packings::sheared_sample();
  ASSERT_EQ(s.size(), 198u);
  const double diameter = packings::mean_diameter(s);
  const Platens platens = packings::sheared_sample_platens;
  const auto topology = membrane3d::detect_membrane(s, platens, 0.7 * diameter);
  const auto o = membrane3d::outer_face_offsets(topology, s, platens);
  for (std::size_t i = 0; i < s.size(); ++i) {
    EXPECT_GE(s[i].x.z() + o[i].z(), platens.lo) << "sphere " << i;
    EXPECT_LE(s[i].x.z() + o[i].z(), platens.hi) << "sphere " << i;
  }
  EXPECT_LT(s[179].x.z() + o[179].z(), platens.hi);
  const auto m =
      membrane3d::place_membrane(topology, s, platens, membrane3d::Vertices::outer_faces);
  const Vector3d total = load_on(s, m, [](const Vector3d &) { return true; });
  EXPECT_LT(total.head<2>().norm(), 1e-12 * p * 1e-4);
  EXPECT_NEAR(membrane3d::enclosed_volume(membrane3d::close_with_caps(m.surface)),
              membrane3d::lateral_volume(m.surface), 1e-18);
}

// The VTK frame of the block with an escaped bump: the membrane's corners then the
// escapee as points, its facets as polys, the escapee as a vertex; the loads in the
// file sum to -p x the vector area (zero) plus the escapee's push p pi r^2.
TEST(LateralSurface, VtkFrameHoldsTheMembraneAndTheEscapee)
{
  const auto s = block_with_bump(radius + 0.1);
  const auto m = membrane3d::lateral_surface(s, touching_platens(s), radius);
  const std::string frame = membrane3d::vtk_frame(m, s, p);
  const std::size_t n = m.surface.points.size();
  EXPECT_NE(frame.find("NumberOfPoints=\"" + std::to_string(n + 1) + "\" NumberOfVerts=\"1\""),
            std::string::npos);
  EXPECT_NE(frame.find("NumberOfPolys=\"" + std::to_string(m.surface.facets.size()) + "\""),
            std::string::npos);
  // the Verts connectivity is the escapee's point, after the corners
  const std::size_t verts = frame.find("<Verts>");
  ASSERT_NE(verts, std::string::npos);
  EXPECT_NE(frame.find(" " + std::to_string(n) + "\n", verts), std::string::npos);
  // the load array: 3 numbers per point; their sum
  const std::size_t load = frame.find("Name=\"load\"");
  ASSERT_NE(load, std::string::npos);
  std::istringstream numbers(frame.substr(frame.find('>', load) + 1));
  Vector3d sum = Vector3d::Zero();
  for (std::size_t k = 0; k < 3 * (n + 1); ++k) {
    double v;
    ASSERT_TRUE(numbers >> v) << k;
    sum[k % 3] += v;
  }
  const double push = p * M_PI * radius * radius;
  EXPECT_NEAR(sum.norm(), push, 1e-12);
}

// The 4 x 3 x 5 block with the middle sphere of its x = 0 face's lowest row (at the
// lower platen) dented in by 1e-6 d, T = 0.7 d. Its face and the face's mirror in the
// platen are flat to 1e-6: the flood's boundary there passes through flat slivers and
// folds (a facet over its neighbours, facing the other way). The fold must not pull
// the row in (counted, it put the row's outer corners at 0.75 r: the volume 0.6 % low
// and an axial load p x 0.125 x 3 out of nothing): the membrane on the outer faces is
// the block's box to the dent, its loads sum to zero and each face gets a wall's load.
TEST(LateralSurface, OuterFacesOfADentedBlockAreItsBox)
{
  auto s = simple_cubic(4, 3, 5);
  const double dent = 1e-6;
  std::size_t dented = s.size();
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s[i].x == Vector3d(0, 1, 0)) dented = i;
  ASSERT_LT(dented, s.size());
  s[dented].x.x() = dent;
  const Platens platens{-radius, 4 + radius};
  const auto topology = membrane3d::detect_membrane(s, platens, 0.7);
  const auto o = membrane3d::outer_face_offsets(topology, s, platens);
  expect_vector_near(o[dented], Vector3d(-radius, 0, 0), 10 * dent);
  const auto m = membrane3d::place_membrane(topology, s, platens, membrane3d::Vertices::outer_faces);
  EXPECT_NEAR(membrane3d::lateral_volume(m.surface), 4 * 3 * 5, 10 * dent);
  // laterally zero to round-off; axially p x the caps' difference (the dent's, ~1e-6)
  const Vector3d total = load_on(s, m, [](const Vector3d &) { return true; });
  EXPECT_LT(total.head<2>().norm(), 1e-12);
  EXPECT_NEAR(total.z(), 0, p * 10 * dent);
  EXPECT_NEAR(load_on(s, m, [](const Vector3d &x) { return x.x() < 0.5; }).x(), p * 3 * 5,
              10 * dent);
  EXPECT_NEAR(load_on(s, m, [](const Vector3d &x) { return x.y() == 2; }).y(), -p * 4 * 5,
              10 * dent);
}

// An offset that points past a platen plane stops in it: a sphere r / 10 below the
// upper platen with three facets sloping up and out around it (a cone opening upwards)
// would be moved up by about r; it is moved to the plane, no further, and sideways as
// the facets ask.
TEST(LateralSurface, OuterFaceOffsetStopsAtThePlatenPlane)
{
  const Platens platens{-10, 0};
  const double z0 = -0.1 * radius;
  std::vector<Sphere> s = {{Vector3d(0, 0, z0), radius}};
  for (int k = 0; k < 3; ++k) {
    const double phi = 2 * M_PI * k / 3;
    s.push_back({Vector3d(std::cos(phi), std::sin(phi), z0 - 1), radius});
  }
  membrane3d::MembraneTopology topology;
  topology.side.assign(s.size(), Side::surface);
  // counter-clockwise seen from outside (above): normals up and out of the cone
  topology.facets = {{{{0, 0}, {1, 0}, {2, 0}}}, {{{0, 0}, {2, 0}, {3, 0}}},
                     {{{0, 0}, {3, 0}, {1, 0}}}};
  const auto o = membrane3d::outer_face_offsets(topology, s, platens);
  EXPECT_EQ(s[0].x.z() + o[0].z(), platens.hi);
}
