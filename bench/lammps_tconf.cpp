// The configurational temperature of rigid TIP3P configurations that LAMMPS wrote (not a test).
// LAMMPS 29 Sep 2021 has no compute for it with rigid bodies; rotlie evaluates the same pair style,
// lj/cut/coul/dsf (water_interaction::lammps_dsf), on each frame of a dump and probes the Laplacians
// (configurational_temperature.hpp): T_conf,trans = ⟨Σ|F|²⟩ / ⟨∇²_q V⟩ / k_B over the centres of
// mass, T_conf,rot = ⟨Σ|τ|²⟩ / ⟨Σ_k X_k² V⟩ / k_B over the bodies' rotations.
//
//   lammps_tconf [options] DUMP...
//
// Each DUMP is a LAMMPS `dump custom` of all atoms with the columns id, type and positions (x y z
// with or without ix iy iz, or xu yu zu), optionally one per-atom energy column (c_NAME of `compute
// pe/atom`), any number of frames, for example
//   compute pa all pe/atom
//   dump d all custom 50 run.dump id type xu yu zu c_pa
//   dump_modify d sort id format float %.17g
// The atoms are the molecules of examples/lammps/tip3p.mol: molecule i has atoms 3i+1 (O, type 1),
// 3i+2 and 3i+3 (H, type 2). Each molecule becomes a rigid body: its centre of mass (masses below),
// and the attitude Q whose body axes are rotlie's for water (0 along H→H, 1 the bisector from O to
// the H's, 2 the normal); the body's sites are the mean O–H and H–H distances of the first frame,
// and every site of every frame must sit within 1e-6 Å of its rebuilt position. Sites are put
// next to their oxygen by the minimum image, so wrapped positions serve as well.
//
// Options (defaults: the LAMMPS input of lammps/bench/thermostat_sweep.py --dsf):
//   --cutoff RC (9)  --alpha A (0.2)        pair_style lj/cut/coul/dsf A RC, pair_modify shift yes
//   --epsilon E (0.1521)  --sigma S (3.1507) pair_coeff 1 1 E S (O–O only)
//   --charge-H Q (0.417)                    O carries −2Q
//   --mass-O M (15.9994)  --mass-H M (1.008)
//   --blocks B (10)                         standard errors from B blocks of consecutive frames
//   --probes K (1)                          Hutchinson probes per frame and kind
//   --skip K (0)                            frames dropped at the start of each file
//   --seed S (1)                            the probes' random directions
//   --tolerance T (1e-6)                    largest |V_rotlie − V_LAMMPS| / |V_LAMMPS| allowed
// With a per-atom energy column, V (the sum of the column: LAMMPS's pe) is checked frame by frame
// against rotlie's and the program stops with status 2 on a disagreement beyond --tolerance (the
// mapping or the parameters are not LAMMPS's). The box must be cubic and longer than 2 RC.
//
// Output, one line per file after a `#` header: file, frames, molecules, V per molecule and its
// standard error (kcal/mol), T_conf,trans ± error, T_conf,rot ± error (K), the largest relative
// difference of V to LAMMPS's (nan without the energy column), the largest site misfit (Å).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "rotlie/models/ensemble_statistics.hpp"
#include "rotlie/models/configurational_temperature.hpp"
#include "rotlie/models/real_units.hpp"
#include "rotlie/models/scenes/liquid_water.hpp"

using namespace rotlie::models;

