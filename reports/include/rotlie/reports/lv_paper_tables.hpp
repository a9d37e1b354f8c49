#pragma once
// Numbers printed in Laskar & Vaillant (2018), quoted once for every section that compares with
// them (the accuracy section's regenerated Table 3, the audit's claims).
#include <array>

namespace rotlie::reports {

/// LV Table 3 (spherical top): the numeric and the analytic remainder of each N solution,
/// normalised by N5 ABC (2).
struct lv_table3_row {
  const char* integrator;
  double numeric;
  double analytic;
};

inline constexpr std::array<lv_table3_row, 11> lv_table3 = {{{"N1 ABC (1)", 119.85, 100.50},
                                                            {"N2 ABC (1)", 3.97, 3.40},
                                                            {"N3 ABC (1)", 27.04, 22.51},
                                                            {"N3 ABC (2)", 107.78, 92.79},
                                                            {"N3 ABC (3)", 1.00, 1},
                                                            {"N4 ABC (1)", 1120.50, 991.42},
                                                            {"N4 ABC (2)", 2.06, 1.58},
                                                            {"N4 ABC (3)", 1.59, 1.18},
                                                            {"N5 ABC (1)", 107.82, 92.79},
                                                            {"N5 ABC (3)", 27.02, 22.51},
                                                            {"N7 ABC (1)", 120.07, 100.50}}};

/// LV Table 4 (water): the 15 N solutions of smallest analytic remainder, in units of 10^-2.
struct lv_table4_row {
  const char* integrator;
  double analytic_e2;
};

inline constexpr std::array<lv_table4_row, 15> lv_table4 = {{{"N1 ABC (1)", 2.09},
                                                            {"N1 ABC (2)", 3.83},
                                                            {"N2 ABC (1)", 3.51},
                                                            {"N2 CAB (2)", 2.91},
                                                            {"N2 ACB (1)", 1.18},
                                                            {"N2 BAC (2)", 1.06},
                                                            {"N3 ABC (1)", 2.77},
                                                            {"N3 BAC (1)", 2.96},
                                                            {"N4 BCA (1)", 3.22},
                                                            {"N5 CAB (2)", 1.59},
                                                            {"N5 ACB (1)", 2.84},
                                                            {"N5 BAC (1)", 2.67},
                                                            {"N6 ABC (1)", 2.11},
                                                            {"N6 ABC (2)", 2.19},
                                                            {"N6 BAC (1)", 3.27}}};

/// Stage coefficients printed with 41 digits in LV eqs. (74) and (76), as quoted there.
struct lv_printed_coefficient {
  const char* file;  ///< the dedicated section's solutions file that holds the scheme
  const char* integrator;
  const char* coefficient;
  const char* paper;
};

inline constexpr std::array<lv_printed_coefficient, 5> lv_printed_coefficients = {{
    {"solutions_water.json", "N2 BAC (2)", "a1", "4.5504624774591050429019276281136041301731e-2"},    // LV eq. (74)
    {"solutions_water.json", "N2 BAC (2)", "a2", "1.5208328361334726621353294430175796767150e-1"},    // LV eq. (74)
    {"solutions_water_P.json", "P1 BAC (5)", "a1", "2.6576137190217391781483465189759344419197e-2"},  // LV eq. (76)
    {"solutions_water_P.json", "P1 BAC (5)", "b1", "2.8352180398306075206301328654179005782548e-1"},  // LV eq. (76)
    {"solutions_water_P.json", "P1 BAC (5)", "a2", "2.7103966011355754480520833151108230977015e-1"}}};  // LV eq. (76)

}  // namespace rotlie::reports
