// Report section "Spin–orbit" (issue 24, docs/spin_orbit.md): the scene's bodies, Wisdom, Peale & Mignard
// (1984)'s planar surface of section for Hyperion with Lyapunov estimates, the tilt instability of its
// synchronous state, Mercury in 3:2 and the Moon's forced libration against their first-order theory, and
// error against CPU time for the exact rotor, table rotors and Boost.Odeint. Cheap by default; --full
// follows more starts for longer and sweeps every step and tolerance.
#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "rotlie/reports/chart.hpp"
#include "rotlie/runs/number_text.hpp"
#include "rotlie/reports/output_file.hpp"
#include "rotlie/reports/report.hpp"
#include "rotlie/reports/section_writer.hpp"
#include "sections.hpp"
#include "rotlie/runs/spin_orbit_cost.hpp"
#include "rotlie/runs/spin_orbit_drift.hpp"
#include "rotlie/runs/spin_orbit_science.hpp"

namespace rotlie::reports {
namespace {

constexpr double pi = boost::math::constants::pi<double>();
constexpr double hyperion_period_days = 21.28;
// A regular orbit's finite-time Lyapunov estimate decays like log(N)/N (0.05 per orbit at N = 100, 0.007 at
// N = 1000): above 0.1 per orbit a start is called chaotic.
constexpr double chaos_threshold = 0.1;  // Hyperion's orbital period (a quote: the scene's time unit is 1/n)

struct budget {
  double rate_step;
  int orbits;
  long steps_per_orbit;
  int resonance_orbits;
};

budget budget_of(const report_options& o) {
  if (o.full) return {0.05, 1000, 200, 1000};
  if (o.quick) return {0.2, 100, 100, 40};
  return {0.1, 200, 100, 200};
}

// The log-slope of the obliquity between 1e-5 and 1e-2 rad (its e-folding rate per orbit), or NaN.
double tilt_growth_rate(const std::vector<double>& ob) {
  long first = -1, last = -1;
  for (std::size_t k = 0; k < ob.size(); ++k) {
    if (first < 0 && ob[k] > 1e-5) first = static_cast<long>(k);
    if (last < 0 && ob[k] > 1e-2) last = static_cast<long>(k);
  }
  if (first < 0 || last <= first) return std::nan("");
  return std::log(ob[static_cast<std::size_t>(last)] / ob[static_cast<std::size_t>(first)]) / static_cast<double>(last - first);
}

void bodies_table(std::ostringstream& md) {
  md << "| body | A/C | B/C | (B − A)/C | e | source |\n|:--|--:|--:|--:|--:|:--|\n";
  for (const auto& b : runs::spin_bodies()) {
    const auto I = runs::spin_moments(b);
    md << "| " << b.name << " | " << runs::significant_text(I[0] / I[2], 8) << " | " << runs::significant_text(I[1] / I[2], 8) << " | "
       << runs::significant_text((I[1] - I[0]) / I[2], 4) << " | " << b.orbit_e << " | " << b.source << " |\n";
  }
  md << "\n";
}

// Which resonances keep an island: the symmetric periodic orbits of the pericentre map (θ = 0 or π/2 at
// pericentre, found by bisection), their turns per orbit and the trace of their Jacobian; the
// resonance-overlap estimate; and starts on a finer grid around the 3:2 orbits' rates.
void islands(std::ostringstream& md, const report_options& o, const runs::spin_body& body, const budget& bu) {
  if (o.progress) o.progress("Spin-orbit: Hyperion's resonant periodic orbits");
  const double e = 0.1, half_pi = pi / 2;
  const auto I = runs::spin_moments(body);
  const double w0 = std::sqrt(3 * (I[1] - I[0]) / I[2]);
  struct family {
    double p, theta0, lo, hi;
  };
  // brackets around each symmetric orbit's pericentre rate (a strong asphericity moves them far from p n)
  const std::vector<family> families = {{0.5, half_pi, 0.8, 1.0}, {1, 0, 0.4, 0.7},      {1.5, 0, 1.85, 2.1},
                                        {1.5, half_pi, 1.2, 1.4}, {2, 0, 2.2, 2.45}, {2.5, 0, 2.6, 2.8}};
  md << "**Which islands survive.** The centre of an island is a periodic orbit; by the time-reversal symmetry the p:1 orbits "
        "start at pericentre with θ = 0 or π/2 and reach θ ≡ θ₀ + pπ (mod π) at apocentre (found by bisection on the rate). "
        "The trace of the one-orbit map's Jacobian at such an orbit (central differences) says whether an island surrounds it "
        "(|tr| < 2, elliptic) or not (|tr| > 2, hyperbolic); SIER4 at h = 1/200 orbit:\n\n"
     << "| p | θ at pericentre | θ'/n at pericentre | turns per orbit | trace | |\n|--:|:--|--:|--:|--:|:--|\n";
  for (const auto& f : families) {
    double w = std::nan("");
    try {
      w = runs::resonant_rate(body, e, f.p, f.lo, f.hi, 200, f.theta0);
    } catch (const std::runtime_error&) {
    }
    if (!std::isfinite(w)) {
      md << "| " << f.p << " | " << (f.theta0 == 0 ? "0" : "π/2") << " | none in " << f.lo << "–" << f.hi << " | | | |\n";
      continue;
    }
    const double tr = runs::planar_map_trace(body, e, f.theta0, w, 200), turns = runs::spin_winding(body, e, f.theta0, w, 1, 200);
    md << "| " << f.p << " | " << (f.theta0 == 0 ? "0" : "π/2") << " | " << runs::significant_text(w, 6) << " | " << runs::significant_text(turns, 6) << " | "
       << runs::significant_text(tr, 4) << " | " << (std::abs(tr) < 2 ? "elliptic: an island" : "hyperbolic: no island") << " |\n";
  }
  md << "\nBoth symmetric 3:2 orbits exist and both are hyperbolic: **Hyperion has no 3:2 island** at (B − A)/C = 0.264, e = 0.1, while the "
        "1:2, 1:1, 2:1 and 5:2 islands survive (issue 24 expected a 3:2 island; there is none). Wisdom (1987, AJ 94, 1350) writes that "
        "this region is so strongly perturbed that the 3/2 resonance … (a quote; the transcript consulted breaks off there, so the "
        "conclusion rests on the table above). The resonance-overlap estimate agrees: the p:1 island's half-width in θ'/n is ω₀√H(p, e), ω₀ = √(3(B − A)/C) = "
     << runs::significant_text(w0, 4) << ", with Cayley's H (WPM 1984):\n\n| p | H(p, e) | half-width ω₀√H | spans θ'/n |\n|--:|--:|--:|:--|\n";
  double width[3];
  int k = 0;
  for (const double p : {1.0, 1.5, 2.0}) {
    const double H = runs::cayley_coefficient(p, e), wd = w0 * std::sqrt(std::abs(H));
    width[k++] = wd;
    md << "| " << p << " | " << runs::significant_text(H, 4) << " | " << runs::significant_text(wd, 3) << " | " << runs::fixed_text(p - wd, 2) << "–"
       << runs::fixed_text(p + wd, 2) << " |\n";
  }
  md << "\nThe 1:1 and 3:2 half-widths add to " << runs::significant_text((width[0] + width[1]) / 0.5, 3) << " times the distance 0.5 between their "
        "centres, the 3:2 and 2:1 ones to "
     << runs::significant_text((width[1] + width[2]) / 0.5, 3)
     << " times (Chirikov's criterion: overlap above 1): the 3:2 centre lies inside the 1:1 resonance's width, and the estimate's "
        "chaotic band, "
     << runs::fixed_text(1 - width[0], 2) << "–" << runs::fixed_text(2 + width[2], 2) << " n, lies within the measured zone.\n\n";
  // starts on a finer grid through both 3:2 orbits' pericentre rates
  const double step = o.quick ? 0.05 : 0.025;
  int regular = 0, total = 0;
  std::string regular_turns;
  for (const double theta0 : {0.0, half_pi})
    for (double w = 1.2; w <= 2.1 + 1e-9; w += step) {
      ++total;
      const double l = runs::lyapunov_per_orbit(body, e, models::spin_orbit_start<double>(I, theta0, w, 0.0), bu.orbits, bu.steps_per_orbit);
      if (l >= chaos_threshold) continue;
      ++regular;
      regular_turns += (regular_turns.empty() ? "" : ", ") + runs::significant_text(runs::spin_winding(body, e, theta0, w, bu.orbits, bu.steps_per_orbit), 4);
    }
  md << "Starts on a finer grid through both 3:2 orbits (θ₀ = 0 and π/2, θ'₀ = 1.2 to 2.1 n in steps of " << step << ", " << bu.orbits
     << " orbits each): " << regular << " of " << total << " are regular"
     << (regular ? ", with mean rates " + regular_turns + " n (none is a 3:2 libration)" : "") << ".\n\n";
}

void hyperion_section(report_section& s, std::ostringstream& md, const report_options& o, const budget& bu) {
  const auto body = runs::spin_body_named("Hyperion");
  if (o.progress) o.progress("Spin-orbit: Hyperion's surface of section");
  std::vector<std::pair<double, double>> starts;
  for (double w = 0.2; w <= 3.0 + 1e-9; w += bu.rate_step) starts.push_back({0.0, w}), starts.push_back({pi / 2, w});
  const auto sec = runs::planar_section(body, 0.1, starts, bu.orbits, bu.steps_per_orbit);
  chart c;
  c.title = "Hyperion (e = 0.1, (B - A)/C = 0.264): planar surface of section at pericentre";
  c.x_label = "theta (mod pi), rad";
  c.y_label = "d theta / dt / n";
  c.log_x = c.log_y = false;
  c.colour_label = "Lyapunov exponent per orbit";
  c.colour_range = std::pair<double, double>{0.0, 0.6};
  chart_series pts{"pericentre passages", {}, {}, true};
  pts.point_size = 0.3;
  for (std::size_t i = 0; i < sec.theta.size(); ++i) {
    pts.x.push_back(sec.theta[i]);
    pts.y.push_back(sec.rate[i]);
    pts.z.push_back(std::min(sec.lyapunov[static_cast<std::size_t>(sec.trajectory[i])], 0.6));
  }
  c.series.push_back(std::move(pts));
  int chaotic = 0;
  double lmax = 0;
  std::string chaotic_rates[2];
  double zone_lo = 1e9, zone_hi = -1e9;
  for (std::size_t i = 0; i < sec.rate.size(); ++i)
    if (sec.lyapunov[static_cast<std::size_t>(sec.trajectory[i])] > chaos_threshold)
      zone_lo = std::min(zone_lo, sec.rate[i]), zone_hi = std::max(zone_hi, sec.rate[i]);
  for (std::size_t j = 0; j < sec.lyapunov.size(); ++j) {
    const double l = sec.lyapunov[j];
    chaotic += l > chaos_threshold, lmax = std::max(lmax, l);
    if (l > chaos_threshold) chaotic_rates[j % 2] += (chaotic_rates[j % 2].empty() ? "" : ", ") + runs::significant_text(starts[j].second, 3);
  }
  md << "### Hyperion: the planar surface of section (Wisdom, Peale & Mignard 1984)\n\n"
     << "With obliquity 0 the scene is the planar problem θ'' = −(3/2)((B − A)/C) r⁻³ sin 2(θ − f). " << starts.size()
     << " starts at pericentre (θ₀ = 0 and π/2, θ'₀ from 0.2 to 3 n in steps of " << bu.rate_step << ") are followed for " << bu.orbits
     << " orbits by SIER4 at h = 1/" << bu.steps_per_orbit
     << " orbit; each point is one pericentre passage, coloured by the start's Lyapunov exponent (two trajectories 1e-9 apart, "
        "renormalised every orbit). A regular orbit's finite-time estimate decays like log(N)/N ("
     << runs::significant_text(std::log(bu.orbits) / bu.orbits, 2) << " per orbit at N = " << bu.orbits << "), so an exponent above "
     << chaos_threshold << " per orbit marks chaos: " << chaotic << " of " << starts.size() << " starts are chaotic, the largest exponent is "
     << runs::significant_text(lmax, 3) << " per orbit (a Lyapunov time of " << runs::significant_text(1 / lmax, 3) << " orbits, "
     << runs::significant_text(hyperion_period_days / lmax, 3) << " days). Chaotic starts: θ₀ = 0 at θ'₀/n = "
     << (chaotic_rates[0].empty() ? std::string("none") : chaotic_rates[0]) << "; θ₀ = π/2 at θ'₀/n = "
     << (chaotic_rates[1].empty() ? std::string("none") : chaotic_rates[1]) << ". The chaotic orbits' pericentre rates fill "
     << runs::fixed_text(zone_lo, 2) << " to " << runs::fixed_text(zone_hi, 2)
     << " n: one zone from almost no rotation to nearly two and a half turns per orbit around the synchronous island, as Wisdom, "
        "Peale & Mignard (1984) found (and Wisdom 1987, AJ 94, 1350, describes: a quote).\n\n";
  add_chart(s, md, o, "spin_orbit_hyperion_section", c, "Hyperion's planar surface of section, coloured by the Lyapunov exponent.");
  islands(md, o, body, bu);

  // the synchronous periodic orbit and its tilt instability
  if (o.progress) o.progress("Spin-orbit: Hyperion's synchronous state in 3-D");
  const double w1 = runs::resonant_rate(body, 0.1, 1.0, 0.5, 1.5, bu.steps_per_orbit);
  const auto I = runs::spin_moments(body);
  const int tilt_orbits = o.quick ? 60 : 100;
  const auto hyp = runs::obliquity_history(body, 0.1, models::spin_orbit_start<double>(I, 0.0, w1, 1e-6), tilt_orbits, bu.steps_per_orbit);
  const double planar_l = runs::lyapunov_per_orbit(body, 0.1, models::spin_orbit_start<double>(I, 0.0, w1, 0.0), bu.orbits, bu.steps_per_orbit);
  const double growth = tilt_growth_rate(hyp);
  const auto moon = runs::spin_body_named("Moon");
  const auto Im = runs::spin_moments(moon);
  const double wm = runs::resonant_rate(moon, 0.0549, 1.0, 0.9, 1.1, bu.steps_per_orbit);
  const auto lun = runs::obliquity_history(moon, 0.0549, models::spin_orbit_start<double>(Im, 0.0, wm, 1e-6), tilt_orbits, bu.steps_per_orbit);
  chart t;
  t.title = "Synchronous state tilted by 1e-6 rad: obliquity at pericentre";
  t.x_label = "orbits";
  t.y_label = "obliquity (rad)";
  t.log_x = false;
  chart_series hs{"Hyperion", {}, {}}, ls{"Moon", {}, {}};
  for (std::size_t k = 0; k < hyp.size(); ++k) hs.x.push_back(static_cast<double>(k + 1)), hs.y.push_back(std::max(hyp[k], 1e-12));
  for (std::size_t k = 0; k < lun.size(); ++k) ls.x.push_back(static_cast<double>(k + 1)), ls.y.push_back(std::max(lun[k], 1e-12));
  t.series = {hs, ls};
  double lun_max = 0;
  for (double x : lun) lun_max = std::max(lun_max, x);
  md << "**The synchronous state is attitude-unstable.** The symmetric synchronous periodic orbit (θ = 0 at pericentre, π at "
        "apocentre) starts at θ' = "
     << runs::significant_text(w1, 8) << " n for Hyperion; in the plane its Lyapunov estimate over " << bu.orbits << " orbits is "
     << runs::significant_text(planar_l, 3) << " per orbit (regular: the 1:1 island). Tilted by 1e-6 rad it leaves the plane: the obliquity "
     << "grows by a factor e every " << runs::significant_text(1 / growth, 3) << " orbits (rate " << runs::significant_text(growth, 3)
     << " per orbit between 1e-5 and 1e-2 rad) and reaches " << runs::significant_text(hyp.back(), 3) << " rad after " << tilt_orbits
     << " orbits, as WPM found. The Moon's synchronous state, tilted the same way, stays below " << runs::significant_text(lun_max, 3)
     << " rad.\n\n";
  add_chart(s, md, o, "spin_orbit_synchronous_tilt", t, "Obliquity of the synchronous state tilted by 1e-6 rad: Hyperion and the Moon.");

  // Lyapunov estimates of 3-D states
  struct state {
    std::string what;
    double theta0, omega0, obliquity;
  };
  const std::vector<state> states = {{"synchronous, tilted 1e-3 rad", 0.0, w1, 1e-3},
                                     {"θ₀ = π/2, θ'₀ = 1 n, planar", pi / 2, 1.0, 0.0},
                                     {"θ'₀ = 1 n about C, tilted 0.5 rad", 0.0, 1.0, 0.5},
                                     {"θ'₀ = 4.2 n about C, tilted 0.5 rad", 0.0, 4.2, 0.5},
                                     {"θ'₀ = 4.2 n about C, planar", 0.0, 4.2, 0.0}};
  md << "Lyapunov estimates (" << bu.orbits << " orbits, SIER4 at h = 1/" << bu.steps_per_orbit << " orbit; 1 orbit = "
     << hyperion_period_days << " days, a quote):\n\n| Hyperion start | exponent per orbit | Lyapunov time (orbits) | (days) |\n|:--|--:|--:|--:|\n";
  for (const auto& st : states) {
    const double l = runs::lyapunov_per_orbit(body, 0.1, models::spin_orbit_start<double>(I, st.theta0, st.omega0, st.obliquity), bu.orbits,
                                              bu.steps_per_orbit);
    const bool regular = l < chaos_threshold;
    md << "| " << st.what << " | " << runs::significant_text(l, 3) << " | " << (regular ? std::string("regular") : runs::significant_text(1 / l, 3)) << " | "
       << (regular ? std::string("—") : runs::significant_text(hyperion_period_days / l, 3)) << " |\n";
  }
  md << "\nGoldberg et al. (2024, A&A 692, A9) argue that Hyperion is near a nutation–orbit resonance and rotates quasi-regularly, "
        "with chaos orders of magnitude weaker than WPM's (a quote). This scene has no tides, no Titan and the Voyager-era moments, "
        "and the starts above are not fitted to the observed spin state (about 4.2–4.5 n, the axis some 30° from the long axis, "
        "Harbison et al. 2011, a quote): the table says how chaotic these states of the model are, not which state Hyperion is in.\n\n";
}

void resonance_section(report_section& s, std::ostringstream& md, const report_options& o, const budget& bu) {
  if (o.progress) o.progress("Spin-orbit: Mercury in 3:2 and the Moon's libration");
  const auto mercury = runs::spin_body_named("Mercury");
  const auto Ime = runs::spin_moments(mercury);
  const double e_me = 0.2056, dme = (Ime[1] - Ime[0]) / Ime[2];
  const double w_me = runs::resonant_rate(mercury, e_me, 1.5, 1.4, 1.6, 200);
  const auto me = runs::resonance(mercury, e_me, 1.5, w_me, bu.resonance_orbits, 200);
  // first-order theory of the forced libration (Margot et al. 2007's form, whole body): (3/2)(B−A)/C (1 − 11e² + 959e⁴/48)
  const double me_theory = 1.5 * dme * (1 - 11 * e_me * e_me + 959.0 / 48 * std::pow(e_me, 4));
  const auto moon = runs::spin_body_named("Moon");
  const auto Imo = runs::spin_moments(moon);
  const double e_mo = 0.0549, w2 = 3 * (Imo[1] - Imo[0]) / Imo[2];
  const double w_mo = runs::resonant_rate(moon, e_mo, 1.0, 0.9, 1.1, 200);
  const auto mo = runs::resonance(moon, e_mo, 1.0, w_mo, bu.resonance_orbits, 200);
  // φ'' + ω₀²φ = 2e ω₀² sin M to first order in e: amplitude 2e ω₀²/(1 − ω₀²)
  const double mo_theory = 2 * e_mo * w2 / (1 - w2);
  const double arcsec = 180 * 3600 / pi;
  md << "### Mercury in 3:2 and the Moon's libration\n\n"
     << "Each starts on the symmetric periodic orbit of its resonance (θ = 0, the long axis towards the point mass, at pericentre and "
        "θ ≡ pπ at apocentre; spin rate at pericentre "
     << runs::significant_text(w_me, 8) << " n for Mercury, " << runs::significant_text(w_mo, 8) << " n for the Moon, found by bisection), so that no "
        "free libration is excited, "
     << bu.resonance_orbits << " orbits of SIER4 at h = 1/200 orbit. γ = θ − pM (mod π) is the resonant angle; its first "
        "harmonic (the discrete Fourier coefficient over each orbit, averaged over the orbits) is the forced libration, compared with first-order theory:\n\n"
     << "| body | p | max |γ| (rad) | forced amplitude | theory | ratio |\n|:--|--:|--:|--:|--:|--:|\n"
     << "| Mercury | 3/2 | " << runs::significant_text(me.max_excursion, 3) << " | " << runs::significant_text(me.forced_amplitude, 4) << " rad = "
     << runs::significant_text(me.forced_amplitude * arcsec, 3) << "″ | (3/2)((B − A)/C)(1 − 11e² + 959e⁴/48) = " << runs::significant_text(me_theory, 4)
     << " | " << runs::significant_text(me.forced_amplitude / me_theory, 4) << " |\n"
     << "| Moon | 1 | " << runs::significant_text(mo.max_excursion, 3) << " | " << runs::significant_text(mo.forced_amplitude, 4) << " rad = "
     << runs::significant_text(mo.forced_amplitude * arcsec, 3) << "″ | 2eω₀²/(1 − ω₀²), ω₀² = 3(B − A)/C: " << runs::significant_text(mo_theory, 4)
     << " | " << runs::significant_text(mo.forced_amplitude / mo_theory, 4) << " |\n\n"
     << "Both stay in resonance (γ bounded). The theory for Mercury is that of a body whose mantle librates alone (Margot et al. "
        "2007 use (B − A)/C_m, about 2.3 times larger); the rigid scene uses the whole body's C, so its amplitude is the rigid "
        "planet's, not the observed 38.5″ (a quote, Margot et al. 2012).\n\n";
  chart c;
  c.title = "Resonant angle at pericentre: Mercury (3:2) and the Moon (1:1)";
  c.x_label = "orbits";
  c.y_label = "gamma = theta - p M (rad)";
  c.log_x = c.log_y = false;
  c.series = {chart_series{"Mercury, 3:2", me.orbit, me.gamma}, chart_series{"Moon, 1:1", mo.orbit, mo.gamma}};
  add_chart(s, md, o, "spin_orbit_resonances", c, "The resonant angle at each pericentre passage.");
}

void cost_section(report_section& s, std::ostringstream& md, const report_options& o) {
  const std::vector<double> steps = o.full    ? std::vector<double>{25, 50, 100, 200, 400, 800, 1600}
                                    : o.quick ? std::vector<double>{25, 100, 400}
                                              : std::vector<double>{25, 50, 100, 200, 400};
  const std::vector<std::string> tols = o.full ? std::vector<std::string>{"1e-6", "1e-7", "1e-8", "1e-9", "1e-10", "1e-11", "1e-12", "1e-13"}
                                               : std::vector<std::string>{"1e-7", "1e-10", "1e-13"};
  md << "### Error against CPU time\n\n"
     << "Final attitude error (Frobenius distance from RKF78 in long double at tolerance 1e-18) against the stepping CPU time, in "
        "double. The dedicated rotors are the best of their family by ‖H_R5‖ for the body (`rotlie best`): R:CBA:4 for the Moon "
        "and Mercury, N4:ABC:3 (9 rotations) for Hyperion; `--full` sweeps more steps and tolerances, and bench/spin_bench "
        "also times the P and N rotors, the ABC compositions, SIER2 and MRDL. At every step the SIER4 "
        "variants have the same error to about three digits: the TV splitting's error dominates, and a rotor changes only the cost "
        "of a step (docs/spin_orbit.md says what follows).\n\n";
  for (const auto& cs : runs::spin_cost_cases()) {
    if (o.progress) o.progress("Spin-orbit: error against CPU time, " + cs.label);
    const auto ref = runs::spin_cost_reference(cs);
    // the best dedicated rotors `rotlie best` ranks for the body: R for the near-symmetric Moon and Mercury,
    // and for Hyperion the cheapest family's best (N, 9 rotations), which spin_bench measures as the winner
    const std::string best = cs.body == "Hyperion" ? "SIER4/N4:ABC:3" : "SIER4/R:CBA:4";
    const std::vector<std::string> methods = {"SIER4", "SIER4/RS4-S5-McLachlan:ABC", best};
    chart c;
    c.title = "Spin-orbit, " + cs.label + ": attitude error against CPU time";
    c.x_label = "CPU seconds";
    c.y_label = "attitude error";
    md << "| " << cs.label << " | CPU for 1e-9 (s) |\n|:--|--:|\n";
    auto add = [&](const std::string& family, const std::vector<runs::spin_cost_point>& pts) {
      chart_series ser{family, {}, {}};
      for (const auto& p : pts)
        if (p.error > 0) ser.x.push_back(p.cpu_s), ser.y.push_back(p.error);
      c.series.push_back(std::move(ser));
      md << "| " << family << " | " << runs::scientific_or_dash(runs::cpu_at_error(pts, 1e-9), 2) << " |\n";
    };
    for (const auto& m : methods) {
      std::vector<runs::spin_cost_point> pts;
      // Hyperion's (B - A)/C is about 1000 times the Moon's: 4 times finer steps reach the same errors (its run is 5 orbits)
      const double finer = cs.body == "Hyperion" ? 4 : 1;
      for (double n : steps) pts.push_back(runs::spin_cost_point_of(cs, ref, m, 1 / (finer * n), o.full ? 0.05 : 0.005));
      add(m, pts);
    }
    for (const std::string family : {"odeint-dopri5", "odeint-rkf78"}) {
      std::vector<runs::spin_cost_point> pts;
      for (const auto& t : tols) pts.push_back(runs::spin_cost_point_of(cs, ref, family + ":" + t, 0, o.full ? 0.05 : 0.005));
      add(family, pts);
    }
    md << "\n";
    std::string key = cs.body;
    std::transform(key.begin(), key.end(), key.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    add_chart(s, md, o, "spin_orbit_cost_" + key, c, "Error against CPU time, " + cs.label + ".");
  }
}

// The long runs (bench/spin_drift_bench measures 10⁴ orbits, and 10⁶ with --full): the Moon and Mercury to
// 10³ orbits (10⁴ with --full) against RKF78 in long double at 1e-18.
void drift_section(std::ostringstream& md, const report_options& o) {
  const long last = o.full ? 10000 : 1000;
  std::vector<long> checkpoints;
  for (long n = 100; n <= last; n *= 10) checkpoints.push_back(n);
  md << "### Long runs: the attitude error\n\n"
     << "The rotation angle of Q_refᵀQ after " << checkpoints.front() << " … " << last << " orbits, in double, against Odeint's RKF78 in "
        "long double at tolerance 1e-18 (bench/spin_drift_bench runs 10⁴ orbits and checks that reference against SIER4 in long double at "
        "a four times finer step: they agree to 1.5e-11 at 10⁴ orbits). RKF78 in double runs at the tolerance whose CPU time over "
        "100 orbits is nearest SIER4's (equal CPU).\n\n";
  for (const auto& c : runs::spin_drift_cases()) {
    if (c.body == "Hyperion") continue;  // 4.2 n needs 400 steps an orbit: the bench's
    if (o.progress) o.progress("Spin-orbit: long runs, " + c.label);
    const std::string tol = runs::rkf78_tolerance_at_equal_cpu(c, 100);
    const auto ref = runs::spin_track_of(c, "odeint-rkf78:1e-18", true, 1, checkpoints);
    md << "| " << c.label << ", h = 1/" << c.steps_per_orbit << " orbit |";
    for (long n : checkpoints) md << " " << n << " orbits |";
    md << " CPU s |\n|:--|";
    for (std::size_t i = 0; i <= checkpoints.size(); ++i) md << "--:|";
    md << "\n";
    const std::string best = "SIER4/R:CBA:4";
    for (const std::string& m : std::vector<std::string>{"SIER4", best, "SIER4/RS4-S5-McLachlan:ABC", "odeint-rkf78:" + tol}) {
      const auto t = runs::spin_track_of(c, m, false, c.steps_per_orbit, checkpoints);
      md << "| " << m << " |";
      for (std::size_t i = 0; i < t.orbits.size(); ++i) md << " " << runs::scientific_or_dash(static_cast<double>(runs::attitude_angle(ref.Q[i], t.Q[i])), 2) << " |";
      md << " " << runs::significant_text(t.cpu_s.back(), 3) << " |\n";
    }
    md << "\n";
  }
}

}  // namespace

report_section spin_orbit_section(const report_options& options) {
  report_section s;
  s.title = "Spin–orbit";
  const budget bu = budget_of(options);
  std::ostringstream md;
  md << "## " << s.title << "\n\n"
     << "A triaxial body on a fixed Kepler orbit under the quadrupole torque (Touma & Wisdom 1994; G M = 1, a = 1, period 2π; "
        "`rotlie spin`, docs/spin_orbit.md). The bodies, their moments with C = 1 and their orbits:\n\n";
  bodies_table(md);
  hyperion_section(s, md, options, bu);
  resonance_section(s, md, options, bu);
  cost_section(s, md, options);
  drift_section(md, options);
  s.markdown = md.str();
  return s;
}

}  // namespace rotlie::reports
