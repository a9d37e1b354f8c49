// Liquid water's potential (TIP3P, smooth molecular cutoff): forces and torques are minus the
// gradient of the energy (central differences in long double, every term, the switch included),
// Newton's third law, invariance under a rigid motion of the whole configuration, the cell list
// against all pairs, the same bits for one and two threads, the state file, and the moments' text
// that dedicated rotors are solved for.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <random>
#include <set>
#include <unistd.h>

#include "rotlie/models/scenes/liquid_water.hpp"
#include "rotlie/models/scenes/water_observables.hpp"
#include "rotlie/models/scenes/water_setup.hpp"
#include "rotlie/models/scenes/water_state_io.hpp"
#include "rotlie/models/scenes/water_model.hpp"
#include "rotlie/schemes/quad.hpp"

BOOST_AUTO_TEST_SUITE(liquid_water_test)

using namespace rotlie::models;
using rotlie::quad;

namespace {

using LD = long double;

template <class T>
rigid_body_state<T> molecule_at(const vec3<T>& q, std::mt19937_64& rng) {
  std::normal_distribution<double> g(0, 1);
  rigid_body_state<T> b;
  b.q = q;
  T v[4], n = 0;
  for (auto& c : v) {
    c = T(g(rng));
    n += c * c;
  }
  n = std::sqrt(n);
  b.rot.Q = quaternion_rotation(v[0] / n, v[1] / n, v[2] / n, v[3] / n);
  return b;
}

/// Molecules placed so that O–O distances fall in every regime: close contact (LJ repulsion),
/// ordinary range, inside the switch (9.5–11 Å), beyond the cutoff, and across the periodic
/// boundary. Positions are of the centre of mass; O sits 0.066 Å from it.
template <class T>
std::vector<rigid_body_state<T>> probe_configuration(const T& L) {
  std::mt19937_64 rng(7);
  std::vector<rigid_body_state<T>> m;
  const T c = L / 2;
  m.push_back(molecule_at<T>({c, c, c}, rng));
  m.push_back(molecule_at<T>({c + T(2.8), c + T(0.3), c}, rng));          // contact
  m.push_back(molecule_at<T>({c - T(4.1), c + T(1.7), c - T(1.2)}, rng));  // ordinary
  m.push_back(molecule_at<T>({c, c + T(10.1), c + T(0.4)}, rng));         // switch
  m.push_back(molecule_at<T>({c - T(9.9), c - T(1.2), c + T(0.6)}, rng)); // switch
  m.push_back(molecule_at<T>({c + T(0.2), c - T(10.6), c - T(0.3)}, rng)); // deep in the switch
  m.push_back(molecule_at<T>({T(0.3), c + T(3), c + T(5)}, rng));          // near the boundary …
  m.push_back(molecule_at<T>({L - T(0.9), c + T(4), c + T(6.5)}, rng));    // … its image is close
  m.push_back(molecule_at<T>({c + T(7), c + T(8), c - T(6)}, rng));        // beyond 11 Å of most
  return m;
}

template <class T>
liquid_water<T> water_in_box(const T& L, int threads = 1) {
  liquid_water_options<T> o;
  o.box = L;
  o.threads = threads;
  return liquid_water<T>(tip3p<T>(), o);
}

template <class T>
T energy_of(const liquid_water<T>& w, const std::vector<rigid_body_state<T>>& m) {
  std::vector<vec3<T>> f(m.size()), t(m.size());
  return w.evaluate(m, f, t);
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_probe_pairs_cover_every_regime) {
  const LD L = 24;
  const auto m = probe_configuration<LD>(L);
  const auto w = water_in_box<LD>(L);
  std::vector<vec3<LD>> x;
  w.site_positions(m, x);
  int contact = 0, plain = 0, switched = 0, beyond = 0, across = 0;
  for (std::size_t i = 0; i < m.size(); ++i)
    for (std::size_t j = i + 1; j < m.size(); ++j) {
      vec3<LD> d{x[3 * i][0] - x[3 * j][0], x[3 * i][1] - x[3 * j][1], x[3 * i][2] - x[3 * j][2]};
      const vec3<LD> e = minimum_image(d, L);
      const LD r = std::sqrt(dot(e, e));
      if (d != e && r < 11) ++across;
      if (r < 3.2L) ++contact;
      else if (r < 9.5L) ++plain;
      else if (r < 11) ++switched;
      else ++beyond;
    }
  BOOST_TEST_MESSAGE("pairs: contact " << contact << ", plain " << plain << ", switch " << switched << ", beyond " << beyond
                                       << ", across the boundary " << across);
  BOOST_TEST(contact >= 1);
  BOOST_TEST(plain >= 3);
  BOOST_TEST(switched >= 3);
  BOOST_TEST(beyond >= 3);
  BOOST_TEST(across >= 1);
}

BOOST_AUTO_TEST_CASE(forces_and_torques_are_minus_the_gradient) {
  const LD L = 24;
  const auto m0 = probe_configuration<LD>(L);
  const auto w = water_in_box<LD>(L);
  std::vector<vec3<LD>> F(m0.size()), tau(m0.size());
  w.evaluate(m0, F, tau);
  const LD step = 1e-6L;
  double worst = 0;
  for (std::size_t i = 0; i < m0.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      auto plus = m0, minus = m0;
      plus[i].q[k] += step;
      minus[i].q[k] -= step;
      const LD f = -(energy_of(w, plus) - energy_of(w, minus)) / (2 * step);
      vec3<LD> axis{};
      axis[k] = 1;
      plus = m0;
      minus = m0;
      plus[i].rot.Q = rotation(axis, step) * m0[i].rot.Q;  // rotation about the lab axis k through the centre
      minus[i].rot.Q = rotation(axis, -step) * m0[i].rot.Q;
      const LD t = -(energy_of(w, plus) - energy_of(w, minus)) / (2 * step);
      const double scale = 1 + std::abs(static_cast<double>(F[i][k])) + std::abs(static_cast<double>(tau[i][k]));
      worst = std::max({worst, std::abs(static_cast<double>(f - F[i][k])) / scale, std::abs(static_cast<double>(t - tau[i][k])) / scale});
      BOOST_TEST(std::abs(static_cast<double>(f - F[i][k])) < 1e-8 * scale, "force " << i << "," << k << ": " << F[i][k] << " vs −dV " << f);
      BOOST_TEST(std::abs(static_cast<double>(t - tau[i][k])) < 1e-8 * scale, "torque " << i << "," << k << ": " << tau[i][k] << " vs −dV " << t);
    }
  BOOST_TEST_MESSAGE("worst relative difference to −∇V: " << worst);
}

BOOST_AUTO_TEST_CASE(the_switch_is_smooth_at_both_ends) {
  const auto w = water_in_box<LD>(24);
  LD S, dS;
  for (LD r : {9.5L, 11.0L}) {
    const LD h = 1e-5L;
    LD Sm, dSm, Sp, dSp;
    w.switch_value(r - h, Sm, dSm);
    w.switch_value(r + h, Sp, dSp);
    w.switch_value(r, S, dS);
    BOOST_TEST(std::abs(static_cast<double>(Sp - Sm)) < 1e-15);  // S′ = 0 at the ends, so S moves by O(h⁴)
    BOOST_TEST(std::abs(static_cast<double>(dSp - dSm)) < 1e-10);
  }
  for (LD r = 9.55L; r < 11; r += 0.1L) {  // dS/dr against central differences
    const LD h = 1e-6L;
    LD Sm, Sp, d;
    w.switch_value(r - h, Sm, d);
    w.switch_value(r + h, Sp, d);
    w.switch_value(r, S, dS);
    BOOST_TEST(std::abs(static_cast<double>((Sp - Sm) / (2 * h) - dS)) < 1e-9);
  }
}

BOOST_AUTO_TEST_CASE(total_force_and_torque_vanish_for_an_isolated_cluster) {
  const LD L = 60;  // the cluster spans 21 Å: no image within the cutoff
  auto m = probe_configuration<LD>(24);
  const auto w = water_in_box<LD>(L);
  std::vector<vec3<LD>> F(m.size()), tau(m.size());
  w.evaluate(m, F, tau);
  vec3<LD> sumF{}, sumT{};
  LD scale = 0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    const vec3<LD> orbit = cross(m[i].q, F[i]);
    for (int k = 0; k < 3; ++k) {
      sumF[k] += F[i][k];
      sumT[k] += orbit[k] + tau[i][k];
      scale = std::max(scale, std::abs(F[i][k]));
    }
  }
  for (int k = 0; k < 3; ++k) {
    BOOST_TEST(std::abs(static_cast<double>(sumF[k])) < 1e-15 * static_cast<double>(scale));
    BOOST_TEST(std::abs(static_cast<double>(sumT[k])) < 1e-14 * static_cast<double>(scale) * 24);
  }
}

