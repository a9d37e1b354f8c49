// SPDX-License-Identifier: GPL-2.0-or-later
#include "fix_rigid_sier_small.h"

#include <mpi.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <exception>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "lammps_frame.hpp"
#include "math_extra.h"
#include "modify.h"
#include "mid_step_forces.h"
#include "rigid_const.h"
#include "rotlie/models/composition.hpp"
#include "rotlie/models/exact_free_rotation_batch.hpp"
#include "rotlie/runs/methods.hpp"
#include "rotlie/schemes/reference_schemes.hpp"
#include "rotlie/schemes/thermostat_tables.hpp"
#include "update.h"
#include "utils.h"

namespace rotlie::lammps {

using namespace LAMMPS_NS;

namespace {

// "rigid/sier2/nvt/small" → "rigid/sier2/small": the integrator family's style
std::string family_style_of(const std::string& style) {
  const std::string nvt = "/nvt/small";
  if (style.size() > nvt.size() && style.compare(style.size() - nvt.size(), nvt.size(), nvt) == 0)
    return style.substr(0, style.size() - nvt.size()) + "/small";
  return style;
}

}  // namespace

std::string nvt_style_of(const std::string& style) {
  const std::string small = "/small";
  if (style.size() <= small.size() || style.compare(style.size() - small.size(), small.size(), small) != 0) return style + "/nvt";
  return style.substr(0, style.size() - small.size()) + "/nvt/small";
}

struct FixRigidSierSmall::arguments {
  std::vector<std::string> words;
  std::string rotor = "exact";
  thermostat_settings thermostat;
  std::vector<char*> argv;

