// Report section "Spin–orbit" (issue 24, docs/spin_orbit.md): the scene's bodies, Wisdom, Peale & Mignard
// (1984)'s planar surface of section for Hyperion with Lyapunov estimates, the tilt instability of its
// synchronous state, Mercury in 3:2 and the Moon's forced libration against their first-order theory, and
// error against CPU time for the exact rotor, table rotors and Boost.Odeint. Cheap by default; --full
// follows more starts for longer and sweeps every step and tolerance. Every number is runs::'s
// (hyperion_study, spin_islands_study, forced_libration_study, spin_cost_study, spin_drift_study); the
// section formats and draws.
#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "rotlie/reports/chart.hpp"
#include "rotlie/runs/number_text.hpp"
#include "rotlie/reports/output_file.hpp"
#include "rotlie/reports/report.hpp"
#include "rotlie/reports/section_writer.hpp"
#include "sections.hpp"
#include "rotlie/runs/forced_libration_study.hpp"
#include "rotlie/runs/hyperion_study.hpp"
#include "rotlie/runs/spin_cost_study.hpp"
#include "rotlie/runs/spin_drift_study.hpp"
#include "rotlie/runs/spin_islands_study.hpp"

namespace rotlie::reports {
namespace {

constexpr double pi = boost::math::constants::pi<double>();
constexpr double chaos_threshold = runs::spin_chaos_threshold;
constexpr double hyperion_period_days = runs::hyperion_period_days;

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

std::string rates_text(const std::vector<double>& rates) {
  std::string s;
  for (const double w : rates) s += (s.empty() ? "" : ", ") + runs::significant_text(w, 3);
  return s.empty() ? std::string("none") : s;
}

void bodies_table(std::ostringstream& md) {
  md << "| body | A/C | B/C | (B − A)/C | e | source |\n|:--|--:|--:|--:|--:|:--|\n";
  for (const auto& b : runs::spin_body_table())
    md << "| " << b.name << " | " << runs::significant_text(b.a_over_c, 8) << " | " << runs::significant_text(b.b_over_c, 8) << " | "
       << runs::significant_text(b.asphericity, 4) << " | " << b.e << " | " << b.source << " |\n";
  md << "\n";
}

// Which resonances keep an island: the symmetric periodic orbits of the pericentre map, the
// resonance-overlap estimate, and starts on a finer grid around the 3:2 orbits' rates.
void islands(std::ostringstream& md, const report_options& o, const budget& bu) {
  if (o.progress) o.progress("Spin-orbit: Hyperion's resonant periodic orbits");
  const auto is = runs::hyperion_islands(0.1, o.quick ? 0.05 : 0.025, bu.orbits, bu.steps_per_orbit);
  md << "**Which islands survive.** The centre of an island is a periodic orbit; by the time-reversal symmetry the p:1 orbits "
        "start at pericentre with θ = 0 or π/2 and reach θ ≡ θ₀ + pπ (mod π) at apocentre (found by bisection on the rate). "
        "The trace of the one-orbit map's Jacobian at such an orbit (central differences) says whether an island surrounds it "
        "(|tr| < 2, elliptic) or not (|tr| > 2, hyperbolic); SIER4 at h = 1/200 orbit:\n\n"
     << "| p | θ at pericentre | θ'/n at pericentre | turns per orbit | trace | |\n|--:|:--|--:|--:|--:|:--|\n";
  for (const auto& f : is.orbits) {
    if (!f.found) {
      md << "| " << f.p << " | " << (f.theta0 == 0 ? "0" : "π/2") << " | none in " << f.lo << "–" << f.hi << " | | | |\n";
      continue;
    }
    md << "| " << f.p << " | " << (f.theta0 == 0 ? "0" : "π/2") << " | " << runs::significant_text(f.rate, 6) << " | " << runs::significant_text(f.turns, 6)
       << " | " << runs::significant_text(f.trace, 4) << " | " << (f.elliptic ? "elliptic: an island" : "hyperbolic: no island") << " |\n";
  }
  md << "\nBoth symmetric 3:2 orbits exist and both are hyperbolic: **Hyperion has no 3:2 island** at (B − A)/C = 0.264, e = 0.1, while the "
        "1:2, 1:1, 2:1 and 5:2 islands survive (issue 24 expected a 3:2 island; there is none). Wisdom (1987, AJ 94, 1350) writes that "
        "this region is so strongly perturbed that the 3/2 resonance … (a quote; the transcript consulted breaks off there, so the "
        "conclusion rests on the table above). The resonance-overlap estimate agrees: the p:1 island's half-width in θ'/n is ω₀√H(p, e), ω₀ = √(3(B − A)/C) = "
     << runs::significant_text(is.omega0, 4) << ", with Cayley's H (WPM 1984):\n\n| p | H(p, e) | half-width ω₀√H | spans θ'/n |\n|--:|--:|--:|:--|\n";
  for (const auto& w : is.widths)
    md << "| " << w.p << " | " << runs::significant_text(w.H, 4) << " | " << runs::significant_text(w.half_width, 3) << " | "
       << runs::fixed_text(w.p - w.half_width, 2) << "–" << runs::fixed_text(w.p + w.half_width, 2) << " |\n";
  md << "\nThe 1:1 and 3:2 half-widths add to " << runs::significant_text(is.overlap_1_to_3_2, 3) << " times the distance 0.5 between their "
        "centres, the 3:2 and 2:1 ones to "
     << runs::significant_text(is.overlap_3_2_to_2, 3)
     << " times (Chirikov's criterion: overlap above 1): the 3:2 centre lies inside the 1:1 resonance's width, and the estimate's "
        "chaotic band, "
     << runs::fixed_text(is.band_lo, 2) << "–" << runs::fixed_text(is.band_hi, 2) << " n, lies within the measured zone.\n\n";
  std::string regular_turns;
  for (const double t : is.regular_turns) regular_turns += (regular_turns.empty() ? "" : ", ") + runs::significant_text(t, 4);
  md << "Starts on a finer grid through both 3:2 orbits (θ₀ = 0 and π/2, θ'₀ = 1.2 to 2.1 n in steps of " << is.grid_step << ", " << bu.orbits
     << " orbits each): " << is.regular << " of " << is.starts << " are regular"
     << (is.regular ? ", with mean rates " + regular_turns + " n (none is a 3:2 libration)" : "") << ".\n\n";
}

void hyperion_section(report_section& s, std::ostringstream& md, const report_options& o, const budget& bu) {
  if (o.progress) o.progress("Spin-orbit: Hyperion's surface of section");
  const auto sum = runs::hyperion_section_study(bu.rate_step, bu.orbits, bu.steps_per_orbit);
  const auto& sec = sum.section;
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
    pts.z.push_back(std::min(sec.lyapunov[static_cast<std::size_t>(sec.trajectory[i])], 0.6));  // the colour scale's top
  }
  c.series.push_back(std::move(pts));
  md << "### Hyperion: the planar surface of section (Wisdom, Peale & Mignard 1984)\n\n"
     << "With obliquity 0 the scene is the planar problem θ'' = −(3/2)((B − A)/C) r⁻³ sin 2(θ − f). " << sum.starts.size()
     << " starts at pericentre (θ₀ = 0 and π/2, θ'₀ from 0.2 to 3 n in steps of " << bu.rate_step << ") are followed for " << bu.orbits
     << " orbits by SIER4 at h = 1/" << bu.steps_per_orbit
     << " orbit; each point is one pericentre passage, coloured by the start's Lyapunov exponent (two trajectories 1e-9 apart, "
        "renormalised every orbit). A regular orbit's finite-time estimate decays like log(N)/N ("
     << runs::significant_text(sum.regular_floor, 2) << " per orbit at N = " << bu.orbits << "), so an exponent above "
     << chaos_threshold << " per orbit marks chaos: " << sum.chaotic << " of " << sum.starts.size() << " starts are chaotic, the largest exponent is "
     << runs::significant_text(sum.largest, 3) << " per orbit (a Lyapunov time of " << runs::significant_text(sum.lyapunov_time_orbits, 3) << " orbits, "
     << runs::significant_text(sum.lyapunov_time_days, 3) << " days). Chaotic starts: θ₀ = 0 at θ'₀/n = " << rates_text(sum.chaotic_rates[0])
     << "; θ₀ = π/2 at θ'₀/n = " << rates_text(sum.chaotic_rates[1]) << ". The chaotic orbits' pericentre rates fill "
     << runs::fixed_text(sum.zone_lo, 2) << " to " << runs::fixed_text(sum.zone_hi, 2)
     << " n: one zone from almost no rotation to nearly two and a half turns per orbit around the synchronous island, as Wisdom, "
        "Peale & Mignard (1984) found (and Wisdom 1987, AJ 94, 1350, describes: a quote).\n\n";
  add_chart(s, md, o, "spin_orbit_hyperion_section", c, "Hyperion's planar surface of section, coloured by the Lyapunov exponent.");
  islands(md, o, bu);