BOOST_AUTO_TEST_CASE(the_energy_is_invariant_under_a_rigid_motion) {
  const LD L = 60;
  auto m = probe_configuration<LD>(24);
  const auto w = water_in_box<LD>(L);
  const LD V0 = energy_of(w, m);
  const mat3<LD> R = rotation(vec3<LD>{2.0L / 7, 3.0L / 7, 6.0L / 7}, 1.234L);
  const vec3<LD> shift{3.3L, -1.7L, 5.1L};
  for (auto& b : m) {
    b.q = R * b.q;
    for (int k = 0; k < 3; ++k) b.q[k] += shift[k];
    b.rot.Q = R * b.rot.Q;
  }
  const LD V1 = energy_of(w, m);
  BOOST_TEST_MESSAGE("V = " << static_cast<double>(V0) << " kcal/mol, after the motion " << static_cast<double>(V1));
  BOOST_TEST(std::abs(static_cast<double>(V1 - V0)) < 1e-15 * std::abs(static_cast<double>(V0)) + 1e-15);
  // and in the periodic box, a translation by any vector (positions unwrapped or not)
  auto p = probe_configuration<LD>(24);
  const auto wp = water_in_box<LD>(24);
  const LD P0 = energy_of(wp, p);
  for (auto& b : p)
    for (int k = 0; k < 3; ++k) b.q[k] += shift[k] + 24 * (k - 1);
  BOOST_TEST(std::abs(static_cast<double>(energy_of(wp, p) - P0)) < 1e-14 * std::abs(static_cast<double>(P0)));
}