namespace {

struct settings {
  double cutoff = 9, alpha = 0.2, epsilon = 0.1521, sigma = 3.1507, charge_H = 0.417, mass_O = 15.9994, mass_H = 1.008;
  int blocks = 10, probes = 1, skip = 0;
  unsigned long seed = 1;
  double tolerance = 1e-6;
};

struct frame {
  long step = 0;
  double box = 0;
  std::vector<vec3<double>> x;  ///< by atom id − 1
  std::vector<int> type;
  double energy = NAN;  ///< Σ of the per-atom energy column, NaN without one
};

/// Reads the next frame of a dump custom file; false at the end.
bool read_frame(std::istream& in, frame& f, const std::string& name) {
  std::string line;
  while (std::getline(in, line) && line.rfind("ITEM: TIMESTEP", 0) != 0) {
  }
  if (!in) return false;
  std::getline(in, line);
  f.step = std::stol(line);
  long atoms = 0;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  while (std::getline(in, line)) {
    if (line.rfind("ITEM: NUMBER OF ATOMS", 0) == 0) {
      std::getline(in, line);
      atoms = std::stol(line);
    } else if (line.rfind("ITEM: BOX BOUNDS", 0) == 0) {
      if (line.find("xy") != std::string::npos) throw std::runtime_error(name + ": a triclinic box");
      for (int d = 0; d < 3; ++d) {
        std::getline(in, line);
        std::istringstream r(line);
        r >> lo[d] >> hi[d];
      }
    } else if (line.rfind("ITEM: ATOMS", 0) == 0) {
      break;
    }
  }
  if (!in || atoms <= 0) throw std::runtime_error(name + ": a frame without atoms at step " + std::to_string(f.step));
  std::istringstream head(line.substr(std::string("ITEM: ATOMS").size()));
  std::vector<std::string> columns;
  for (std::string c; head >> c;) columns.push_back(c);
  auto column = [&](const std::vector<std::string>& names) {
    for (const auto& n : names) {
      const auto it = std::find(columns.begin(), columns.end(), n);
      if (it != columns.end()) return static_cast<int>(it - columns.begin());
    }
    return -1;
  };
  const int id = column({"id"}), type = column({"type"}), ix = column({"ix"}), iy = column({"iy"}), iz = column({"iz"});
  int x = column({"xu"}), y = column({"yu"}), z = column({"zu"});
  const bool unwrapped = x >= 0;
  if (!unwrapped) x = column({"x"}), y = column({"y"}), z = column({"z"});
  int energy = -1;
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c].rfind("c_", 0) == 0) energy = static_cast<int>(c);
  if (id < 0 || type < 0 || x < 0 || y < 0 || z < 0) throw std::runtime_error(name + ": need the columns id, type and x y z (or xu yu zu)");
  const bool images = !unwrapped && ix >= 0 && iy >= 0 && iz >= 0;
  f.box = hi[0] - lo[0];
  for (int d = 1; d < 3; ++d)
    if (std::abs((hi[d] - lo[d]) - f.box) > 1e-9 * f.box) throw std::runtime_error(name + ": the box is not cubic");
  f.x.assign(static_cast<std::size_t>(atoms), vec3<double>{NAN, NAN, NAN});
  f.type.assign(static_cast<std::size_t>(atoms), 0);
  f.energy = energy >= 0 ? 0.0 : NAN;
  std::vector<std::string> w(columns.size());
  for (long k = 0; k < atoms; ++k) {
    if (!std::getline(in, line)) throw std::runtime_error(name + ": a truncated frame at step " + std::to_string(f.step));
    std::istringstream r(line);
    for (auto& s : w) r >> s;
    if (!r) throw std::runtime_error(name + ": a short atom line at step " + std::to_string(f.step));
    const long a = std::stol(w[static_cast<std::size_t>(id)]);
    if (a < 1 || a > atoms) throw std::runtime_error(name + ": atom id " + std::to_string(a) + " out of 1 … " + std::to_string(atoms));
    auto& p = f.x[static_cast<std::size_t>(a - 1)];
    p = {std::stod(w[static_cast<std::size_t>(x)]), std::stod(w[static_cast<std::size_t>(y)]), std::stod(w[static_cast<std::size_t>(z)])};
    if (images) {
      const int image[3] = {ix, iy, iz};
      for (int d = 0; d < 3; ++d) p[d] += f.box * std::stod(w[static_cast<std::size_t>(image[d])]);
    }
    f.type[static_cast<std::size_t>(a - 1)] = std::stoi(w[static_cast<std::size_t>(type)]);
    if (energy >= 0) f.energy += std::stod(w[static_cast<std::size_t>(energy)]);
  }
  for (const auto& p : f.x)
    if (std::isnan(p[0])) throw std::runtime_error(name + ": an atom missing at step " + std::to_string(f.step));
  return true;
}

