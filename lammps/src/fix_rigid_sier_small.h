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
#include <array>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "fix_rigid_small.h"
#include "body_rotors.hpp"

namespace rotlie::lammps {

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

 private:
  struct arguments;  // the command's words without `rotor VALUE`, thermostats and barostats refused
  FixRigidSierSmall(LAMMPS_NS::LAMMPS* lmp, arguments&& args);

  void kick(double c);           // V for c h: vcm, angmom, omega of the owned bodies
  void free_flight(double c);    // T for c h: xcm and the free rotation of the owned bodies
  void place_atoms(int vflag);   // ghost bodies, then the atoms of every body
  void resolve_shapes();         // the rotors of every body shape, the same on every rank
  void share_texts(std::vector<std::string>& texts);  // each shape's text from the rank that resolved it
  void print_shapes(double seconds) const;            // rank 0: the shapes, their rotors, the fallbacks
  void note_new_shapes();        // one line per shape that appeared during the run

  std::vector<double> coefficients_;  ///< the TV table's stage coefficients, V first
  std::string tv_table_;
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
