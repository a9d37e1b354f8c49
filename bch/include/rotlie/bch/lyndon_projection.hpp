#pragma once
// Coordinates in the Lyndon basis of a homogeneous Lie element from its coefficients on the
// Lyndon words alone. P_l = l + (lexicographically larger words), so on the Lyndon words of one
// multidegree the pairing M[l][w] = <P_l, w> is unitriangular and z_w = Σ_{l ≤ w} c_l M[l][w]
// is solved by forward substitution. M is never stored: for a block of words w, every
// <P_u, w[o : o+|u|]> needed (u a bracket factor, o an offset) is one node of a straight-line
// program, P_uv = P_u P_v − P_v P_u read on the window.
#include <vector>

#include "rotlie/bch/int128.hpp"
#include "rotlie/bch/lyndon_basis.hpp"

namespace rotlie::bch {

/// coefficients[i] for i in [basis.begin(d), basis.end(d)) holds z_w · D on entry and c_w · D on
/// exit (D any common denominator). `threads` workers share the multidegree classes (plain integers
/// only). Exact: node values are bounded by 2^(d−1) (int32 up to degree 31); each dot product is
/// bounded before it is summed (max |c| · Σ |M| + |z| < 2^126), else std::overflow_error.
void solve_lyndon_coordinates(const lyndon_basis& basis, int d, std::vector<int128>& coefficients, int threads = 1);

}  // namespace rotlie::bch