BOOST_AUTO_TEST_CASE(the_cell_list_finds_the_same_pairs_as_all_pairs) {
  // 1728 molecules: a box of 37.3 Å, three cells a side for the 12 Å list radius
  const long n = 1728;
  const double L = cubic_box_side<double>(n, tip3p<double>().mass, 0.9973);
  const auto s = lattice_water<double>(tip3p<double>(), n, L, 297, 3);
  std::vector<vec3<double>> o;
  for (const auto& b : s.bodies) o.push_back(b.q);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> jitter(-1, 1);
  for (auto& x : o)
    for (auto& c : x) c += jitter(rng) + 3 * L;  // off the lattice, and unwrapped
  molecule_pair_list<double> cells;
  cells.build(o, L, 12.0);
  std::set<std::pair<int, int>> by_cells, by_all;
  for (const auto& p : cells.pairs()) by_cells.insert({p.i, p.j});
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const vec3<double> d = minimum_image(vec3<double>{o[i][0] - o[j][0], o[i][1] - o[j][1], o[i][2] - o[j][2]}, L);
      if (dot(d, d) < 144.0) by_all.insert({i, j});
    }
  BOOST_TEST(cells.pairs().size() == by_cells.size());  // no pair twice
  BOOST_TEST((by_cells == by_all));
  BOOST_TEST_MESSAGE(by_all.size() << " pairs within 12 Å among " << n << " molecules");
}

BOOST_AUTO_TEST_CASE(one_and_two_threads_give_the_same_bits) {
  const long n = 512;
  const double L = cubic_box_side<double>(n, tip3p<double>().mass, 0.9973);
  const auto s = lattice_water<double>(tip3p<double>(), n, L, 297, 5);
  const auto w1 = water_in_box<double>(L, 1), w2 = water_in_box<double>(L, 2);
  std::vector<vec3<double>> F1(n), T1(n), F2(n), T2(n);
  const double V1 = w1.evaluate(s.bodies, F1, T1), V2 = w2.evaluate(s.bodies, F2, T2);
  BOOST_TEST(V1 == V2);
  BOOST_TEST((F1 == F2));
  BOOST_TEST((T1 == T2));
  // and the molecule sums equal the site forces summed (a second route through the same pairs)
  std::vector<vec3<double>> sites;
  const double Vs = w1.evaluate_sites(s.bodies, sites);
  BOOST_TEST(std::abs(Vs - V1) < 1e-12 * std::abs(V1));
  double worst = 0;
  for (long i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k)
      worst = std::max(worst, std::abs(sites[3 * i][k] + sites[3 * i + 1][k] + sites[3 * i + 2][k] - F1[i][k]));
  BOOST_TEST(worst < 1e-10);
}