  arguments(LAMMPS* lmp, int narg, char** arg) {
    const std::string style = narg > 2 ? arg[2] : "rigid/sier/small";
    const std::string family = family_style_of(style), nvt = nvt_style_of(family);
    const bool chains = style != family;  // rigid/NAME/nvt/small
    const std::string fix = "Fix " + style + ": ";
    auto refuse = [&](const std::string& why) { lmp->error->all(FLERR, fix + why); };
    // the barostat keywords of rigid/npt/small and rigid/nph/small
    static const std::set<std::string> barostat = {"iso", "aniso", "x", "y", "z", "couple", "pchain", "dilate", "press", "ptemp"};
    static const std::set<std::string> with_value = {"infile", "reinit", "mol", "gravity"};
    int first = std::min(narg, 4);
    if (narg > 3 && std::strcmp(arg[3], "custom") == 0) first = std::min(narg, 5);
    for (int i = 0; i < first; ++i) words.emplace_back(arg[i]);
    // the values of keyword `key` at arg[i + 1 …]: `count` of them, named in `names`
    auto values = [&](int i, int count, const std::string& key, const std::string& names) {
      if (i + count >= narg)
        refuse(key + " needs " + std::to_string(count) + " values: " + names + " (" + std::to_string(narg - i - 1) + " given)");
    };
    auto positive = [&](const char* text, const std::string& what) {
      char* end = nullptr;
      const double x = std::strtod(text, &end);
      if (end == text || *end != '\0' || !(x > 0) || !std::isfinite(x)) refuse(what + " must be a number > 0, not '" + text + "'");
      return x;
    };
    auto integer = [&](const char* text, const std::string& what, long low, long high) {
      char* end = nullptr;
      errno = 0;
      const long n = std::strtol(text, &end, 10);
      if (end == text || *end != '\0' || errno == ERANGE || n < low || n > high)
        refuse(what + " must be an integer " + std::to_string(low) + " to " + std::to_string(high) + ", not '" + text + "'");
      return n;
    };
    bool tparam = false;
    for (int i = first; i < narg; ++i) {
      const std::string w = arg[i];
      if (w == "rotor") {
        if (i + 1 >= narg) refuse("rotor needs a value (" + rotor_values_help() + ")");
        rotor = arg[++i];
      } else if (w == "langevin") {
        if (chains)
          refuse("keyword 'langevin' is " + family + "'s (the Langevin O-step); " + style +
                 " thermostats by Nose-Hoover chains (temp Tstart Tstop Tdamp): use one or the other style");
        values(i, 4, w, "Tstart Tstop Tperiod seed");
        thermostat.what = thermostat_settings::kind::langevin;
        thermostat.t_start = positive(arg[i + 1], "langevin Tstart");
        thermostat.t_stop = positive(arg[i + 2], "langevin Tstop");
        thermostat.period = positive(arg[i + 3], "langevin Tperiod");
        thermostat.seed = static_cast<std::uint64_t>(integer(arg[i + 4], "langevin seed", 1, 2147483647L));
        i += 4;
      } else if (w == "temp" || w == "tparam") {
        if (!chains)
          refuse("keyword '" + w + "' is " + nvt + "'s (Nose-Hoover chains); " + style +
                 " takes langevin Tstart Tstop Tperiod seed, or integrates at constant energy without it");
        if (w == "temp") {
          values(i, 3, w, "Tstart Tstop Tdamp");
          thermostat.what = thermostat_settings::kind::chain;
          thermostat.t_start = positive(arg[i + 1], "temp Tstart");
          thermostat.t_stop = positive(arg[i + 2], "temp Tstop");
          thermostat.period = positive(arg[i + 3], "temp Tdamp");
          i += 3;
        } else {
          values(i, 3, w, "Tchain Titer Torder");
          thermostat.chain_length = static_cast<int>(integer(arg[i + 1], "tparam Tchain", 1, 100));
          thermostat.iterations = static_cast<int>(integer(arg[i + 2], "tparam Titer", 1, 100));
          thermostat.order = static_cast<int>(integer(arg[i + 3], "tparam Torder", 3, 5));
          if (thermostat.order == 4) refuse("tparam Torder must be 3 or 5 (Suzuki-Yoshida), not '4'");
          tparam = true;
          i += 3;
        }
      } else if (barostat.count(w)) {
        refuse("keyword '" + w + "' is a barostat's: a barostat around SIER's free flights is not implemented; use fix rigid/npt/small or rigid/nph/small");
      } else if (with_value.count(w) && i + 1 < narg) {
        words.push_back(w);
        words.emplace_back(arg[++i]);
      } else {
        words.push_back(w);  // fix rigid/small names what it does not know
      }
    }
    if (chains && thermostat.what != thermostat_settings::kind::chain)
      refuse("temp Tstart Tstop Tdamp is required (the chains' target temperature and period)" +
             std::string(tparam ? "; tparam alone sets only the chains' shape" : ""));
    for (auto& w : words) argv.push_back(w.data());
  }
};

FixRigidSierSmall::FixRigidSierSmall(LAMMPS* lmp, int narg, char** arg) : FixRigidSierSmall(lmp, arguments(lmp, narg, arg)) {}

FixRigidSierSmall::FixRigidSierSmall(LAMMPS* lmp, arguments&& args)
    : FixRigidSmall(lmp, static_cast<int>(args.argv.size()), args.argv.data()), thermostat_(args.thermostat) {
  try {
    const auto* family = runs::lammps_style_family(family_style_of(style));
    if (!family) throw std::invalid_argument("no integrator family has this style");
    tv_table_ = family->tv_table;
    rotors_ = std::make_unique<body_rotors>(parse_rotor(args.rotor));
    auto table = schemes::reference_scheme(tv_table_);
    if (!table) throw std::invalid_argument("no TV table " + tv_table_);
    // V T V … V with thermostat letters: a kick first and last, the forces of the step's start and end
    // (first same as last)
    if (thermostat_.what == thermostat_settings::kind::langevin)
      table = schemes::thermostatted_table(*table, schemes::thermostat_placement::middle);
    else if (thermostat_.what == thermostat_settings::kind::chain)
      table = schemes::thermostatted_table(*table, schemes::thermostat_placement::chain);
    table_name_ = table->name;
    force_evaluations_ = schemes::force_evaluations(*table);
    const auto& st = table->stages;
    bool first_kick = false;
    for (std::size_t k = 0; k < st.size(); ++k) {
      const char part = st[k].part;
      if (part != 'V' && part != 'T' && !schemes::is_thermostat_letter(part))
        throw std::invalid_argument(table_name_ + " has a stage " + std::string(1, part) + ": not a TV table");
      if (part == 'T' && !first_kick) throw std::invalid_argument(table_name_ + " moves before its first kick: not V T ... V");
      if (part == 'V') first_kick = true, last_kick_ = k;
      stages_.push_back({part, models::parse_scalar<double>(st[k].value), part == 'O' ? o_stages_++ : -1});
    }
    for (std::size_t k = last_kick_; k < st.size(); ++k)
      if (st[k].part == 'T') throw std::invalid_argument(table_name_ + " moves after its last kick: not V T ... V");
  } catch (const std::exception& e) {
    error->all(FLERR, "Fix " + std::string(style) + ": " + e.what());
  }
  if (thermostat_.what == thermostat_settings::kind::chain) {
    // the chains' energy, the share of the conserved quantity etotal + f_ID (thermo's ecouple, econserve)
    scalar_flag = 1;
    extscalar = 1;
    global_freq = 1;
    ecouple_flag = 1;
    restart_global = 1;
  } else if (thermostat_.what == thermostat_settings::kind::langevin) {
    vector_flag = 1;
    size_vector = 2;
    extvector = 0;
    global_freq = 1;
  }
  if (comm->me == 0) {
    std::string line = "  " + std::string(style) + ": " + table_name_ + ", " + std::to_string(force_evaluations_) +
                       " force evaluations per step, rotor " + args.rotor;
    char text[200];
    if (thermostat_.what == thermostat_settings::kind::langevin) {
      std::snprintf(text, sizeof text, "; Langevin O-step: %g to %g over each run, damping period %g (friction %g per time unit), seed %llu",
                    thermostat_.t_start, thermostat_.t_stop, thermostat_.period, 1 / thermostat_.period,
                    static_cast<unsigned long long>(thermostat_.seed));
      line += text;
    } else if (thermostat_.what == thermostat_settings::kind::chain) {
      std::snprintf(text, sizeof text, "; Nose-Hoover chains (translations, rotations): %g to %g over each run, Tdamp %g, length %d, %d iteration(s), order %d",
                    thermostat_.t_start, thermostat_.t_stop, thermostat_.period, thermostat_.chain_length, thermostat_.iterations,
                    thermostat_.order);
      line += text;
    }
    utils::logmesg(lmp, line + "\n");
  }
}

FixRigidSierSmall::~FixRigidSierSmall() = default;

int FixRigidSierSmall::setmask() {
  return FixRigidSmall::setmask() & ~(FixConst::INITIAL_INTEGRATE_RESPA | FixConst::FINAL_INTEGRATE_RESPA);
}

void FixRigidSierSmall::init() {
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Fix " + std::string(style) + " does not support run_style respa");
  // SIER4's inner force evaluations see only what this fix moves: another fix that integrates atoms
  // (fix nve on free atoms, a second rigid fix) would move them by whole steps between them and the
  // composition would lose its order (seen: LAMMPS's rigid/in.rigid.tnr, rods with fix nve on their
  // tethers, 1000× the energy error of rigid/nve/small). SIER2 (V T V) is LAMMPS's own step layout.
  if (force_evaluations_ > 1)
    for (int i = 0; i < modify->nfix; ++i)
      if (modify->fix[i] != this && modify->fix[i]->time_integrate)
        error->all(FLERR, "Fix " + std::string(style) + ": fix " + modify->fix[i]->id + " (" + modify->fix[i]->style +
                              ") also integrates atoms; the inner force evaluations of a step need every moving atom in this fix's stages "
                              "(use rigid/sier2/small, or put every moving atom in a body of this fix)");
  FixRigidSmall::init();
}

void FixRigidSierSmall::setup(int vflag) {
  FixRigidSmall::setup(vflag);
  resolve_shapes();
  if (thermostat_.what == thermostat_settings::kind::chain) {
    chains_ = {};  // built anew at this run's target (their masses), their state kept
    count_and_build_chains();
  }
}

void FixRigidSierSmall::resolve_shapes() {
  // each rank's distinct shapes with a body ID, gathered on every rank in rank order, so that every
  // rank resolves the same list and a refusal is one collective error
  std::vector<double> mine;
  std::vector<std::array<double, 3>> seen;
  bool all_known = true;
  for (int ibody = 0; ibody < nlocal_body; ++ibody) {
    const Body& b = body[ibody];
    const auto I = rotlie_moments(b.inertia);
    if (!rotors_->shape_of(I)) all_known = false;
    if (std::any_of(seen.begin(), seen.end(), [&](const auto& s) { return same_shape(s, I); })) continue;
    seen.push_back(I);
    mine.insert(mine.end(), {I[0], I[1], I[2], static_cast<double>(atom->tag[b.ilocal])});
  }
  int unknown = (all_known && shapes_resolved_) ? 0 : 1, any_unknown = 0;
  MPI_Allreduce(&unknown, &any_unknown, 1, MPI_INT, MPI_MAX, world);
  if (!any_unknown) return;
  int count = static_cast<int>(mine.size());
  std::vector<int> counts(static_cast<std::size_t>(comm->nprocs)), offsets(counts.size());
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  int total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) offsets[r] = total, total += counts[r];
  std::vector<double> all(static_cast<std::size_t>(total));
  MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, world);
  std::vector<std::pair<std::array<double, 3>, long>> bodies;
  for (std::size_t k = 0; k + 3 < all.size(); k += 4) bodies.push_back({{all[k], all[k + 1], all[k + 2]}, static_cast<long>(all[k + 3])});
  const double start = MPI_Wtime();
  rotors_->set_planar(domain->dimension == 2);
  const auto mine_to_resolve = [&](std::size_t k) { return static_cast<int>(k % comm->nprocs) == comm->me; };
  const auto progress = [&](const std::string& line) {
    if (comm->me == 0)
      utils::logmesg(lmp, "  " + std::string(style) + ": " + line +
                              (comm->nprocs > 1 ? ", shared among " + std::to_string(comm->nprocs) + " ranks" : "") + "\n");
  };
  try {
    body_rotor_.clear();  // the rotors and shapes they point to are rebuilt
    body_moments_.clear();
    body_key_.clear();
    rotors_->resolve_shapes(bodies, {mine_to_resolve, [&](std::vector<std::string>& texts) { share_texts(texts); }}, progress);
  } catch (const std::exception& e) {
    error->all(FLERR, "Fix " + std::string(style) + ": " + e.what());
  }
  shapes_resolved_ = true;
  if (comm->me == 0) print_shapes(MPI_Wtime() - start);
}

