#pragma once
// Writers for the dimension table and Table 1: plain text for the terminal, markdown and
// LaTeX for the report, JSON for machines. The libraries compute; these only format.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "rotlie/lie/lie_poisson_algebra.hpp"
#include "rotlie/lie/stage_table.hpp"

namespace rotlie::runs {

nlohmann::json dims_json(const std::vector<lie::graded_piece>& pieces);
std::string dims_text(const std::vector<lie::graded_piece>& pieces);
std::string dims_markdown(const std::vector<lie::graded_piece>& pieces);

nlohmann::json stages_json(const std::vector<lie::stage_block>& blocks);
std::string stages_text(const std::vector<lie::stage_block>& blocks);
std::string stages_markdown(const std::vector<lie::stage_block>& blocks);
std::string stages_latex(const std::vector<lie::stage_block>& blocks);

}  // namespace rotlie::runs
