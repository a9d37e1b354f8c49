#pragma once
// An ellipsoid as an ICQ shape model (Gaskell's format): the six faces of a cube, each a (Q+1)² grid,
// pushed radially onto the unit sphere and stretched to semi-axes a, b, c. The faces are laid as in
// SPC's models (face 1 at +z, faces 2 … 5 at +x, +y, −x, −y, face 6 at −z) with I and J turned so that
// every shared edge of the format's table is the same row of two faces. A vertex is computed from its
// integer cube coordinates, so the copies on shared edges are bit for bit equal.
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

namespace rotlie::test_support {

/// The file's text; `mirrored` negates x (the faces' I, J axes then turn the other way round).
inline std::string icq_ellipsoid_text(int q, double a, double b, double c, bool mirrored = false) {
  // per face: the axis and sign of its normal, then of I, then of J
  struct layout {
    int normal, normal_sign, i_axis, i_sign, j_axis, j_sign;
  };
  constexpr layout faces[6] = {{2, 1, 1, -1, 0, 1}, {0, 1, 1, -1, 2, -1}, {1, 1, 0, 1, 2, -1},
                               {0, -1, 1, 1, 2, -1}, {1, -1, 0, -1, 2, -1}, {2, -1, 1, -1, 0, -1}};
  std::string text = std::to_string(q) + "\n";
  char line[128];
  for (const auto& f : faces)
    for (int j = 0; j <= q; ++j)
      for (int i = 0; i <= q; ++i) {
        std::array<double, 3> p{};
        p[static_cast<std::size_t>(f.normal)] = f.normal_sign * q;
        p[static_cast<std::size_t>(f.i_axis)] = f.i_sign * (2 * i - q);
        p[static_cast<std::size_t>(f.j_axis)] = f.j_sign * (2 * j - q);
        const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", (mirrored ? -a : a) * p[0] / n, b * p[1] / n, c * p[2] / n);
        text += line;
      }
  return text;
}

}  // namespace rotlie::test_support
