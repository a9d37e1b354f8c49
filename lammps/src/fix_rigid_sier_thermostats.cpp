// SPDX-License-Identifier: GPL-2.0-or-later
// The thermostat letters of FixRigidSierSmall's stage loop: O, the exact Ornstein–Uhlenbeck step of
// `langevin` on the owned bodies, and N, the two Nosé–Hoover chains of rigid/NAME/nvt/small.
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_rigid_sier_small.h"
#include "force.h"
#include "math_extra.h"
#include "rotlie/models/thermostats/ornstein_uhlenbeck.hpp"
#include "update.h"

namespace rotlie::lammps {

using namespace LAMMPS_NS;

namespace {
// rigid/nvt/small's test for a missing rotational degree of freedom (an absolute moment, mass·length²)
constexpr double no_moment = 1e-7;

// rigid/nvt/small's count of a body's degrees of freedom: `dimension` translational ones; 3 rotational
// ones less one for each moment below 1e-7 (a linear body has 2), 1 in 2-d
void add_dof(const double* inertia, int dimension, double* dof) {
  dof[0] += dimension;
  if (dimension == 2) dof[1] += 1;
  else
    for (int k = 0; k < 3; ++k) dof[1] += std::abs(inertia[k]) < no_moment ? 0 : 1;
}

}  // namespace

double FixRigidSierSmall::target_temperature() const {
  // LAMMPS's ramp (rigid/small's langevin, rigid/nvt/small): linear in the step from the run's first to its last
  double delta = static_cast<double>(update->ntimestep - update->beginstep);
  if (delta != 0) delta /= static_cast<double>(update->endstep - update->beginstep);
  return thermostat_.t_start + delta * (thermostat_.t_stop - thermostat_.t_start);
}

void FixRigidSierSmall::langevin_step(double c, int o_index) {
  // Exact OU for c h on each owned body: vcm (σ² = kT/(m mvv2e)) and the body-frame angular momentum
  // G = Qᵀ L (σ_i² = I_i kT/mvv2e), so that the kinetic energy is Boltzmann-distributed at T. The normals
  // of a body come from the stream keyed by (seed, this O-stage's count in the run's steps, the tag of
  // the body's atom): the same on any number of ranks, and continued by a restart without stored state.
  const double kT = force->boltz * target_temperature() / force->mvv2e;
  const auto factors = models::ou_factors_for(1 / thermostat_.period, c * update->dt);
  const std::uint64_t draw = static_cast<std::uint64_t>(update->ntimestep) * static_cast<std::uint64_t>(o_stages_) +
                             static_cast<std::uint64_t>(o_index);
  const bool planar = domain->dimension == 2;
  if (o_index == 0) o_stage_sums_ = {0, 0, 0, 0};
  for (int ibody = 0; ibody < nlocal_body; ++ibody) {
    Body* b = &body[ibody];
    if (o_index == 0) {  // the kinetic energies the O-stage finds (compute_vector)
      o_stage_sums_[0] += b->mass * MathExtra::dot3(b->vcm, b->vcm);
      o_stage_sums_[1] += MathExtra::dot3(b->angmom, b->omega);
      add_dof(b->inertia, domain->dimension, o_stage_sums_.data() + 2);
    }
    const double* e[3] = {b->ex_space, b->ey_space, b->ez_space};
    models::vec3<double> v{b->vcm[0], b->vcm[1], b->vcm[2]}, G{}, sigma_G{};
    for (int i = 0; i < 3; ++i) {
      G[i] = MathExtra::dot3(b->angmom, e[i]);
      sigma_G[i] = std::sqrt(std::max(b->inertia[i], 0.0) * kT);
    }
    int axis = 0;  // 2-d: the principal axis along z, the only one the body turns about
    if (planar) {
      for (int i = 1; i < 3; ++i)
        if (std::abs(e[i][2]) > std::abs(e[axis][2])) axis = i;
      for (int i = 0; i < 3; ++i)
        if (i != axis) sigma_G[i] = 0, G[i] = 0;
    }
    auto noise = models::langevin_noise(thermostat_.seed, draw, static_cast<std::uint64_t>(atom->tag[b->ilocal]));
    models::langevin_body(v, G, factors, std::sqrt(kT / b->mass), sigma_G, noise);
    for (int i = 0; i < (planar ? 2 : 3); ++i) b->vcm[i] = v[i];
    for (int k = 0; k < 3; ++k) b->angmom[k] = G[0] * e[0][k] + G[1] * e[1][k] + G[2] * e[2][k];
    if (planar) b->angmom[0] = b->angmom[1] = 0;
    MathExtra::angmom_to_omega(b->angmom, b->ex_space, b->ey_space, b->ez_space, b->inertia, b->omega);
  }
}

void FixRigidSierSmall::count_and_build_chains() {
  // the degrees of freedom as rigid/nvt/small counts them (none removed for the total momentum), summed
  // over the ranks at each run's setup and, with fix_modify dynamic/dof yes, at each N stage; a chain
  // is (re)built when its count changes (bodies added by fix deposit or pour), its state kept. A chain
  // without degrees of freedom is left out (rigid/nvt/small skips its chains when it counts none).
  double mine[2] = {0, 0}, all[2] = {0, 0};
  for (int ibody = 0; ibody < nlocal_body; ++ibody) add_dof(body[ibody].inertia, domain->dimension, mine);
  MPI_Allreduce(mine, all, 2, MPI_DOUBLE, MPI_SUM, world);
  build_chains(all);
}

void FixRigidSierSmall::build_chains(const double* dof) {
  const double kT = force->boltz * target_temperature();
  for (int i = 0; i < 2; ++i) {
    if (chains_[i] && chain_dof_[i] == dof[i]) continue;
    chain_dof_[i] = dof[i];
    chains_[i].reset();
    if (!(dof[i] > 0)) continue;
    try {
      chains_[i].emplace(dof[i], kT, thermostat_.period, thermostat_.chain_length, thermostat_.order, thermostat_.iterations);
    } catch (const std::exception& e) {
      error->all(FLERR, "Fix " + std::string(style) + ": " + e.what());
    }
    if (chain_states_[i].v.size() != static_cast<std::size_t>(thermostat_.chain_length)) chain_states_[i] = chains_[i]->rest();
  }
}

void FixRigidSierSmall::chain_step(double c) {
  // 2K of the translations and of the rotations (energy units), summed over the ranks, with the
  // degrees of freedom in the same reduction when they are recounted (fix_modify dynamic/dof yes). Each
  // rank sums its bodies in the order of their tags, not of their slots (which differ between a run and
  // its restart): a restarted run continues to the last bit.
  double mine[4] = {0, 0, 0, 0}, all[4] = {0, 0, 0, 0};
  chain_terms_.clear();
  for (int ibody = 0; ibody < nlocal_body; ++ibody) {
    const Body& b = body[ibody];
    chain_terms_.push_back({atom->tag[b.ilocal], b.mass * MathExtra::dot3(b.vcm, b.vcm), MathExtra::dot3(b.angmom, b.omega)});
    if (dynamic) add_dof(b.inertia, domain->dimension, mine + 2);
  }
  std::sort(chain_terms_.begin(), chain_terms_.end(), [](const auto& x, const auto& y) { return x.tag < y.tag; });
  for (const auto& t : chain_terms_) mine[0] += t.mv2, mine[1] += t.Lw;
  MPI_Allreduce(mine, all, dynamic ? 4 : 2, MPI_DOUBLE, MPI_SUM, world);
  if (dynamic) build_chains(all + 2);
  const double kT = force->boltz * target_temperature();
  double scale[2] = {1, 1};
  for (int i = 0; i < 2; ++i) {
    if (!chains_[i]) continue;
    chains_[i]->set_kT(kT);
    scale[i] = chains_[i]->advance(chain_states_[i], all[i] * force->mvv2e, c * update->dt);
  }
  if (scale[0] == 1 && scale[1] == 1) return;
  for (int ibody = 0; ibody < nlocal_body; ++ibody) {
    Body* b = &body[ibody];
    for (int k = 0; k < 3; ++k) {
      b->vcm[k] *= scale[0];
      b->angmom[k] *= scale[1];
      b->omega[k] *= scale[1];
    }
  }
}

double FixRigidSierSmall::compute_scalar() {
  if (thermostat_.what != thermostat_settings::kind::chain) return FixRigidSmall::compute_scalar();
  double e = 0;
  for (int i = 0; i < 2; ++i)
    if (chains_[i]) e += chains_[i]->energy(chain_states_[i]);
  return e;
}

double FixRigidSierSmall::compute_vector(int i) {
  if (thermostat_.what != thermostat_settings::kind::langevin || i < 0 || i > 1) return 0;
  std::array<double, 4> all{};
  MPI_Allreduce(o_stage_sums_.data(), all.data(), 4, MPI_DOUBLE, MPI_SUM, world);
  const double dof = all[2 + i];
  return dof > 0 ? all[i] * force->mvv2e / (dof * force->boltz) : 0.0;
}

// The restart record (rank 0 writes it; every rank reads it): a format number, the chain length M,
// then η and v of the translations' chain and of the rotations' chain (M each).
namespace {
constexpr double restart_format = 1;
}

void FixRigidSierSmall::write_restart(FILE* fp) {
  if (thermostat_.what != thermostat_settings::kind::chain) return;
  const auto M = static_cast<std::size_t>(thermostat_.chain_length);
  std::vector<double> list{restart_format, static_cast<double>(M)};
  for (const auto& s : chain_states_) {
    for (std::size_t k = 0; k < M; ++k) list.push_back(k < s.eta.size() ? s.eta[k] : 0.0);
    for (std::size_t k = 0; k < M; ++k) list.push_back(k < s.v.size() ? s.v[k] : 0.0);
  }
  if (comm->me == 0) {
    const int size = static_cast<int>(list.size() * sizeof(double));
    std::fwrite(&size, sizeof(int), 1, fp);
    std::fwrite(list.data(), sizeof(double), list.size(), fp);
  }
}

void FixRigidSierSmall::restart(char* buf) {
  if (thermostat_.what != thermostat_settings::kind::chain) return;
  double head[2];
  std::memcpy(head, buf, sizeof head);
  const auto M = static_cast<std::size_t>(head[1]);
  if (head[0] != restart_format || M != static_cast<std::size_t>(thermostat_.chain_length)) {
    if (comm->me == 0)
      error->warning(FLERR, "Fix " + std::string(style) + ": the restart file's chains (length " + std::to_string(M) +
                                ") do not fit this fix's tparam (length " + std::to_string(thermostat_.chain_length) + "): the chains start at rest");
    return;
  }
  std::vector<double> list(2 + 4 * M);
  std::memcpy(list.data(), buf, list.size() * sizeof(double));
  std::size_t at = 2;
  for (auto& s : chain_states_) {
    s.eta.assign(list.begin() + static_cast<long>(at), list.begin() + static_cast<long>(at + M));
    s.v.assign(list.begin() + static_cast<long>(at + M), list.begin() + static_cast<long>(at + 2 * M));
    at += 2 * M;
  }
}

}  // namespace rotlie::lammps
