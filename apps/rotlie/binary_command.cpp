// binary: two rigid bodies in mutual gravity (the full two-body problem of binary asteroids), any of
// its integrators: the final state, the mutual gravity there, the conserved quantities' errors.
// --every K's trajectory goes to --out FILE (JSON lines, CSV or .npz, written whole at the end) or, with --json and no --out,
// to standard output as JSON lines before the summary's line; never beside the text summary.
#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <utility>
#include <vector>

#include "arguments.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "rotlie/runs/binary_fields.hpp"
#include "rotlie/runs/binary_io.hpp"
#include "rotlie/runs/binary_run.hpp"
#include "rotlie/runs/gubas_config.hpp"
#include "rotlie/runs/npz_file.hpp"
#include "rotlie/runs/output_file.hpp"

namespace rotlie::app {

namespace {

// A sample's fields in the order of its JSON line and of the CSV's columns.
constexpr std::array<const char*, 8> sample_fields = {"t", "r", "v", "Q1", "Q2", "omega1", "omega2", "energy"};

// A number as the JSON lines write it (shortest round trip); nan, inf, -inf where JSON has null.
std::string csv_number(const nlohmann::json& x) {
  const double v = x.is_number() ? x.get<double>() : std::nan("");
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return nlohmann::json(v).dump();
}

// Each column of a sample in order, its name and its value: a number as is, a vector's components
// r_x, r_y, r_z, a matrix's entries by row Q1_11, Q1_12, … Q1_33.
void for_each_column(const nlohmann::json& sample, const std::function<void(const std::string&, const nlohmann::json&)>& column) {
  static const char* const axes[] = {"x", "y", "z"};
  for (const char* name : sample_fields) {
    const auto& value = sample.at(name);
    if (!value.is_array()) {
      column(name, value);
      continue;
    }
    for (std::size_t i = 0; i < value.size(); ++i) {
      if (!value[i].is_array()) {
        column(std::string(name) + "_" + (i < 3 ? axes[i] : std::to_string(i + 1)), value[i]);
        continue;
      }
      for (std::size_t k = 0; k < value[i].size(); ++k) column(std::string(name) + "_" + std::to_string(i + 1) + std::to_string(k + 1), value[i][k]);
    }
  }
}

// One CSV row of a sample, or with `header` its column names.
std::string csv_row(const nlohmann::json& sample, bool header) {
  std::string row;
  for_each_column(sample, [&](const std::string& name, const nlohmann::json& value) { row += (row.empty() ? "" : ",") + (header ? name : csv_number(value)); });
  return row + "\n";
}

bool ends_with(const std::string& path, const std::string& suffix) {
  return path.size() >= suffix.size() && path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The --out file: JSON lines; CSV with a header line when its name ends in .csv; NumPy's .npz (one
// float64 array per CSV column, runs/npz_file.hpp) when it ends in .npz, its columns held in memory
// until the end. Nothing is in place until commit(): a run that fails leaves the file as it was.
class trajectory_file {
 public:
  enum class format { json_lines, csv, npz };

  explicit trajectory_file(const std::string& path)
      : format_(ends_with(path, ".csv") ? format::csv : ends_with(path, ".npz") ? format::npz : format::json_lines) {
    try {
      file_ = std::make_unique<runs::output_file_stream>(path);
    } catch (const std::runtime_error& e) {  // a folder, a FIFO, a missing folder: nothing computed
      throw usage_error("--out: " + std::string(e.what()));
    }
  }
  void add(const nlohmann::json& sample) {
    if (format_ == format::npz) {
      std::size_t k = 0;
      for_each_column(sample, [&](const std::string& name, const nlohmann::json& value) {
        if (columns_.size() == k) columns_.push_back({name, {}});
        columns_[k++].second.push_back(value.is_number() ? value.get<double>() : std::nan(""));
      });
      return;
    }
    if (format_ == format::csv && first_) file_->write(csv_row(sample, true));
    first_ = false;
    file_->write(format_ == format::csv ? csv_row(sample, false) : sample.dump() + "\n");
  }
  void commit() {
    if (format_ == format::npz) {
      try {
        file_->write(runs::npz_of_columns(columns_));
      } catch (const std::length_error& e) {
        throw std::runtime_error("--out: " + std::string(e.what()) + "; write a .csv instead");
      }
    }
    file_->commit();
  }

 private:
  format format_;
  bool first_ = true;
  std::unique_ptr<runs::output_file_stream> file_;
  std::vector<std::pair<std::string, std::vector<double>>> columns_;  // .npz: each column's values so far
};

// The request as typed, on top of what --gubas-config sets: an option the config sets, or one that
// describes the bodies or the start another way, is refused beside it rather than silently preferred.
runs::binary_request request_of(const binary_options& o) {
  runs::binary_request request;
  std::map<std::string, std::string> from_config;
  if (!o.gubas_config.empty()) {
    auto mapped = runs::read_gubas_config(o.gubas_config);
    request = std::move(mapped.request);
    from_config = std::move(mapped.source);
  }
  for (const auto& f : runs::binary_fields()) {
    if (f.type == runs::binary_field::kind::flag) {
      request.*f.flag = o.flags.at(f.name);
      continue;
    }
    const bool given = o.given.count(f.name) > 0;
    if (given && from_config.count(f.name))
      throw usage_error(f.option + " is set by --gubas-config (from GUBAS's '" + from_config.at(f.name) + "'): give one of them");
    if (given && !o.gubas_config.empty() && (f.name == "system" || f.name == "mass" || f.name == "separation" || f.name == "primary_period"))
      throw usage_error(f.option + " and --gubas-config exclude each other (the config gives the bodies, their densities and the start)");
    if (given || o.gubas_config.empty()) request.*f.text = o.fields.at(f.name);
    if (f.cli_required && !given && o.gubas_config.empty()) throw usage_error(f.option + " is required");
  }
  return request;
}

}  // namespace

int run_binary(const binary_options& o) {
  auto request = request_of(o);
  for (const auto& [name, text] : o.terms)
    if (!text.empty()) request.terms[name] = text;
  const auto setup = runs::binary_setup_of(request);
  if (setup.every > 0 && o.out.empty() && !o.json)
    throw usage_error("--every writes a trajectory, which does not go beside the text summary: add --out FILE (or --json, for "
                      "JSON lines on stdout before the summary's line)");
  if (setup.every == 0 && !o.out.empty()) throw usage_error("--out FILE is --every's trajectory file: add --every K");
  std::unique_ptr<trajectory_file> trajectory;
  if (!o.out.empty()) trajectory = std::make_unique<trajectory_file>(o.out);
  const bool lines_on_stdout = setup.every > 0 && !trajectory;

  const auto sys = setup.system_model();
  progress_line progress;  // on a terminal only
  const auto r = runs::binary_run(
      setup,
      [&](const runs::binary_sample& s) {
        const auto sample = runs::binary_sample_json(s, sys);
        if (trajectory)
          trajectory->add(sample);
        else
          std::cout << sample.dump() << "\n";
      },
      [&](double done) { progress.show("binary: " + std::to_string(static_cast<int>(100 * done)) + " % of " + std::to_string(setup.steps) + " steps"); });
  if (trajectory) trajectory->commit();
  for (const auto& w : r.check.warnings) std::cerr << "rotlie: warning: " << w << "\n";
  if (o.json)
    std::cout << (lines_on_stdout ? runs::binary_json(r).dump() : runs::binary_json(r).dump(2)) << "\n";
  else
    std::cout << runs::binary_text(r);
  return 0;
}

}  // namespace rotlie::app
