#pragma once
// What rank 0 of a shared run does with the lines: a map's bodies (map_run.cpp) and a sweep's runs
// (sweep_run.cpp) arrive from any process in any order and are written in their own order.
#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "rotlie/runs/map_file.hpp"

namespace rotlie::runs {

/// Rank 0's collector: lines arrive in any order and leave in the order of `todo` (to the file, the
/// echo and the kept lines, each optional).
class ordered_lines {
 public:
  ordered_lines(std::vector<std::size_t> todo, map_file_writer* file, const std::function<void(const std::string&)>* echo,
                std::vector<std::string>* keep)
      : todo_(std::move(todo)), file_(file), echo_(echo), keep_(keep) {}
  void add(std::size_t index, std::string line) {
    pending_.emplace(index, std::move(line));
    while (next_ < todo_.size()) {
      const auto found = pending_.find(todo_[next_]);
      if (found == pending_.end()) break;
      if (file_) file_->append(found->second);
      if (echo_) (*echo_)(found->second);
      if (keep_) (*keep_)[found->first] = found->second;
      pending_.erase(found);
      ++next_;
    }
  }
  std::size_t written() const { return next_; }
  bool complete() const { return next_ == todo_.size(); }

 private:
  std::vector<std::size_t> todo_;
  map_file_writer* file_;
  const std::function<void(const std::string&)>* echo_;
  std::vector<std::string>* keep_;
  std::map<std::size_t, std::string> pending_;
  std::size_t next_ = 0;
};

}  // namespace rotlie::runs