  // the synchronous periodic orbit and its tilt instability
  if (o.progress) o.progress("Spin-orbit: Hyperion's synchronous state in 3-D");
  const int tilt_orbits = o.quick ? 60 : 100;
  const auto tilt = runs::synchronous_tilt_study(tilt_orbits, bu.orbits, bu.steps_per_orbit);
  chart t;
  t.title = "Synchronous state tilted by 1e-6 rad: obliquity at pericentre";
  t.x_label = "orbits";
  t.y_label = "obliquity (rad)";
  t.log_x = false;
  chart_series hs{"Hyperion", {}, {}}, ls{"Moon", {}, {}};
  // a log axis: an obliquity of 0 is drawn at 1e-12
  for (std::size_t k = 0; k < tilt.obliquity.size(); ++k) hs.x.push_back(static_cast<double>(k + 1)), hs.y.push_back(std::max(tilt.obliquity[k], 1e-12));
  for (std::size_t k = 0; k < tilt.moon_obliquity.size(); ++k)
    ls.x.push_back(static_cast<double>(k + 1)), ls.y.push_back(std::max(tilt.moon_obliquity[k], 1e-12));
  t.series = {hs, ls};
  md << "**The synchronous state is attitude-unstable.** The symmetric synchronous periodic orbit (θ = 0 at pericentre, π at "
        "apocentre) starts at θ' = "
     << runs::significant_text(tilt.rate, 8) << " n for Hyperion; in the plane its Lyapunov estimate over " << bu.orbits << " orbits is "
     << runs::significant_text(tilt.planar_lyapunov, 3) << " per orbit (regular: the 1:1 island). Tilted by 1e-6 rad it leaves the plane: the obliquity "
     << "grows by a factor e every " << runs::significant_text(tilt.e_folding_orbits, 3) << " orbits (rate " << runs::significant_text(tilt.growth, 3)
     << " per orbit between 1e-5 and 1e-2 rad) and reaches " << runs::significant_text(tilt.obliquity.back(), 3) << " rad after " << tilt_orbits
     << " orbits, as WPM found. The Moon's synchronous state, tilted the same way, stays below " << runs::significant_text(tilt.moon_largest, 3)
     << " rad.\n\n";
  add_chart(s, md, o, "spin_orbit_synchronous_tilt", t, "Obliquity of the synchronous state tilted by 1e-6 rad: Hyperion and the Moon.");