void FixRigidSierSmall::share_texts(std::vector<std::string>& texts) {
  // shape k was resolved by rank k % nprocs: every rank gets its text from there
  for (std::size_t k = 0; k < texts.size(); ++k) {
    const int owner = static_cast<int>(k % comm->nprocs);
    long size = static_cast<long>(texts[k].size());
    MPI_Bcast(&size, 1, MPI_LONG, owner, world);
    texts[k].resize(static_cast<std::size_t>(size));
    MPI_Bcast(texts[k].data(), static_cast<int>(size), MPI_CHAR, owner, world);
  }
}

void FixRigidSierSmall::print_shapes(double seconds) const {
  // each shape with its rotor, the first few of many (the 2-d micelle has 150), then the others counted
  constexpr std::size_t listed = 10;
  const auto& shapes = rotors_->shapes();
  std::map<std::string, int> rest;
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    const auto& s = shapes[k];
    const std::string rotor = !(s.moments[0] > 0) ? "exact (linear body)" : s.table_name;
    if (k >= listed) {
      ++rest[rotor];
      continue;
    }
    char text[160];
    std::snprintf(text, sizeof text, "  %s: body shape (%.8g, %.8g, %.8g) (body %ld): rotor %s\n", style, s.moments[0], s.moments[1],
                  s.moments[2], s.first_body, rotor.c_str());
    utils::logmesg(lmp, text);
  }
  if (!rest.empty()) {
    std::string line = "  " + std::string(style) + ": and " + std::to_string(shapes.size() - listed) + " more, rotors:";
    for (const auto& [rotor, n] : rest) line += " " + rotor + " (" + std::to_string(n) + ")";
    utils::logmesg(lmp, line + "\n");
  }
  if (const auto note = rotors_->fallback_note(); !note.empty()) utils::logmesg(lmp, "  " + std::string(style) + ": " + note + "\n");
  if (rotors_->request().what == rotor_request::kind::automatic) {
    char text[120];
    std::snprintf(text, sizeof text, "  %s: rotor auto: %s resolved in %.1f s\n", style, body_shapes_text(shapes.size()).c_str(), seconds);
    utils::logmesg(lmp, text);
  }
}

