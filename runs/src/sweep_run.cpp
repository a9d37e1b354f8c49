#include "rotlie/runs/sweep_run.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <sstream>

#include "ordered_lines.hpp"
#include "rotlie/runs/binary_fields.hpp"
#include "rotlie/runs/binary_io.hpp"
#include "rotlie/runs/binary_run.hpp"
#include "rotlie/runs/number_text.hpp"
#include "rotlie/runs/output_file.hpp"
#include "rotlie/runs/text_file.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::runs {

namespace {

using nlohmann::json;

constexpr int sweep_format_version = 1;
constexpr std::size_t input_limit = std::size_t(64) << 20;  // 64 MiB of runs
// A run's options and results nest a few levels (a state's rows of Q1 are three); the JSON library's
// writer recurses per level, so tens of thousands of them overflow the stack: refused before parsing.
constexpr int nesting_limit = 64;

// Whether no bracket of `line` lies deeper than `limit` (brackets inside strings are text).
bool nested_within(const std::string& line, int limit) {
  int depth = 0;
  bool in_string = false, escaped = false;
  for (const char c : line) {
    if (in_string) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) return false;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return true;
}

std::string fnv1a(const std::string& text) {
  std::uint64_t h = 1469598103934665603ull;
  for (const unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  char buffer[17];
  std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(h));
  return buffer;
}

// An option's value as the command line would have it: text as is, a number as JSON writes it.
std::string option_text(const json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); }

// A field a sweep line may give (runs/binary_fields.hpp), or nullptr.
const binary_field* sweep_field(const std::string& key) {
  const auto* f = binary_field_named(key);
  return f && f->sweep ? f : nullptr;
}

bool known_option(const std::string& key) { return sweep_field(key) != nullptr || binary_term_named(key) != nullptr; }

// A term's values: text, a number, or an array of numbers (as the command line's "A,B,…").
std::string term_text(const json& v) {
  if (!v.is_array()) return option_text(v);
  std::string text;
  for (const auto& x : v) text += (text.empty() ? "" : ",") + option_text(x);
  return text;
}

binary_request request_of(const json& j) {
  binary_request r;
  for (const auto& [key, value] : j.items()) {
    if (const auto* term = binary_term_named(key)) {
      r.terms[term->name] = term_text(value);
    } else if (const auto* f = sweep_field(key)) {
      if (f->type == binary_field::kind::flag)
        r.*f->flag = value.get<bool>();
      else if (f->type == binary_field::kind::state && value.is_object())
        r.state_text = value.dump();
      else
        r.*f->text = option_text(value);
    }
  }
  return r;
}

// A line as sweep_line writes it: binary's JSON (the fields every run has, of their kinds; a number
// that is not finite is written as null), or a run not made, with its reason.
bool is_result(const json& j) {
  const auto field = [&](const char* key, auto kind) { return j.contains(key) && kind(j[key]); };
  const auto text = [](const json& v) { return v.is_string(); };
  const auto number = [](const json& v) { return v.is_number(); };
  const auto number_or_null = [](const json& v) { return v.is_number() || v.is_null(); };
  const auto three = [](const json& v) {
    return v.is_array() && v.size() == 3 && std::all_of(v.begin(), v.end(), [](const json& x) { return x.is_number() || x.is_null(); });
  };
  if (j.contains("status")) {
    if (!field("status", text) || !field("error", text)) return false;
    const auto status = j["status"].get<std::string>();
    if (status == "contact") return field("contact_t", number);
    return status == "refused" || status == "failed";
  }
  return field("t", number) && field("r", three) && field("v", three) && field("energy", number_or_null) &&
         field("energy_start", number_or_null) && field("cpu_s", number) && field("unstable", [](const json& v) { return v.is_boolean(); }) &&
         field("warnings", [](const json& v) { return v.is_array(); });
}

int owner_of(std::size_t run, int processes) { return static_cast<int>(run % static_cast<std::size_t>(processes)); }

}  // namespace