vec3<double> minus(const vec3<double>& a, const vec3<double>& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double norm(const vec3<double>& a) { return std::sqrt(dot(a, a)); }
vec3<double> scaled(const vec3<double>& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }

/// The three sites of molecule i, the hydrogens moved to their oxygen's nearest image.
std::array<vec3<double>, 3> molecule_sites(const frame& f, std::size_t i) {
  std::array<vec3<double>, 3> s{f.x[3 * i], f.x[3 * i + 1], f.x[3 * i + 2]};
  for (int a = 1; a < 3; ++a)
    for (int d = 0; d < 3; ++d) s[static_cast<std::size_t>(a)][d] -= f.box * std::nearbyint((s[static_cast<std::size_t>(a)][d] - s[0][d]) / f.box);
  return s;
}

/// TIP3P as the LAMMPS input has it, the geometry measured: mean O–H and H–H distances.
water_model<double> lammps_tip3p(const settings& o, const frame& f) {
  const std::size_t n = f.x.size() / 3;
  double oh = 0, hh = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto s = molecule_sites(f, i);
    oh += (norm(minus(s[1], s[0])) + norm(minus(s[2], s[0]))) / (2.0 * static_cast<double>(n));
    hh += norm(minus(s[2], s[1])) / static_cast<double>(n);
  }
  water_model<double> w;
  w.name = "TIP3P (LAMMPS input)";
  w.mass_O = o.mass_O, w.mass_H = o.mass_H, w.mass = o.mass_O + 2 * o.mass_H;
  w.charge = {-2 * o.charge_H, o.charge_H, o.charge_H};
  w.sigma = o.sigma, w.epsilon = o.epsilon;
  const double x = hh / 2, y = std::sqrt(oh * oh - x * x), y_com = 2 * w.mass_H * y / w.mass;
  w.site = {vec3<double>{0, -y_com, 0}, vec3<double>{-x, y - y_com, 0}, vec3<double>{x, y - y_com, 0}};
  const std::array<double, 3> m{w.mass_O, w.mass_H, w.mass_H};
  w.moments = {};
  for (int a = 0; a < 3; ++a) {
    w.moments[0] += m[static_cast<std::size_t>(a)] * w.site[static_cast<std::size_t>(a)][1] * w.site[static_cast<std::size_t>(a)][1];
    w.moments[1] += m[static_cast<std::size_t>(a)] * w.site[static_cast<std::size_t>(a)][0] * w.site[static_cast<std::size_t>(a)][0];
  }
  w.moments[2] = w.moments[0] + w.moments[1];
  w.site_radius = 0;
  for (const auto& s : w.site) w.site_radius = std::max(w.site_radius, norm(s));
  return w;
}

