#include <chrono>
#include <sstream>

#include "rotlie/lie/lie_poisson_algebra.hpp"
#include "rotlie/lie/stage_table.hpp"
#include "rotlie/runs/lie_tables_io.hpp"
#include "rotlie/reports/output_file.hpp"
#include "rotlie/reports/report.hpp"

namespace rotlie::reports {
namespace {

constexpr int paper_table_orders = 10;  // Table 1 of the paper stops at order 10

}  // namespace

report_section lie_algebra_section(const report_options& options) {
  const int max_order = options.quick ? 20 : 40;
  if (options.progress) options.progress("Lie algebra: dimensions of L_k up to order " + std::to_string(max_order));

  const auto start = std::chrono::steady_clock::now();
  const auto pieces = lie::lie_poisson_algebra(max_order);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::vector<std::size_t> dims;
  bool all_theorems = true, all_attained = true;
  for (const auto& p : pieces) {
    dims.push_back(p.dimension);
    all_theorems = all_theorems && p.theorem1 && p.theorem2.value_or(true);
    all_attained = all_attained && p.bound_attained();
  }
  const auto blocks = lie::stage_table(paper_table_orders, dims);

  report_section s;
  s.title = "Lie algebra of the free rigid body";
  const auto& dir = options.out_dir;
  auto write = [&](const std::string& name, const std::string& content) {
    write_file_atomically(dir / name, content);
    s.files.push_back(dir / name);
  };
  write("dims.json", runs::dims_json(pieces).dump(2) + "\n");
  write("dims.md", runs::dims_markdown(pieces));
  write("table1.json", runs::stages_json(blocks).dump(2) + "\n");
  write("table1.md", runs::stages_markdown(blocks));
  write("table1.tex", runs::stages_latex(blocks));

  std::ostringstream md;
  md << "## " << s.title << "\n\n"
     << "L_1 = span(G1², G2², G3²), L_{k+1} = span{ {G_i², v} : v ∈ L_k } with {G_i, G_j} = ε_ijk G_k (eq. 16).\n"
     << "Orders 1–" << max_order << " computed in " << std::fixed;
  md.precision(3);
  md << seconds << " s. Theorem 1 (eqs. 23–24) and Theorem 2 (eq. 28) "
     << (all_theorems ? "hold at every order" : "FAIL at some order (see the table)") << "; the Theorem 1–2 upper bound "
     << (all_attained ? "is attained at every order" : "is NOT attained at some order") << ", so the dimensions the paper "
     << "uses as upper bounds beyond order 5 are the true dimensions.\n\n"
     << "An order marked `certificate` has its rank established by a rank modulo the prime 2^61 − 1 (a lower bound "
        "over Q) equal to the Theorem 1–2 bound (an upper bound, because every spanning vector was checked exactly "
        "to satisfy both theorems).\n\n"
     << "Files: [dims.md](dims.md), [dims.json](dims.json).\n\n"
     << runs::dims_markdown(pieces) << "\n"
     << "### Table 1 (regenerated)\n\n"
     << "Files: [table1.md](table1.md), [table1.tex](table1.tex), [table1.json](table1.json). Rigid-body stage "
        "counts follow the paper's rules (N equations → N stages; symmetric: 2N_sym − 1 stages); the general blocks' "
        "stage columns are literature values the paper quotes, marked as such.\n\n"
     << runs::stages_markdown(blocks) << "\n";
  s.markdown = md.str();
  return s;
}

}  // namespace rotlie::reports
