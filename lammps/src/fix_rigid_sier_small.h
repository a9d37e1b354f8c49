// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
// fix rigid/sier2/small, rigid/sier4/small, …, one style for each TV family of the method registry that
// has one (runs/methods.hpp: van Zon & Schofield's SIER2, Strang-TV, eq. 7; SIER4, PEFRL-TV with the
// corrected h5, eq. 8; SIER6, Kahan & Li's composition of Strang-TV) on the bodies of LAMMPS's fix rigid/small, whose
// body bookkeeping (creation from molecules or custom IDs, ghost bodies, exchange between ranks,
// forces and torques on bodies, atom positions from bodies) they inherit unchanged. They replace the
// time integration: a TV table's kicks (V) and free flights (T: translation and the free rotation
// chosen by `rotor VALUE`, exact by default).
//
// One LAMMPS step is one step of the table. Its first kick uses the forces of the step's start (a TV
// table starts and ends with V: first same as last), its last kick the forces LAMMPS computes after
// initial_integrate; the forces between the free flights (PEFRL-TV: 3 more, f = 4) are computed by
// the fix itself in initial_integrate, with the sequence of LAMMPS's Verlet (neighbour decision,
// communication or re-neighbouring, pre_force, pair, bonded, kspace, reverse communication,
// post_force of every fix): see mid_step_forces.h.
//
// Thermostats are letters of the table (schemes/thermostat_tables.hpp), executed in the same stage loop:
// rigid/NAME/small takes rigid/small's `langevin Tstart Tstop Tperiod seed`, the exact Ornstein–Uhlenbeck
// step O in the middle of the step (SIER2: BAOAB); rigid/NAME/nvt/small takes rigid/nvt/small's `temp
// Tstart Tstop Tdamp` and `tparam Tchain Titer Torder`, two Nosé–Hoover chains (the bodies' translations
// and rotations) for h/2 at both ends of the step, N ½ … N ½.
#include <array>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "fix_rigid_small.h"
#include "body_rotors.hpp"
#include "rotlie/models/thermostats/nose_hoover_chain.hpp"

namespace rotlie::lammps {

/// The thermostatted variant of a family's style: rigid/sier2/small → rigid/sier2/nvt/small.
std::string nvt_style_of(const std::string& style);

class FixRigidSierSmall : public LAMMPS_NS::FixRigidSmall {
 public:
  /// The style (arg[2], rigid/NAME/small) names the family of runs/methods.hpp whose TV table it steps.
  FixRigidSierSmall(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);
  ~FixRigidSierSmall() override;

  int setmask() override;
  void init() override;
  void setup(int vflag) override;
  void initial_integrate(int vflag) override;
  void final_integrate() override;
  /// rigid/NAME/nvt/small: the chains' share of the conserved quantity (etotal + f_ID is conserved);
  /// rigid/NAME/small: rigid/small's own scalar.
  double compute_scalar() override;
  /// langevin: the bodies' translational [0] and rotational [1] kinetic temperatures at the last step's
  /// O-stage, just before it (BAOAB's middle, where its momenta have no h² error for harmonic modes)
  double compute_vector(int i) override;
  void write_restart(FILE* fp) override;  // nvt: the chains' state
  void restart(char* buf) override;

  /// The thermostat a fix command asked for (its keywords' values).
  struct thermostat_settings {
    enum class kind { none, langevin, chain } what = kind::none;
    double t_start = 0, t_stop = 0, period = 0;  ///< target ramp (temperature units), period (time units)
    std::uint64_t seed = 0;                       ///< langevin
    int chain_length = 10, iterations = 1, order = 3;  ///< tparam (rigid/nvt/small's defaults)
  };

 private:
  struct arguments;  // the command's words without `rotor VALUE` and the thermostat's keywords
  FixRigidSierSmall(LAMMPS_NS::LAMMPS* lmp, arguments&& args);

  struct step_stage {
    char part;      ///< V, T, O or N
    double c;       ///< coefficient: the stage lasts c h
    int o_index;    ///< O: its number within the step (0, 1, …), the noise's key
  };
  void run_stages(std::size_t first, std::size_t last);  // stages [first, last) of the step
  void kick(double c);           // V for c h: vcm, angmom, omega of the owned bodies
  void free_flight(double c);    // T for c h: xcm and the free rotation of the owned bodies
  void langevin_step(double c, int o_index);  // O for c h on the owned bodies
  void chain_step(double c);     // N for c h: both chains, then the momenta scaled
  double target_temperature() const;  // the ramp from t_start to t_stop over the run, as LAMMPS's
  void count_and_build_chains();  // the degrees of freedom (as rigid/nvt/small counts them), the chains for them
  void build_chains(const double* dof);  // the chains for dof[0] translational, dof[1] rotational degrees of freedom
  void place_atoms(int vflag);   // ghost bodies, then the atoms of every body
  void resolve_shapes();         // the rotors of every body shape, the same on every rank
  void share_texts(std::vector<std::string>& texts);  // each shape's text from the rank that resolved it
  void print_shapes(double seconds) const;            // rank 0: the shapes, their rotors, the fallbacks
  void note_new_shapes();        // one line per shape that appeared during the run

  std::vector<step_stage> stages_;  ///< the step's table (V first), thermostat letters included
  std::size_t last_kick_ = 0;       ///< the last V: final_integrate runs it and the stages after it
  int o_stages_ = 0;                ///< O stages per step
  int force_evaluations_ = 1;
  std::string tv_table_, table_name_;
  thermostat_settings thermostat_;
  // the step's bookkeeping: whether the forces are those of the current positions, the atoms placed
  bool forces_current_ = true, atoms_placed_ = true;
  int vflag_ = 0;
  // Nosé–Hoover chains [0] translations, [1] rotations: built for the current degrees of freedom
  std::array<std::optional<models::nose_hoover_chain>, 2> chains_;
  std::array<models::nose_hoover_chain_state, 2> chain_states_;
  std::array<double, 2> chain_dof_{0, 0};
  struct chain_term {
    LAMMPS_NS::tagint tag;
    double mv2, Lw;  ///< a body's m v·v and L·ω
  };
  std::vector<chain_term> chain_terms_;  ///< chain_step's scratch
  std::array<double, 4> o_stage_sums_{0, 0, 0, 0};  ///< this rank's Σ m v·v, Σ L·ω and dof before the last O-stage
  std::unique_ptr<body_rotors> rotors_;
  // free_flight's scratch (kept between calls: no allocation once the rank's body count settles)
  std::unordered_map<const void*, std::size_t> flight_group_of_;  ///< an exact-rotor group's index, by its key
  std::vector<std::size_t> flight_count_, flight_first_, flight_next_;  ///< per group: bodies, first slot, next slot
  std::vector<int> flight_group_;                 ///< per local body: its group, −1 when turned directly
  std::vector<models::body_state<double>> flight_states_;  ///< the gathered states, grouped
  std::vector<const models::exact_free_rotation<double>*> flight_exact_;  ///< each gathered state's own rotor
  std::vector<int> flight_order_;                 ///< the local body of each gathered state
  // each local body's rotor as last looked up, the moments it was looked up for and its group key (its
  // shape, or the rotor itself for a shape met during the run): a body whose moments are unchanged (the
  // same body, or one of identical moments moved into its slot) skips the lookup; cleared with the rotors
  std::vector<const body_rotor*> body_rotor_;
  std::vector<std::array<double, 3>> body_moments_;
  std::vector<const void*> body_key_;
  bool shapes_resolved_ = false;
};

}  // namespace rotlie::lammps
