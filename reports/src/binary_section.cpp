// Report section "Binary asteroid" (issue 33, docs/binary.md): two rigid bodies in mutual gravity, the
// Didymos system. The benchmark's observables from two starts (the circular start that balances the
// mutual pull, and the public GUBAS example's start), the period change of an impulsive Δv on the
// secondary at DART's geometry, and error against CPU time for every integrator at orders 2 and 4.
// Every number is runs::'s (didymos_study.hpp, binary_study.hpp); the section formats and draws.
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

#include "rotlie/reports/chart.hpp"
#include "rotlie/reports/report.hpp"
#include "rotlie/reports/section_writer.hpp"
#include "rotlie/runs/didymos_study.hpp"
#include "rotlie/runs/number_text.hpp"
#include "sections.hpp"

namespace rotlie::reports {
namespace {

constexpr double hour = 3600;

// Quotes: the observed system (not computed here).
constexpr double observed_period_h = 11.921473;   // Dimorphos's pre-impact orbit (Scheirich & Pravec 2022)
constexpr double observed_change_min = -33.0;     // ± 1.0 min (Thomas et al. 2023, Nature 616, 448)
constexpr double observed_primary_h = 2.2600;     // Didymos's rotation (Pravec et al. 2006)
// DART's momentum transfer (Cheng et al. 2023, Nature 616, 457): mass and speed at impact, and β
constexpr runs::dart_impact dart{579.4, 6.1449, 3.61};

void benchmark_table(std::ostringstream& md, const report_options& o, double days) {
  if (o.progress) o.progress("Binary asteroid: the Didymos benchmark");
  const double T = runs::didymos_span_s(days);
  md << "### The Didymos system\n\n"
     << "`--system didymos`: the secondary 103.16 × 79.35 × 66.13 m, both bodies of density 2203.1 kg/m³, 1.2 km apart, the primary "
        "spinning in 2.26 h (the public GUBAS example configuration) and the primary an ellipsoid 398.88 × 391.30 × 383.48 m (GUBAS's "
        "Perturbed-Model configuration; the example's primary is a shape model). Agrusa et al. (2020)'s benchmark parameters and results "
        "were not available to us; docs/binary.md sets GUBAS's own run of this setup beside rotlie's. Read over "
     << runs::significant_text(T / 86400, 3) << " days by KEPLER4 at h = 60 s, sampled every 5 minutes:\n\n"
     << "| start | order | mutual orbit (h) | separation (km) | libration of the secondary (°) | its period (h) | primary's spin (h) |\n"
        "|:--|--:|--:|--:|--:|--:|--:|\n";
  for (const auto& row : runs::didymos_benchmark(T)) {
    const auto& ob = row.observed;
    md << "| " << (row.gubas_start ? "GUBAS example (0.1757 m/s)" : "circular, balanced") << " | " << row.order << " | "
       << runs::significant_text(ob.orbit_period_h, 6) << " | " << runs::significant_text(ob.separation_min_km, 5) << " – "
       << runs::significant_text(ob.separation_max_km, 5) << " | " << runs::significant_text(ob.libration_mean_deg, 3) << " ± "
       << runs::significant_text(ob.libration_amplitude_deg, 3) << " | "
       << (ob.libration_period_h > 0 ? runs::significant_text(ob.libration_period_h, 4) : std::string("–")) << " | "
       << runs::significant_text(ob.primary_period_h, 6) << " |\n";
  }
  md << "\nObserved (quotes): the mutual orbit " << observed_period_h << " h before the impact (Scheirich & Pravec 2022), the primary's "
     << "rotation " << observed_primary_h << " h (Pravec et al. 2006). The circular start is a relative equilibrium for an axisymmetric "
        "primary: its libration is what the primary's small triaxiality and the fourth-degree terms force. The GUBAS start is not balanced "
        "for these ellipsoids: the secondary librates freely about the line of centres.\n\n";
}

void dart_table(std::ostringstream& md, const report_options& o, double days) {
  if (o.progress) o.progress("Binary asteroid: an impulsive Δv at DART's geometry");
  const double T = runs::didymos_span_s(days);
  const auto d = runs::dart_period_change(dart, T);
  md << "### DART, as a worked example\n\n"
     << "An impulsive Δv on the secondary against its orbital motion, at the circular start (order 4, KEPLER4 at h = 60 s, the "
        "period read over "
     << runs::significant_text(T / 86400, 3) << " days). Δv from DART's momentum, β m U / M₂ with m = " << dart.mass_kg << " kg, U = "
     << dart.speed_km_s << " km/s and β = " << dart.beta << " (Cheng et al. 2023, quotes) and this model's M₂ = "
     << runs::scientific_or_dash(d.secondary_mass_kg, 4) << " kg:\n\n| Δv (mm/s) | mutual orbit (h) | change (min) |\n|--:|--:|--:|\n"
     << "| 0 | " << runs::significant_text(d.period_before_h, 6) << " | – |\n";
  for (const auto& r : d.rows)
    md << "| " << runs::significant_text(r.dv_km_s * 1e6, 3) << " | " << runs::significant_text(r.period_h, 6) << " | "
       << runs::significant_text(r.change_min, 4) << " |\n";
  md << "\nObserved (quote): " << observed_change_min << " ± 1.0 min (Thomas et al. 2023). The model leaves out what the impact did "
        "besides the push: the ejecta's momentum not along the orbit, Dimorphos's mass loss and reshaping (which changes its "
        "moments and the mutual potential), the real shapes (shape models instead of ellipsoids), the Sun's tide and radiation "
        "(BYORP); and this model's Dimorphos, of Didymos's density, is heavier than the observed estimate, so the same β gives a "
        "smaller Δv.\n\n";
}

void beta_table(std::ostringstream& md, const report_options& o, double days) {
  if (o.progress) o.progress("Binary asteroid: DART's beta and Dimorphos's excitation");
  const double T = runs::didymos_span_s(days);
  const std::vector<double> betas = o.quick ? std::vector<double>{1, 3, 5} : std::vector<double>{1, 1.5, 2, 2.5, 3, 3.5, 4, 4.5, 5};
  const double tilt_deg = 3;
  const auto d = runs::dart_beta_sweep(dart, betas, dart.beta, tilt_deg, observed_change_min, T);
  md << "### DART's β and the secondary's excitation\n\n"
     << "The same push at each momentum enhancement β along the track, and once at β = " << dart.beta << " turned " << tilt_deg
     << "° out of the orbit plane (the same start, span and integrator). The libration is the secondary's long axis against the "
        "line of centres (half its range); the tumbling measure is the largest angle between its angular momentum and its "
        "maximum-moment axis, tumbling above "
     << runs::significant_text(runs::default_tumbling_threshold_deg, 2) << "°:\n\n"
     << "| β | tilt (°) | Δv (mm/s) | period change (min) | libration (°) | G off the spin axis (°) | tumbling |\n|--:|--:|--:|--:|--:|--:|:--|\n";
  for (const auto& r : d.rows)
    md << "| " << r.beta << " | " << r.tilt_deg << " | " << runs::significant_text(r.dv_km_s * 1e6, 3) << " | " << runs::significant_text(r.change_min, 4)
       << " | " << runs::significant_text(r.libration_amplitude_deg, 3) << " | " << runs::scientific_or_dash(r.npa_angle_max_deg, 2) << " | "
       << (r.tumbling ? "yes" : "no") << " |\n";
  md << "\n";
  if (d.beta_for_target > 0)
    md << "The observed " << observed_change_min << " min needs β ≈ " << runs::significant_text(d.beta_for_target, 3)
       << " in this model (interpolated along the table). ";
  md << "The period change is nearly linear in β; a push in the orbit plane keeps the secondary's spin planar (no tumbling), "
        "one out of it lets the roll and pitch grow (a tumbling Dimorphos: Agrusa et al. 2021's subject). The charts, the "
        "distribution under the published uncertainties of β, mass and direction on MPI ranks, and the time series of the Euler "
        "angles: examples/python/dart_beta_sweep.py and docs/binary.md.\n\n";
}

void cost_tables(report_section& s, std::ostringstream& md, const report_options& o) {
  const double orbits = o.full ? 1000 : o.quick ? 2 : 10;
  const auto plan = runs::didymos_cost_plan(orbits, o.quick);
  const auto result = runs::binary_cost_study(plan, [&](const std::string& line) {
    if (o.progress) o.progress(line);
  });
  md << "### Error against CPU time\n\n"
     << "The Didymos system from the circular start over " << runs::significant_text(plan.T / hour, 4) << " h (" << orbits << " × 11.73 h), "
     << "each integrator at h = ";
  for (std::size_t k = 0; k < plan.steps.size(); ++k) md << (k ? ", " : "") << plan.steps[k];
  md << " s and Odeint's RKF78 at three tolerances (checked every 480 s). The error is the largest of |Δr|/|r| and the two bodies' "
        "attitude angles (rad) at the end, against KEPLER4 at h = 7.5 s (its own error, against h = 3.75 s: ";
  for (std::size_t k = 0; k < plan.orders.size(); ++k)
    md << (k ? ", " : "") << runs::scientific_or_dash(result.reference_error[k], 2) << " at order " << plan.orders[k];
  md << "). CPU is the stepping's (the conserved quantities' checks left out), one core.\n\n";
  for (std::size_t k = 0; k < plan.orders.size(); ++k) {
    const int order = plan.orders[k];
    md << "| order " << order << " | h (s) | steps | gravity evaluations | CPU (s) | error | energy | angular momentum |\n|:--|--:|--:|--:|--:|--:|--:|--:|\n";
    std::map<std::string, chart_series> series;
    for (const auto& r : result.rows) {
      if (r.order != order) continue;
      md << "| " << r.integrator << " | " << r.h << " | " << r.steps << " | " << r.evaluations << " | " << runs::scientific_or_dash(r.cpu_s, 3) << " | "
         << runs::scientific_or_dash(r.error, 2) << (r.unstable ? " (unstable)" : "") << " | " << runs::scientific_or_dash(r.energy_error, 2) << " | "
         << runs::scientific_or_dash(r.angular_momentum_error, 2) << " |\n";
      // one curve per integrator, RKF78's tolerances on one; a log chart leaves out the points it cannot place
      const std::string family = r.integrator.rfind("odeint-rkf78", 0) == 0 ? "odeint-rkf78" : r.integrator;
      auto& ser = series[family];
      ser.name = family;
      if (r.error > 0 && std::isfinite(r.error) && r.cpu_s > 0) ser.x.push_back(r.cpu_s), ser.y.push_back(r.error);
    }
    md << "\n";
    chart c;
    c.title = "Didymos, order " + std::to_string(order) + ": error against CPU time";
    c.x_label = "CPU seconds";
    c.y_label = "error (relative position, attitude angles)";
    for (auto& [name, ser] : series) c.series.push_back(std::move(ser));
    add_chart(s, md, o, "binary_cost_order" + std::to_string(order), c, "Error against CPU time at order " + std::to_string(order) + ".");
    // the goals' ratios: at the LGVI's error with h = 30 s, and at RKF78's tightest error
    for (const auto& [anchor, h] : {std::pair<std::string, double>{"LGVI", 30}, {"odeint-rkf78:1e-13", plan.adaptive_h}}) {
      const auto cheapest = runs::cheapest_splitting_at(result, order, anchor, h);
      if (!cheapest) continue;
      md << "At the error of " << anchor << (anchor == "LGVI" ? " with h = 30 s" : "") << " (" << runs::scientific_or_dash(cheapest->anchor.error, 2) << ", "
         << runs::scientific_or_dash(cheapest->anchor.cpu_s, 3) << " s): ";
      if (cheapest->found)
        md << "the cheapest splitting that reaches it is " << cheapest->best.integrator << " at h = " << cheapest->best.h << " s ("
           << runs::scientific_or_dash(cheapest->best.error, 2) << ", " << runs::scientific_or_dash(cheapest->best.cpu_s, 3) << " s): "
           << runs::significant_text(cheapest->cpu_ratio, 3)
           << (cheapest->less_cpu ? "× less CPU" : "× more CPU (over this span; docs/binary.md has 10⁴ orbits)") << ".\n\n";
      else
        md << "no splitting step of this sweep reaches it.\n\n";
    }
  }
}

// Every registered force term at its example values: drawn from the registry, so a new term appears here
// with no edit to this section.
void terms_table(std::ostringstream& md, double days) {
  const auto effects = runs::didymos_term_effects(days * 86400);
  if (effects.empty()) return;
  md << "### Added force terms\n\n"
     << "Each registered term (docs/binary.md) at its example values on the Didymos system, KEPLER4 at order 4 with h = 60 s over " << days
     << " days, against the same run without it.\n\n| term | values | end position change (km) | orbit phase change (deg) | its values at the end |\n"
        "|:--|:--|--:|--:|:--|\n";
  for (const auto& e : effects)
    md << "| " << e.name << " | " << e.values << " | " << runs::scientific_or_dash(e.separation_change_km, 3) << " | "
       << runs::scientific_or_dash(e.phase_change_deg, 3) << " | `" << e.values_at_end << "` |\n";
  md << "\n";
}

}  // namespace

report_section binary_section(const report_options& options) {
  report_section s;
  s.title = "Binary asteroid";
  std::ostringstream md;
  md << "## " << s.title << "\n\n"
     << "Two rigid bodies in mutual gravity, rotation and orbit coupled both ways (the full two-body problem; `rotlie binary`, "
        "docs/binary.md): the mutual potential expanded in the bodies' inertia integrals to any total degree (here 2 to 8; Hou, Scheeres "
        "& Xin 2017), integrated by TV splittings with each body's exact free rotation (SIER2, SIER4, SIER6), the same with the point masses' "
        "Kepler orbit as the drift (KEPLER2, KEPLER4, KEPLER6), and the methods of GUBAS: the Lie-group variational integrator (LGVI), RK4 and an "
        "adaptive RK 7(8).\n\n";
  const double days = options.quick ? 2 : options.full ? 30 : 6;
  benchmark_table(md, options, days);
  dart_table(md, options, days);
  beta_table(md, options, days);
  cost_tables(s, md, options);
  terms_table(md, days);
  s.markdown = md.str();
  return s;
}

}  // namespace rotlie::reports