BOOST_AUTO_TEST_CASE(a_state_file_round_trips_and_refuses_another_system) {
  const long n = 27;
  const double L = 30;
  const auto s = lattice_water<double>(tip3p<double>(), n, L, 297, 9);
  const auto dir = std::filesystem::temp_directory_path() / ("rotlie_water_state_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto path = dir / "state.txt";
  water_state_header<double> h;
  h.model = "TIP3P";
  h.molecules = n;
  h.box = L;
  write_water_state(path, h, s);
  water_state_header<double> got;
  const auto back = read_water_state(path, h, got);
  BOOST_TEST(back.bodies.size() == s.bodies.size());
  bool same = true;
  for (std::size_t i = 0; i < s.bodies.size(); ++i)
    same = same && back.bodies[i].q == s.bodies[i].q && back.bodies[i].p == s.bodies[i].p && back.bodies[i].rot.Q.a == s.bodies[i].rot.Q.a &&
           back.bodies[i].rot.G == s.bodies[i].rot.G;
  BOOST_TEST(same);  // bit for bit
  auto refused = [&](water_state_header<double> other, const std::string& words) {
    try {
      water_state_header<double> g;
      read_water_state(path, other, g);
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      BOOST_TEST_MESSAGE(what);
      return what.find(words) != std::string::npos && what.find('\n') == std::string::npos;
    }
    return false;
  };
  auto refused_path = [&](const std::filesystem::path& p, water_state_header<double> expected, const std::string& words) {
    try {
      water_state_header<double> g;
      read_water_state(p, expected, g);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what()).find(words) != std::string::npos;
    }
    return false;
  };
  auto other = h;
  other.molecules = 512;
  BOOST_TEST(refused(other, "holds 27 molecules, not 512"));
  other = h;
  other.box = 24.86;
  BOOST_TEST(refused(other, "box"));
  other = h;
  other.model = "TIP4P";
  BOOST_TEST(refused(other, "model TIP3P"));
  other = h;
  other.system = "dipole-field";
  BOOST_TEST(refused(other, "is for the system 'liquid-water'"));
  // a damaged file is refused, never read as something it is not
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string good = text.str();
  auto damaged = [&](const std::string& from, const std::string& to) {
    std::string t = good;
    const auto at = t.find(from);
    BOOST_REQUIRE(at != std::string::npos);
    t.replace(at, from.size(), to);
    std::ofstream(path, std::ios::trunc) << t;
  };
  damaged("molecules 27\n", "molecules 27junk\n");
  BOOST_TEST(refused(h, "is not a count"));
  damaged("time_fs 0\n", "time_fs nan\n");
  BOOST_TEST(refused(h, "time_fs"));
  const auto first_row_end = good.find('\n', good.find("columns"));
  const auto second_row_end = good.find('\n', first_row_end + 1);
  damaged(good.substr(first_row_end, second_row_end - first_row_end), good.substr(first_row_end, second_row_end - first_row_end) + " 1");
  BOOST_TEST(refused(h, "more than 18 numbers"));
  BOOST_TEST(refused_path("/dev/zero", h, "is not a regular file"));
  std::filesystem::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_box_smaller_than_twice_the_cutoff_is_refused) {
  BOOST_CHECK_THROW(water_in_box<double>(21.9), std::invalid_argument);
  BOOST_CHECK_NO_THROW(water_in_box<double>(22.1));
}

BOOST_AUTO_TEST_CASE(the_moments_text_is_the_geometry_to_18_digits_and_planar) {
  // the same geometry evaluated in float128 (34 digits): the text is it to 18 significant digits
  const auto geometry = tip3p<quad>().moments;
  for (int a = 0; a < 3; ++a) {
    const quad text = parse_scalar<quad>(tip3p_moments_text[a]);
    BOOST_TEST(static_cast<double>(abs(text - geometry[a]) / geometry[a]) < 1e-17, "axis " << a);
  }
  // I3 is the exact sum of the decimals I1 + I2 (18 decimals fit float128 exactly as integers)
  const quad unit = parse_scalar<quad>("1e-18");
  const quad I1 = round(parse_scalar<quad>(tip3p_moments_text[0]) / unit), I2 = round(parse_scalar<quad>(tip3p_moments_text[1]) / unit),
             I3 = round(parse_scalar<quad>(tip3p_moments_text[2]) / unit);
  BOOST_TEST((I3 == I1 + I2));
}

BOOST_AUTO_TEST_SUITE_END()  // liquid_water_test