void FixRigidSierSmall::note_new_shapes() {
  // one line per shape met by this rank: rank 0 writes LAMMPS's screen and log; the others, which
  // have neither, standard error
  for (const auto& s : rotors_->take_new_shapes()) {
    char text[240];
    std::snprintf(text, sizeof text,
                  "  %s: body %ld with moments (%.8g, %.8g, %.8g), a shape that appeared during the run, runs the exact rotor\n", style,
                  s.first_body, s.moments[0], s.moments[1], s.moments[2]);
    if (comm->me == 0) utils::logmesg(lmp, text);
    else std::fputs(text, stderr);
  }
}

void FixRigidSierSmall::kick(double c) {
  const double k = c * update->dt * force->ftm2v;
  for (int ibody = 0; ibody < nlocal_body; ++ibody) {
    Body* b = &body[ibody];
    const double dtfm = k / b->mass;
    for (int i = 0; i < 3; ++i) {
      b->vcm[i] += dtfm * b->fcm[i];
      b->angmom[i] += k * b->torque[i];
    }
    MathExtra::angmom_to_omega(b->angmom, b->ex_space, b->ey_space, b->ez_space, b->inertia, b->omega);
  }
}

namespace {

// A steady rotation: L on a principal axis to rounding (the other two body components of L within
// 16ε of |L|; every body of a 2-d system, whose L is along z). Then w ← the angular velocity
// L_k/I_k e_k about that axis, the exact free rotation (the general closed form would refine the
// rounding of the off-axis components in float128 instead).
bool steady(const double* L, const double* const e[3], const double* inertia, double* w) {
  double G[3], gg = 0;
  int k = 0;
  for (int i = 0; i < 3; ++i) {
    G[i] = L[0] * e[i][0] + L[1] * e[i][1] + L[2] * e[i][2];
    gg += G[i] * G[i];
    if (std::abs(G[i]) > std::abs(G[k])) k = i;
  }
  const double off = gg - G[k] * G[k];
  constexpr double tol = 16 * std::numeric_limits<double>::epsilon();
  if (!(inertia[k] > 0) || !(off <= tol * tol * gg)) return false;
  for (int i = 0; i < 3; ++i) w[i] = G[k] / inertia[k] * e[k][i];
  return true;
}

}  // namespace

