// How the tolerance T sets fix membrane3d's surface on a real packing: for T from
// 0.05 to 1.0 mean diameters, the membrane spheres, those more than two diameters
// inside the skin of a cylinder of radius R (leaks, or the membrane closing under a
// platen where the sample has left it) and how many of them are next to a platen, the
// escaped spheres, the volume and the detection time.
// Reads a LIGGGHTS dump "id radius x y z" (bench/membrane3d_tolerance.sh writes it).
//   membrane3d_tolerance DUMP R ZLO ZHI
#include "lateral_surface.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char **argv) {
  if (argc != 5) {
    std::cerr << "usage: membrane3d_tolerance DUMP R ZLO ZHI\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  const double radius = std::atof(argv[2]);
  const membrane3d::Platens platens{std::atof(argv[3]), std::atof(argv[4])};
  std::string line;
  for (int k = 0; k < 9 && std::getline(in, line); ++k) {}  // the dump's header
  std::vector<membrane3d::Sphere> s;
  double id, r, x, y, z, diameters = 0;
  while (in >> id >> r >> x >> y >> z) {
    s.push_back({Eigen::Vector3d(x, y, z), r});
    diameters += 2 * r;
  }
  if (s.empty()) {
    std::cerr << "no spheres in " << argv[1] << "\n";
    return 1;
  }
  const double d = diameters / s.size();
  std::printf("%zu spheres, mean diameter %.4g m, cylinder radius %.4g m, platens %.4g .. %.4g m\n",
              s.size(), d, radius, platens.lo, platens.hi);
  std::printf("| T / d | membrane spheres | more than 2 d inside the skin | of them within 2 d of a "
              "platen | escaped | V (cm^3) | detection (ms) |\n|---|---|---|---|---|---|---|\n");
  for (double t : {0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 1.0}) {
    const auto start = std::chrono::steady_clock::now();
    membrane3d::LateralSurface m;
    try {
      m = membrane3d::lateral_surface(s, platens, t * d);
    } catch (const std::exception &e) {
      std::printf("| %.2f | %s | | | | | |\n", t, e.what());
      continue;
    }
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    int on = 0, deep = 0, deep_at_platen = 0, out = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (m.side[i] == membrane3d::Side::outside) ++out;
      if (m.side[i] != membrane3d::Side::surface) continue;
      ++on;
      if (std::hypot(s[i].x.x(), s[i].x.y()) + s[i].r >= radius - 2 * d) continue;
      ++deep;
      if (s[i].x.z() - platens.lo < 2 * d || platens.hi - s[i].x.z() < 2 * d) ++deep_at_platen;
    }
    std::printf("| %.2f | %d | %d | %d | %d | %.2f | %.0f |\n", t, on, deep, deep_at_platen, out,
                1e6 * membrane3d::lateral_volume(m.surface), ms);
  }
}