/// Each molecule's centre of mass and attitude; returns the largest misfit of a site (Å).
double rebuild_bodies(const frame& f, const water_model<double>& w, std::vector<rigid_body_state<double>>& bodies) {
  const std::size_t n = f.x.size() / 3;
  bodies.resize(n);
  double misfit = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (f.type[3 * i] != 1 || f.type[3 * i + 1] != 2 || f.type[3 * i + 2] != 2)
      throw std::runtime_error("molecule " + std::to_string(i + 1) + " is not O, H, H (types 1, 2, 2) at atoms 3i+1 … 3i+3");
    const auto s = molecule_sites(f, i);
    vec3<double> c{};
    for (int d = 0; d < 3; ++d) c[d] = (w.mass_O * s[0][d] + w.mass_H * (s[1][d] + s[2][d])) / w.mass;
    // body axis 0 along H1 → H2, axis 1 along the bisector from O to the H's, axis 2 = 0 × 1
    vec3<double> e0 = minus(s[2], s[1]);
    e0 = scaled(e0, 1 / norm(e0));
    vec3<double> e1 = minus(scaled({s[1][0] + s[2][0], s[1][1] + s[2][1], s[1][2] + s[2][2]}, 0.5), s[0]);
    e1 = minus(e1, scaled(e0, dot(e0, e1)));
    e1 = scaled(e1, 1 / norm(e1));
    const vec3<double> e2 = cross(e0, e1);
    auto& b = bodies[i];
    b.q = c;
    b.p = {};
    b.rot.G = {};
    for (int r = 0; r < 3; ++r) b.rot.Q(r, 0) = e0[r], b.rot.Q(r, 1) = e1[r], b.rot.Q(r, 2) = e2[r];
    for (int a = 0; a < 3; ++a) {
      const vec3<double> fit = b.rot.Q * w.site[static_cast<std::size_t>(a)];
      misfit = std::max(misfit, norm(minus(minus(s[static_cast<std::size_t>(a)], c), fit)));
    }
  }
  return misfit;
}

struct file_result {
  long frames = 0;
  std::size_t molecules = 0;
  mean_error v, t_trans, t_rot;
  double worst_relative = NAN, misfit = 0;
};