void FixRigidSierSmall::free_flight(double c) {
  const double t = c * update->dt;
  // Linear and steady bodies and those of a table's rotor turn here, one by one; the exact rotor's
  // bodies are gathered by shape (a counting sort) and each shape's advanced at once, vectorised across
  // them, each body with its own moments (LAMMPS computes them from its atoms: they differ in the last
  // digits among the molecules of one shape).
  const auto bodies = static_cast<std::size_t>(nlocal_body);
  flight_group_of_.clear();
  flight_count_.clear();
  flight_group_.assign(bodies, -1);
  body_rotor_.resize(bodies, nullptr);
  body_moments_.resize(bodies);
  body_key_.resize(bodies, nullptr);
  models::body_state<double> s;
  for (int ibody = 0; ibody < nlocal_body; ++ibody) {
    Body* b = &body[ibody];
    for (int i = 0; i < 3; ++i) b->xcm[i] += t * b->vcm[i];
    const double* axes[3] = {b->ex_space, b->ey_space, b->ez_space};
    double w[3];
    if (!(b->inertia[2] > 0)) {
      // a linear body: its free rotation is the uniform rotation about its angular velocity
      MathExtra::angmom_to_omega(b->angmom, b->ex_space, b->ey_space, b->ez_space, b->inertia, b->omega);
      rotate_about(b->omega, t, b->ex_space, b->ey_space, b->ez_space);
      continue;
    }
    if (steady(b->angmom, axes, b->inertia, w)) {
      rotate_about(w, t, b->ex_space, b->ey_space, b->ez_space);
      continue;
    }
    const auto moments = rotlie_moments(b->inertia);
    const auto slot = static_cast<std::size_t>(ibody);
    if (!body_rotor_[slot] || body_moments_[slot] != moments) {
      try {
        body_rotor_[slot] = &rotors_->rotor_for(moments, atom->tag[b->ilocal]);
      } catch (const std::exception& e) {
        error->one(FLERR, "Fix " + std::string(style) + ": " + e.what());
      }
      body_moments_[slot] = moments;
      const body_shape* shape = rotors_->shape_of(moments);
      body_key_[slot] = shape ? static_cast<const void*>(shape) : static_cast<const void*>(body_rotor_[slot]);
    }
    const body_rotor* r = body_rotor_[slot];
    if (!r->exact()) {
      to_rotlie(b->ex_space, b->ey_space, b->ez_space, b->angmom, s);
      r->advance(s, t);
      from_rotlie(s, b->ex_space, b->ey_space, b->ez_space, b->angmom);
      continue;
    }
    const auto [known, added] = flight_group_of_.try_emplace(body_key_[slot], flight_count_.size());
    if (added) flight_count_.push_back(0);
    flight_group_[slot] = static_cast<int>(known->second);
    ++flight_count_[known->second];
  }
  // the bodies of each group contiguous: flight_first_[g] is where group g starts
  const std::size_t groups = flight_count_.size();
  flight_first_.assign(groups + 1, 0);
  for (std::size_t g = 0; g < groups; ++g) flight_first_[g + 1] = flight_first_[g] + flight_count_[g];
  flight_states_.resize(flight_first_.back());
  flight_exact_.resize(flight_first_.back());
  flight_order_.resize(flight_first_.back());
  flight_next_.assign(flight_first_.begin(), flight_first_.end() - 1);
  for (int ibody = 0; ibody < nlocal_body; ++ibody) {
    const int group = flight_group_[static_cast<std::size_t>(ibody)];
    if (group < 0) continue;
    const std::size_t at = flight_next_[static_cast<std::size_t>(group)]++;
    Body* b = &body[ibody];
    to_rotlie(b->ex_space, b->ey_space, b->ez_space, b->angmom, flight_states_[at]);
    flight_exact_[at] = body_rotor_[static_cast<std::size_t>(ibody)]->exact();
    flight_order_[at] = ibody;
  }
  for (std::size_t g = 0; g < groups; ++g) {
    const std::size_t first = flight_first_[g];
    try {
      models::advance_all(flight_exact_.data() + first, flight_count_[g],
                          [&](std::size_t i) -> models::body_state<double>& { return flight_states_[first + i]; }, t);
    } catch (const std::exception& e) {
      error->one(FLERR, "Fix " + std::string(style) + ": " + e.what());
    }
  }
  for (std::size_t at = 0; at < flight_order_.size(); ++at) {
    Body* b = &body[flight_order_[at]];
    from_rotlie(flight_states_[at], b->ex_space, b->ey_space, b->ez_space, b->angmom);
  }
  for (int ibody = 0; ibody < nlocal_body; ++ibody) {
    Body* b = &body[ibody];
    // the attitude as LAMMPS keeps it: a unit quaternion, the axes derived from it
    MathExtra::exyz_to_q(b->ex_space, b->ey_space, b->ez_space, b->quat);
    MathExtra::q_to_exyz(b->quat, b->ex_space, b->ey_space, b->ez_space);
    MathExtra::angmom_to_omega(b->angmom, b->ex_space, b->ey_space, b->ez_space, b->inertia, b->omega);
  }
  note_new_shapes();
}

