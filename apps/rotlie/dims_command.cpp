#include <iostream>

#include "arguments.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "rotlie/lie/lie_poisson_algebra.hpp"
#include "rotlie/runs/lie_tables_io.hpp"

namespace rotlie::app {

int run_dims(const dims_options& options) {
  const int max_order =
      static_cast<int>(parse_integer_in_range(options.max_order, "--max-order", 1, lie::max_supported_order));
  progress_line progress;
  lie::algebra_options algebra;
  algebra.exact_only = options.exact;
  algebra.on_order = [&](const lie::graded_piece& p) {
    progress.show("order " + std::to_string(p.order) + "/" + std::to_string(max_order));
  };
  const auto pieces = lie::lie_poisson_algebra(max_order, algebra);
  print_answer(options.json, [&] { return runs::dims_json(pieces); }, [&] { return runs::dims_text(pieces); });
  return 0;
}

}  // namespace rotlie::app