sweep_plan plan_sweep(const std::filesystem::path& input) {
  std::string text;
  try {
    text = read_bounded_file(input, input_limit);
  } catch (const std::runtime_error& e) {
    throw bad_input("--in: " + one_line(e.what()));
  }
  sweep_plan plan;
  plan.input_hash = fnv1a(text);
  std::istringstream lines(text);
  std::string line;
  for (long number = 1; std::getline(lines, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::string where = "--in " + printable_path(input) + ", line " + std::to_string(number);
    if (!nested_within(line, nesting_limit))
      throw bad_input(where + ": nested deeper than " + std::to_string(nesting_limit) + " levels (a run's options nest a few)");
    const auto j = json::parse(line, nullptr, false);
    if (j.is_discarded() || !j.is_object()) throw bad_input(where + ": not a JSON object of binary's options");
    for (const auto& [key, value] : j.items()) {
      if (!known_option(key)) throw bad_input(where + ": '" + one_line(key) + "' is not an option of binary (a sweep takes no --every or --json)");
      const bool numbers = value.is_array() && binary_term_named(key) && std::all_of(value.begin(), value.end(), [](const json& x) { return x.is_number(); });
      const auto* f = sweep_field(key);
      const bool flag = f && f->type == binary_field::kind::flag;
      if (flag && !value.is_boolean()) throw bad_input(where + ": '" + key + "' must be true or false");
      const bool state = f && f->type == binary_field::kind::state && value.is_object();
      if (!(value.is_string() || value.is_number() || numbers || state || flag))
        throw bad_input(where + ": '" + one_line(key) + "' must be text or a number" + (binary_term_named(key) ? " (or an array of numbers)" : ""));
    }
    plan.inputs.push_back(j.dump());
  }
  if (plan.inputs.empty()) throw bad_input("--in " + printable_path(input) + " holds no runs");
  plan.done.assign(plan.inputs.size(), 0);
  return plan;
}

std::string sweep_header(const sweep_plan& plan) {
  nlohmann::ordered_json h = {{"rotlie_sweep", sweep_format_version}, {"runs", plan.inputs.size()}, {"input", plan.input_hash}};
  return h.dump();
}

resumed_map resume_sweep_file(const std::filesystem::path& path, const sweep_plan& plan) {
  resumed_map out;
  out.done.assign(plan.inputs.size(), 0);
  const map_file_text text = resumable_text(path, "result");
  out.whole_length = text.whole_length;
  const std::string refusal = "--resume: " + printable_path(path) + " ";
  for (std::size_t n = 0; n < text.lines.size(); ++n) {
    const std::string line_name = "line " + std::to_string(n + 1);
    if (!nested_within(text.lines[n], nesting_limit))
      throw bad_input(refusal + line_name + " is nested deeper than " + std::to_string(nesting_limit) +
                      " levels (not a line a sweep writes); it is left as it is");
    const auto j = json::parse(text.lines[n], nullptr, false);
    if (n == 0) {
      if (text.lines[n] != sweep_header(plan)) {
        const bool ours = !j.is_discarded() && j.is_object() && j.contains("rotlie_sweep");
        throw bad_input(refusal + (ours ? "holds the results of another input file (its header names another one)" : "is not a rotlie sweep file") +
                        "; it is left as it is");
      }
      out.has_header = true;
      continue;
    }
    const std::size_t index = n - 1;
    if (j.is_discarded() || !j.is_object() || !j.contains("index") || !j["index"].is_number_unsigned() || j["index"].get<std::size_t>() != index ||
        index >= plan.inputs.size())
      throw bad_input(refusal + line_name + " is not run " + std::to_string(index) + " of this sweep; it is left as it is");
    if (!is_result(j))
      throw bad_input(refusal + line_name + " holds no result of run " + std::to_string(index) +
                      " (neither binary's JSON nor a status of refused, contact or failed with its error); it is left as it is");
    out.done[index] = 1;
    out.lines.push_back(text.lines[n]);
  }
  return out;
}

std::string sweep_line(const sweep_plan& plan, std::size_t index) {
  const auto options = json::parse(plan.inputs.at(index));
  json line;
  try {
    const auto setup = binary_setup_of(request_of(options));
    line = binary_json(binary_run(setup));
  } catch (const bad_input& e) {
    line = {{"status", "refused"}, {"error", one_line(e.what())}};
  } catch (const binary_contact& e) {
    line = {{"status", "contact"}, {"error", one_line(e.what())}, {"contact_t", e.t}};
  } catch (const binary_unconfirmed_contact& e) {  // the step's error, not a physical outcome
    line = {{"status", "failed"}, {"error", one_line(e.what())}, {"inaccurate", true}};
  } catch (const std::exception& e) {
    line = {{"status", "failed"}, {"error", one_line(e.what())}};
  }
  nlohmann::ordered_json ordered = {{"index", index}};
  for (const auto& [key, value] : line.items()) ordered[key] = value;
  return ordered.dump();
}

void sweep_counts::count(const std::string& line) {
  const auto j = json::parse(line, nullptr, false);
  const bool marked = !j.is_discarded() && j.is_object() && j.contains("status") && j["status"].is_string();
  const std::string status = marked ? j["status"].get<std::string>() : "";
  if (status == "refused")
    ++refused;
  else if (status == "contact")
    ++contact;
  else if (status == "failed")
    ++failed;
  else
    ++computed;
}

std::string sweep_inputs_text(const sweep_plan& plan) {
  std::string text;
  for (const auto& input : plan.inputs) text += input + "\n";  // one line each: a JSON dump escapes its newlines
  return text;
}

sweep_plan sweep_plan_of(const std::string& inputs_text, std::vector<char> done) {
  sweep_plan plan;
  std::istringstream lines(inputs_text);
  for (std::string line; std::getline(lines, line);) plan.inputs.push_back(std::move(line));
  if (done.size() != plan.inputs.size())
    throw std::runtime_error("rank 0 sent " + std::to_string(plan.inputs.size()) + " runs with " + std::to_string(done.size()) + " marks of runs done");
  plan.done = std::move(done);
  return plan;
}

sweep_counts run_sweep_rank0(const sweep_plan& plan, map_processes& processes, const sweep_output& out) {
  static const resumed_map nothing_yet;
  map_file_writer file(out.path, out.existing ? *out.existing : nothing_yet, sweep_header(plan));
  std::vector<std::size_t> todo;
  for (std::size_t k = 0; k < plan.inputs.size(); ++k)
    if (!plan.done[k]) todo.push_back(k);
  sweep_counts counts;
  if (out.existing)
    for (const auto& line : out.existing->lines) counts.count(line);
  counts.now = todo.size();
  const std::function<void(const std::string&)> tally = [&counts](const std::string& line) { counts.count(line); };
  ordered_lines collected(todo, &file, &tally, nullptr);
  const auto start = std::chrono::steady_clock::now();
  const auto show = [&] {
    if (!out.progress) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::size_t done = collected.written();
    std::ostringstream s;
    s << "sweep: " << done << "/" << todo.size() << " runs on " << processes.size() << " process(es)";
    if (done > 0) s << ", about " << duration_text(elapsed / static_cast<double>(done) * static_cast<double>(todo.size() - done)) << " left";
    out.progress(s.str());
  };
  int workers_left = processes.size() - 1;
  const auto drain = [&](bool wait) {
    auto d = processes.receive(wait);
    for (auto& m : d.lines) collected.add(m.index, std::move(m.payload));
    workers_left -= d.done;
  };
  for (const std::size_t k : todo) {
    if (owner_of(k, processes.size()) != 0) continue;
    collected.add(k, sweep_line(plan, k));
    if (processes.size() > 1) drain(false);
    show();
  }
  while (workers_left > 0) {
    drain(true);
    show();
  }
  if (!collected.complete()) throw std::runtime_error("a process of the MPI job did not deliver all its runs");
  file.finish();
  return counts;
}

void run_sweep_worker(const sweep_plan& plan, map_processes& processes) {
  for (std::size_t k = 0; k < plan.inputs.size(); ++k)
    if (!plan.done[k] && owner_of(k, processes.size()) == processes.rank()) processes.send_results({{k, sweep_line(plan, k)}});
  processes.send_done();
}

}  // namespace rotlie::runs