  // Lyapunov estimates of 3-D states
  md << "Lyapunov estimates (" << bu.orbits << " orbits, SIER4 at h = 1/" << bu.steps_per_orbit << " orbit; 1 orbit = "
     << hyperion_period_days << " days, a quote):\n\n| Hyperion start | exponent per orbit | Lyapunov time (orbits) | (days) |\n|:--|--:|--:|--:|\n";
  for (const auto& st : runs::hyperion_state_exponents(tilt.rate, bu.orbits, bu.steps_per_orbit))
    md << "| " << st.what << " | " << runs::significant_text(st.exponent, 3) << " | "
       << (st.regular ? std::string("regular") : runs::significant_text(st.lyapunov_time_orbits, 3)) << " | "
       << (st.regular ? std::string("—") : runs::significant_text(st.lyapunov_time_days, 3)) << " |\n";
  md << "\nGoldberg et al. (2024, A&A 692, A9) argue that Hyperion is near a nutation–orbit resonance and rotates quasi-regularly, "
        "with chaos orders of magnitude weaker than WPM's (a quote). This scene has no tides, no Titan and the Voyager-era moments, "
        "and the starts above are not fitted to the observed spin state (about 4.2–4.5 n, the axis some 30° from the long axis, "
        "Harbison et al. 2011, a quote): the table says how chaotic these states of the model are, not which state Hyperion is in.\n\n";
}

void resonance_section(report_section& s, std::ostringstream& md, const report_options& o, const budget& bu) {
  if (o.progress) o.progress("Spin-orbit: Mercury in 3:2 and the Moon's libration");
  const auto lib = runs::forced_librations(bu.resonance_orbits);
  const auto& me = lib[0];
  const auto& mo = lib[1];
  const double arcsec = 180 * 3600 / pi;
  md << "### Mercury in 3:2 and the Moon's libration\n\n"
     << "Each starts on the symmetric periodic orbit of its resonance (θ = 0, the long axis towards the point mass, at pericentre and "
        "θ ≡ pπ at apocentre; spin rate at pericentre "
     << runs::significant_text(me.rate, 8) << " n for Mercury, " << runs::significant_text(mo.rate, 8) << " n for the Moon, found by bisection), so that no "
        "free libration is excited, "
     << bu.resonance_orbits << " orbits of SIER4 at h = 1/200 orbit. γ = θ − pM (mod π) is the resonant angle; its first "
        "harmonic (the discrete Fourier coefficient over each orbit, averaged over the orbits) is the forced libration, compared with first-order theory:\n\n"
     << "| body | p | max |γ| (rad) | forced amplitude | theory | ratio |\n|:--|--:|--:|--:|--:|--:|\n"
     << "| Mercury | 3/2 | " << runs::significant_text(me.run.max_excursion, 3) << " | " << runs::significant_text(me.run.forced_amplitude, 4) << " rad = "
     << runs::significant_text(me.run.forced_amplitude * arcsec, 3) << "″ | (3/2)((B − A)/C)(1 − 11e² + 959e⁴/48) = " << runs::significant_text(me.theory, 4)
     << " | " << runs::significant_text(me.ratio, 4) << " |\n"
     << "| Moon | 1 | " << runs::significant_text(mo.run.max_excursion, 3) << " | " << runs::significant_text(mo.run.forced_amplitude, 4) << " rad = "
     << runs::significant_text(mo.run.forced_amplitude * arcsec, 3) << "″ | 2eω₀²/(1 − ω₀²), ω₀² = 3(B − A)/C: " << runs::significant_text(mo.theory, 4)
     << " | " << runs::significant_text(mo.ratio, 4) << " |\n\n"
     << "Both stay in resonance (γ bounded). The theory for Mercury is that of a body whose mantle librates alone (Margot et al. "
        "2007 use (B − A)/C_m, about 2.3 times larger); the rigid scene uses the whole body's C, so its amplitude is the rigid "
        "planet's, not the observed 38.5″ (a quote, Margot et al. 2012).\n\n";
  chart c;
  c.title = "Resonant angle at pericentre: Mercury (3:2) and the Moon (1:1)";
  c.x_label = "orbits";
  c.y_label = "gamma = theta - p M (rad)";
  c.log_x = c.log_y = false;
  c.series = {chart_series{"Mercury, 3:2", me.run.orbit, me.run.gamma}, chart_series{"Moon, 1:1", mo.run.orbit, mo.run.gamma}};
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
  const auto panels = runs::spin_cost_study(steps, tols, o.full ? 0.05 : 0.005, [&](const std::string& line) {
    if (o.progress) o.progress(line);
  });
  for (const auto& panel : panels) {
    const auto& cs = panel.case_;
    chart c;
    c.title = "Spin-orbit, " + cs.label + ": attitude error against CPU time";
    c.x_label = "CPU seconds";
    c.y_label = "attitude error";
    md << "| " << cs.label << " | CPU for 1e-9 (s) |\n|:--|--:|\n";
    for (const auto& curve : panel.curves) {
      chart_series ser{curve.method, {}, {}};
      for (const auto& p : curve.points)
        if (p.error > 0) ser.x.push_back(p.cpu_s), ser.y.push_back(p.error);  // a log chart
      c.series.push_back(std::move(ser));
      md << "| " << curve.method << " | " << runs::scientific_or_dash(curve.cpu_at_1e9, 2) << " |\n";
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
  const auto drift = runs::spin_drift_study(last, [&](const std::string& line) {
    if (o.progress) o.progress(line);
  });
  md << "### Long runs: the attitude error\n\n"
     << "The rotation angle of Q_refᵀQ after " << drift.checkpoints.front() << " … " << last << " orbits, in double, against Odeint's RKF78 in "
        "long double at tolerance 1e-18 (bench/spin_drift_bench runs 10⁴ orbits and checks that reference against SIER4 in long double at "
        "a four times finer step: they agree to 1.5e-11 at 10⁴ orbits). RKF78 in double runs at the tolerance whose CPU time over "
        "100 orbits is nearest SIER4's (equal CPU).\n\n";
  for (const auto& table : drift.tables) {
    md << "| " << table.case_.label << ", h = 1/" << table.case_.steps_per_orbit << " orbit |";
    for (long n : drift.checkpoints) md << " " << n << " orbits |";
    md << " CPU s |\n|:--|";
    for (std::size_t i = 0; i <= drift.checkpoints.size(); ++i) md << "--:|";
    md << "\n";
    for (const auto& row : table.rows) {
      md << "| " << row.method << " |";
      for (const double e : row.error) md << " " << runs::scientific_or_dash(e, 2) << " |";
      md << " " << runs::significant_text(row.cpu_s, 3) << " |\n";
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
