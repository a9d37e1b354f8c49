// The library floor (rotlie::runs) from a program of one's own: name a body, ask for its best
// dedicated integrator by analytic remainder, name that scheme (solved for the body on the fly),
// step the body with it and measure the error against the exact flow, Exits non-zero unless the dedicated scheme is of
// order 4 here (its error falls by about 16 when h halves).
//
//   best_and_step [BODY]        BODY: I1,I2,I3 (exact numbers) or water (default)
#include <cmath>
#include <exception>
#include <iostream>
#include <string>

#include "rotlie/runs/best_for_body.hpp"
#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/free_body_runs.hpp"
#include "rotlie/runs/numeric_inputs.hpp"
#include "rotlie/runs/user_input.hpp"

int main(int argc, char** argv) {
  namespace runs = rotlie::runs;
  try {
    const std::string body_text = argc > 1 ? argv[1] : "water";
    const auto body = runs::best_body(body_text);  // bad_input for a symmetric top or bad text
    const auto best = runs::best_for_body(body, /*analytic_only=*/true);
    std::cout << "body " << body_text << ": recommended " << best.recommended << "\n";

    const auto G0 = runs::initial_momentum("1,1,1");
    const auto dedicated = runs::free_body_of(best.recommended, body_text, runs::foreign_table::refuse);
    double previous = 0;
    for (const double h : {1.0 / 64, 1.0 / 128}) {
      const auto r = runs::integrate_run(dedicated, G0, h, 1.0);
      std::cout << "  " << r.scheme << "  h = " << h << "  mean attitude error " << r.point.error << "\n";
      if (previous > 0 && previous / r.point.error < 12) {
        std::cerr << "best_and_step: the error fell by " << previous / r.point.error << " only, not about 16\n";
        return 1;
      }
      previous = r.point.error;
    }
    return 0;
  } catch (const rotlie::runs::bad_input& e) {
    std::cerr << "best_and_step: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "best_and_step: " << e.what() << "\n";
    return 1;
  }
}
