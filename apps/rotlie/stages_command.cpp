#include <iostream>

#include "arguments.hpp"
#include "commands.hpp"
#include "rotlie/lie/lie_poisson_algebra.hpp"
#include "rotlie/lie/stage_table.hpp"
#include "rotlie/runs/lie_tables_io.hpp"

namespace rotlie::app {

int run_stages(const stages_options& options) {
  const int max_order =
      static_cast<int>(parse_integer_in_range(options.max_order, "--max-order", 1, lie::max_stage_table_order));
  std::vector<std::size_t> dims;
  for (const auto& p : lie::lie_poisson_algebra(max_order)) dims.push_back(p.dimension);
  const auto blocks = lie::stage_table(max_order, dims);
  print_answer(options.json, [&] { return runs::stages_json(blocks); }, [&] { return runs::stages_text(blocks); });
  return 0;
}

}  // namespace rotlie::app