void FixRigidSierSmall::place_atoms(int vflag) {
  v_init(vflag);
  commflag = RigidConst::INITIAL;
  comm->forward_comm_fix(this, 29);
  set_xv();
}

void FixRigidSierSmall::run_stages(std::size_t first, std::size_t last) {
  for (std::size_t k = first; k < last; ++k) {
    const step_stage& st = stages_[k];
    switch (st.part) {
      case 'V':
        // fresh forces only when a free flight moved the bodies since the last evaluation (the kicks on
        // either side of a thermostat stage share them)
        if (!forces_current_) {
          if (!atoms_placed_) place_atoms(0);
          atoms_placed_ = true;
          mid_step_forces(lmp);
          compute_forces_and_torques();
          forces_current_ = true;
        }
        kick(st.c);
        break;
      case 'T':
        free_flight(st.c);
        forces_current_ = atoms_placed_ = false;
        break;
      case 'O': langevin_step(st.c, st.o_index); break;
      case 'N': chain_step(st.c); break;
    }
  }
}

void FixRigidSierSmall::initial_integrate(int vflag) {
  // every stage before the last kick, which final_integrate gives with the forces LAMMPS computes next
  forces_current_ = atoms_placed_ = true;
  run_stages(0, last_kick_);
  // the atoms where the bodies are, for LAMMPS's evaluation; the constraint virial is tallied in this,
  // the step's last placement only (rigid/small's formula)
  if (!atoms_placed_) place_atoms(vflag);
  atoms_placed_ = true;
}

void FixRigidSierSmall::final_integrate() {
  if (!earlyflag) compute_forces_and_torques();
  forces_current_ = atoms_placed_ = true;
  run_stages(last_kick_, stages_.size());
  commflag = RigidConst::FINAL;
  comm->forward_comm_fix(this, 10);
  set_v();
}

}  // namespace rotlie::lammps