file_result analyse(const std::string& name, const settings& o) {
  std::ifstream in(name);
  if (!in) throw std::runtime_error("cannot read " + name);
  std::vector<frame> frames;
  for (frame f; read_frame(in, f, name);) frames.push_back(std::move(f));
  if (static_cast<long>(frames.size()) <= o.skip) throw std::runtime_error(name + ": no frame left after --skip");
  frames.erase(frames.begin(), frames.begin() + o.skip);
  if (frames[0].x.size() % 3 != 0) throw std::runtime_error(name + ": the atom count is not a multiple of 3");
  const water_model<double> model = lammps_tip3p(o, frames[0]);
  liquid_water_options<double> lo;
  lo.box = frames[0].box;
  lo.cutoff = o.cutoff;
  lo.dsf_alpha = o.alpha;
  lo.interaction = water_interaction::lammps_dsf;
  const liquid_water<double> water(model, lo);
  const double k_B = real_units::boltz<double>();
  file_result r;
  r.frames = static_cast<long>(frames.size());
  r.molecules = frames[0].x.size() / 3;
  const int blocks = static_cast<int>(std::min<long>(o.blocks, r.frames));
  std::vector<double> v(static_cast<std::size_t>(blocks)), f2(v.size()), t2(v.size()), lt(v.size()), lr(v.size());
  std::vector<long> in_block(v.size(), 0);
  seeded_random random(o.seed, 0);
  std::vector<rigid_body_state<double>> bodies, scratch;
  std::vector<vec3<double>> force, torque;
  for (long k = 0; k < r.frames; ++k) {
    const frame& f = frames[static_cast<std::size_t>(k)];
    if (std::abs(f.box - lo.box) > 1e-9 * lo.box) throw std::runtime_error(name + ": the box changes (constant volume only)");
    if (f.x.size() != 3 * r.molecules) throw std::runtime_error(name + ": the atom count changes");
    r.misfit = std::max(r.misfit, rebuild_bodies(f, model, bodies));
    force.resize(bodies.size());
    torque.resize(bodies.size());
    const double V = water.evaluate(bodies, force, torque);
    if (!std::isnan(f.energy)) {
      const double rel = std::abs(V - f.energy) / std::abs(f.energy);
      r.worst_relative = std::isnan(r.worst_relative) ? rel : std::max(r.worst_relative, rel);
      if (!(rel <= o.tolerance)) {
        std::fprintf(stderr, "lammps_tconf: %s step %ld: V = %.12g (rotlie) against %.12g (LAMMPS), relative %.3g > %.3g: the mapping or the parameters differ\n",
                     name.c_str(), f.step, V, f.energy, rel, o.tolerance);
        std::exit(2);
      }
    }
    const auto b = static_cast<std::size_t>(k * blocks / r.frames);
    v[b] += V / static_cast<double>(r.molecules);
    for (int p = 0; p < o.probes; ++p) {
      const auto c = probe_configurational(water, bodies, force, torque, random, scratch);
      f2[b] += c.force_squared, t2[b] += c.torque_squared, lt[b] += c.translation_laplacian, lr[b] += c.rotation_laplacian;
    }
    ++in_block[b];
  }
  if (r.misfit > 1e-6) throw std::runtime_error(name + ": a site lies " + std::to_string(r.misfit) + " Å from its rigid body (not rigid TIP3P?)");
  std::vector<double> vb, ct, cr;
  double F2 = 0, T2 = 0, LT = 0, LR = 0;
  for (std::size_t b = 0; b < v.size(); ++b) {
    if (in_block[b] == 0) continue;
    vb.push_back(v[b] / static_cast<double>(in_block[b]));
    ct.push_back(f2[b] / lt[b] / k_B), cr.push_back(t2[b] / lr[b] / k_B);
    F2 += f2[b], T2 += t2[b], LT += lt[b], LR += lr[b];
  }
  r.v = ensemble_mean(vb);
  r.t_trans = {F2 / LT / k_B, ensemble_mean(ct).error};
  r.t_rot = {T2 / LR / k_B, ensemble_mean(cr).error};
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  settings o;
  std::vector<std::string> files;
  try {
    for (int k = 1; k < argc; ++k) {
      const std::string a = argv[k];
      auto value = [&]() -> std::string {
        if (k + 1 >= argc) throw std::invalid_argument(a + " needs a value");
        return argv[++k];
      };
      if (a == "--cutoff") o.cutoff = std::stod(value());
      else if (a == "--alpha") o.alpha = std::stod(value());
      else if (a == "--epsilon") o.epsilon = std::stod(value());
      else if (a == "--sigma") o.sigma = std::stod(value());
      else if (a == "--charge-H") o.charge_H = std::stod(value());
      else if (a == "--mass-O") o.mass_O = std::stod(value());
      else if (a == "--mass-H") o.mass_H = std::stod(value());
      else if (a == "--blocks") o.blocks = std::stoi(value());
      else if (a == "--probes") o.probes = std::stoi(value());
      else if (a == "--skip") o.skip = std::stoi(value());
      else if (a == "--seed") o.seed = std::stoul(value());
      else if (a == "--tolerance") o.tolerance = std::stod(value());
      else if (a == "-h" || a == "--help") {
        std::printf("usage: lammps_tconf [--cutoff RC] [--alpha A] [--epsilon E] [--sigma S] [--charge-H Q] [--mass-O M] [--mass-H M]\n"
                    "                    [--blocks B] [--probes K] [--skip K] [--seed S] [--tolerance T] DUMP...\n"
                    "(see the comment at the top of bench/lammps_tconf.cpp)\n");
        return 0;
      } else if (a.rfind("--", 0) == 0) throw std::invalid_argument("unknown option " + a);
      else files.push_back(a);
    }
    if (files.empty()) throw std::invalid_argument("no dump file given (--help)");
    if (o.blocks < 2 || o.probes < 1 || o.skip < 0) throw std::invalid_argument("need --blocks ≥ 2, --probes ≥ 1, --skip ≥ 0");
    std::printf("# file frames molecules V_per_molecule V_err T_conf_trans T_conf_trans_err T_conf_rot T_conf_rot_err V_rel_diff_lammps site_misfit\n");
    for (const auto& name : files) {
      const auto r = analyse(name, o);
      std::printf("%s %ld %zu %.8f %.8f %.4f %.4f %.4f %.4f %.3g %.3g\n", name.c_str(), r.frames, r.molecules, r.v.mean, r.v.error, r.t_trans.mean,
                  r.t_trans.error, r.t_rot.mean, r.t_rot.error, r.worst_relative, r.misfit);
      std::fflush(stdout);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lammps_tconf: %s\n", e.what());
    return 1;
  }
  return 0;
}
